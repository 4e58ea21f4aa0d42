#include "render/solid_orientation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace fluence::render {

namespace {

// Positions closer than this, relative to the mesh's extent, are one corner: points a
// tessellator computed twice (a seam, a pole) differ in their last bits.
constexpr double kWeldTolerance = 1e-6;

struct CellHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
        std::uint64_t h = std::uint64_t(c[0]);
        h = h * 0x9E3779B97F4A7C15ull ^ std::uint64_t(c[1]);
        h = h * 0x9E3779B97F4A7C15ull ^ std::uint64_t(c[2]);
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

// For each position, the index of the first position in its cell of the weld grid.
std::vector<std::uint32_t> weldedIndices(const std::vector<Vec3f>& positions) {
    Vec3f lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Vec3f& p : positions) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    const double extent = positions.empty() ? 0.0 : double(maxComponent(hi - lo));
    const double cell = extent > 0.0 ? kWeldTolerance * extent : 1.0;
    std::unordered_map<std::array<std::int64_t, 3>, std::uint32_t, CellHash> first;
    first.reserve(positions.size());
    std::vector<std::uint32_t> welded(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Vec3d p = Vec3d(positions[i] - lo) / cell;
        const std::array<std::int64_t, 3> key{std::llround(p.x), std::llround(p.y), std::llround(p.z)};
        welded[i] = first.try_emplace(key, static_cast<std::uint32_t>(i)).first->second;
    }
    return welded;
}

template <typename T>
void swapSecondAndThirdCorners(std::vector<T>& perCorner, std::size_t valuesPerCorner) {
    const std::size_t triangle = 3 * valuesPerCorner;
    for (std::size_t t = 0; t + triangle <= perCorner.size(); t += triangle)
        std::swap_ranges(perCorner.begin() + std::ptrdiff_t(t + valuesPerCorner),
                         perCorner.begin() + std::ptrdiff_t(t + 2 * valuesPerCorner),
                         perCorner.begin() + std::ptrdiff_t(t + 2 * valuesPerCorner));
}

// Whether the corner normals, weighted by their triangles' areas, point against the winding.
bool normalsPointInward(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& indices,
                        const std::vector<Vec3f>& normals) {
    double agreement = 0.0;
    for (std::size_t c = 0; c + 2 < indices.size() && c + 2 < normals.size(); c += 3) {
        const Vec3f& p0 = positions[indices[c]];
        const Vec3f area = cross(positions[indices[c + 1]] - p0, positions[indices[c + 2]] - p0);
        agreement += dot(area, normals[c] + normals[c + 1] + normals[c + 2]);
    }
    return agreement < 0.0;
}

}  // namespace

bool isClosed(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& indices) {
    if (indices.empty()) return false;
    const std::vector<std::uint32_t> welded = weldedIndices(positions);
    std::unordered_map<std::uint64_t, int> edgeUses;
    edgeUses.reserve(indices.size());
    for (std::size_t c = 0; c + 2 < indices.size(); c += 3) {
        const std::uint32_t corner[3] = {welded[indices[c]], welded[indices[c + 1]], welded[indices[c + 2]]};
        // A triangle with two corners at one point (a quad's half at a UV sphere's pole) bounds
        // nothing: its edges are not counted.
        if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = corner[k], b = corner[(k + 1) % 3];
            edgeUses[(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)] += 1;
        }
    }
    if (edgeUses.empty()) return false;
    return std::all_of(edgeUses.begin(), edgeUses.end(), [](const auto& e) { return e.second == 2; });
}

double signedVolume(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& indices) {
    if (indices.empty()) return 0.0;
    const Vec3d origin(positions[indices[0]]);  // near the mesh, for precision
    double sixTimes = 0.0;
    for (std::size_t c = 0; c + 2 < indices.size(); c += 3) {
        const Vec3d p0 = Vec3d(positions[indices[c]]) - origin, p1 = Vec3d(positions[indices[c + 1]]) - origin,
                    p2 = Vec3d(positions[indices[c + 2]]) - origin;
        sixTimes += dot(p0, cross(p1, p2));
    }
    return sixTimes / 6.0;
}

bool fillsItsInside(const MaterialDesc& material) {
    if (material.thinWalled) return false;
    const bool boundTransmission =
        std::any_of(material.bindings.begin(), material.bindings.end(),
                    [](const InputBinding& b) { return b.input == MaterialInput::Transmission; });
    return material.transmission > 0.0f || boundTransmission || material.subsurface > 0.0f ||
           material.interior.has_value();
}

bool orientClosedMeshOutward(const std::vector<Vec3f>& positions, TriangleCorners corners) {
    if (!isClosed(positions, corners.indices)) return false;
    if (signedVolume(positions, corners.indices) < 0.0) {
        swapSecondAndThirdCorners(corners.indices, 1);
        swapSecondAndThirdCorners(corners.normals, 1);
        swapSecondAndThirdCorners(corners.colors, 1);
        for (CornerPrimvar& p : corners.primvars)
            swapSecondAndThirdCorners(p.values, static_cast<std::size_t>(p.components));
    }
    if (normalsPointInward(positions, corners.indices, corners.normals))
        for (Vec3f& n : corners.normals) n = -n;
    return true;
}

}  // namespace fluence::render
