#include "integrators/radiosity_mesh.h"

#include <algorithm>
#include <cmath>

namespace fluence::integrators {

namespace {

// How far from a patch's plane (a fraction of the cell size) and outside its edges (in barycentric
// units) a point may be and still be located on it: float rounding in hit points, nothing more.
constexpr float kPlaneTolerance = 1e-3f;
constexpr float kEdgeTolerance = 1e-2f;
// A patch is a candidate for a point only if its normal is this close to the surface's (|cos|).
constexpr float kMinNormalAgreement = 0.9f;

// Bits per axis of a grid cell's key: cells from -2^20 to 2^20 per axis have distinct keys; beyond,
// keys alias, which only adds candidates (every candidate's geometry is checked).
constexpr int kKeyBits = 21;
constexpr std::int64_t kKeyOffset = std::int64_t(1) << (kKeyBits - 1);
std::int64_t cellKey(std::int64_t x, std::int64_t y, std::int64_t z) {
    return ((x + kKeyOffset) << (2 * kKeyBits)) | ((y + kKeyOffset) << kKeyBits) | (z + kKeyOffset);
}

}  // namespace

float defaultPatchEdge(const render::SceneBounds& bounds) { return 2.0f * bounds.radius / kDefaultPatchesPerDiameter; }

std::vector<Patch> meshPatches(const std::vector<render::RenderScene::SurfaceTriangle>& triangles, float maxEdge) {
    std::vector<Patch> patches;
    for (const render::RenderScene::SurfaceTriangle& t : triangles) {
        const Vec3f e1 = t.p1 - t.p0, e2 = t.p2 - t.p0;
        const Vec3f n = cross(e1, e2);
        if (lengthSquared(n) <= 0.0f) continue;
        const float longest = std::max({length(e1), length(e2), length(t.p2 - t.p1)});
        const int cuts = std::max(1, static_cast<int>(std::ceil(longest / maxEdge)));
        const Vec3f du = e1 / float(cuts), dv = e2 / float(cuts);
        auto at = [&](int i, int j) { return t.p0 + du * float(i) + dv * float(j); };
        const Vec3f normal = normalize(n);
        const float area = 0.5f * length(n) / float(cuts * cuts);
        // Row j holds cuts - j upright triangles and cuts - j - 1 inverted ones.
        for (int j = 0; j < cuts; ++j)
            for (int i = 0; i + j < cuts; ++i) {
                patches.push_back({at(i, j), at(i + 1, j), at(i, j + 1), normal, area, t.albedo, t.emission});
                if (i + j + 1 < cuts)
                    patches.push_back(
                        {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), normal, area, t.albedo, t.emission});
            }
    }
    return patches;
}

float gridCellSize(const std::vector<Patch>& patches) {
    if (patches.empty()) return 1.0f;
    double sum = 0.0;
    float longest = 0.0f;
    for (const Patch& p : patches) {
        const float edge = std::max({length(p.p1 - p.p0), length(p.p2 - p.p0), length(p.p2 - p.p1)});
        sum += edge;
        longest = std::max(longest, edge);
    }
    return std::max(float(sum / double(patches.size())), longest / kMaxCellsPerPatch);
}

std::vector<RGB> cornerAverages(const std::vector<Patch>& patches, const std::vector<RGB>& values) {
    // Corners are welded when within kWeldTolerance x gridCellSize of each other (the same
    // point computed along two triangles' edges differs by rounding); a welded point is looked up
    // in the 27 cells of that size around it.
    constexpr float kWeldTolerance = 1e-3f;
    const float weld = kWeldTolerance * gridCellSize(patches);
    struct Group {
        Vec3f point, normal;
        RGB sum{0.0f};
        float area = 0.0f;
    };
    std::vector<Group> groups;
    std::unordered_map<std::int64_t, std::vector<int>> cells;
    const auto cell = [&](float x) { return static_cast<std::int64_t>(std::floor(x / weld)); };
    auto groupOf = [&](const Vec3f& point, const Vec3f& normal) {
        const std::int64_t x = cell(point.x), y = cell(point.y), z = cell(point.z);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    auto found = cells.find(cellKey(x + dx, y + dy, z + dz));
                    if (found == cells.end()) continue;
                    for (int g : found->second)
                        if (lengthSquared(groups[g].point - point) <= weld * weld &&
                            dot(groups[g].normal, normal) >= kSmoothingCosine)
                            return g;
                }
        groups.push_back({point, normal});
        cells[cellKey(x, y, z)].push_back(static_cast<int>(groups.size()) - 1);
        return static_cast<int>(groups.size()) - 1;
    };
    std::vector<int> cornerGroup(3 * values.size());
    for (std::size_t e = 0; e < values.size(); ++e) {
        const Patch& patch = patches[e / kSides];
        const Vec3f normal = sideNormal(patch, static_cast<int>(e % kSides));
        const Vec3f corners[3] = {patch.p0, patch.p1, patch.p2};
        for (int c = 0; c < 3; ++c) {
            const int g = groupOf(corners[c], normal);
            groups[g].sum += values[e] * patch.area;
            groups[g].area += patch.area;
            cornerGroup[3 * e + c] = g;
        }
    }
    std::vector<RGB> out(cornerGroup.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = groups[cornerGroup[i]].sum / groups[cornerGroup[i]].area;
    return out;
}

PatchLocator::PatchLocator(const std::vector<Patch>& patches) : cellSize_(gridCellSize(patches)) {
    const float pad = kPlaneTolerance * cellSize_;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const Patch& p = patches[i];
        const Vec3f lo = vmin(p.p0, vmin(p.p1, p.p2)) - Vec3f(pad), hi = vmax(p.p0, vmax(p.p1, p.p2)) + Vec3f(pad);
        for (std::int64_t x = cellOf(lo.x); x <= cellOf(hi.x); ++x)
            for (std::int64_t y = cellOf(lo.y); y <= cellOf(hi.y); ++y)
                for (std::int64_t z = cellOf(lo.z); z <= cellOf(hi.z); ++z)
                    cells_[cellKey(x, y, z)].push_back(static_cast<int>(i));
    }
}

std::int64_t PatchLocator::cellOf(float coordinate) const {
    return static_cast<std::int64_t>(std::floor(coordinate / cellSize_));
}

std::optional<PatchPoint> PatchLocator::locate(const std::vector<Patch>& patches, const Vec3f& p,
                                               const Vec3f& n) const {
    auto found = cells_.find(cellKey(cellOf(p.x), cellOf(p.y), cellOf(p.z)));
    if (found == cells_.end()) return std::nullopt;
    std::optional<PatchPoint> best;
    float bestOutside = kEdgeTolerance;
    for (int index : found->second) {
        const Patch& patch = patches[index];
        if (std::abs(dot(patch.normal, n)) < kMinNormalAgreement) continue;
        if (std::abs(dot(p - patch.p0, patch.normal)) > kPlaneTolerance * cellSize_) continue;
        // Barycentrics of p's projection onto the patch.
        const Vec3f v0 = patch.p1 - patch.p0, v1 = patch.p2 - patch.p0, v2 = p - patch.p0;
        const float d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1), d20 = dot(v2, v0), d21 = dot(v2, v1);
        const float denominator = d00 * d11 - d01 * d01;
        const float b1 = (d11 * d20 - d01 * d21) / denominator, b2 = (d00 * d21 - d01 * d20) / denominator;
        const float outside = std::max(0.0f, -std::min({1.0f - b1 - b2, b1, b2}));
        if (outside <= bestOutside) {
            bestOutside = outside;
            best = PatchPoint{index, b1, b2};
        }
    }
    return best;
}

}  // namespace fluence::integrators
