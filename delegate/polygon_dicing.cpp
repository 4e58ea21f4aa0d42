#include "delegate/polygon_dicing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

#include "delegate/displacement.h"

namespace fluence::delegate {

namespace {

// Where a grid vertex lies on its base triangle, as the corners it is interpolated from: one
// corner exactly; a point of an edge, `f` of the way from corner c[0] (the lower-numbered point)
// to c[1]; or inside, with barycentric weights w over the three corners.
struct GridPoint {
    int kind = 0;  // 1 corner, 2 edge, 3 inside
    int c[3] = {0, 1, 2};
    float w[3] = {1.0f, 0.0f, 0.0f};
};

// Interpolates `k` floats per corner (corner i at values + i * k) at p into out.
void interpolate(const GridPoint& p, const float* values, int k, float* out) {
    for (int i = 0; i < k; ++i) {
        const float a = values[p.c[0] * k + i], b = values[p.c[1] * k + i];
        if (p.kind == 1)
            out[i] = a;
        else if (p.kind == 2)
            out[i] = a + (b - a) * p.w[1];
        else
            out[i] = a * p.w[0] + b * p.w[1] + values[p.c[2] * k + i] * p.w[2];
    }
}

// Grid vertex (i, j) of a triangle cut into n: barycentric (n - i - j, i, j) / n over corners 0,
// 1, 2, with vertices on a side snapped to the side's edge's own points.
GridPoint gridPoint(int i, int j, int n, const std::uint32_t* points, const TriangleEdges& edges, std::size_t t,
                    const std::vector<int>& segments) {
    GridPoint p;
    if (i + j == 0 || i == n || j == n) {
        p.kind = 1;
        p.c[0] = i == n ? 1 : j == n ? 2 : 0;
        return p;
    }
    int side = -1, k = 0;  // along side s from corner s, k of n steps
    if (j == 0)
        side = 0, k = i;
    else if (i + j == n)
        side = 1, k = j;
    else if (i == 0)
        side = 2, k = n - j;
    if (side < 0) {
        p.kind = 3;
        p.w[0] = static_cast<float>(n - i - j) / static_cast<float>(n);
        p.w[1] = static_cast<float>(i) / static_cast<float>(n);
        p.w[2] = static_cast<float>(j) / static_cast<float>(n);
        return p;
    }
    int from = side, to = (side + 1) % 3;
    if (points[from] > points[to]) std::swap(from, to), k = n - k;
    const long long m = segments[edges.sideEdge(t, side)];
    const long long snapped = (2LL * k * m + n) / (2LL * n);  // the nearest of the edge's m + 1 points
    if (snapped == 0 || snapped == m) {
        p.kind = 1;
        p.c[0] = snapped == 0 ? from : to;
        return p;
    }
    p.kind = 2;
    p.c[0] = from;
    p.c[1] = to;
    p.w[1] = static_cast<float>(snapped) / static_cast<float>(m);
    return p;
}

int triangleSegments(const TriangleEdges& edges, std::size_t t, const std::vector<int>& segments) {
    return std::max({segments[edges.sideEdge(t, 0)], segments[edges.sideEdge(t, 1)], segments[edges.sideEdge(t, 2)]});
}

// Per point, the unit area-weighted normal of the triangles around it.
std::vector<Vec3f> pointNormals(const render::MeshDesc& mesh) {
    std::vector<Vec3f> normals(mesh.positions.size(), Vec3f(0.0f));
    for (std::size_t c = 0; c + 2 < mesh.indices.size(); c += 3) {
        const Vec3f &a = mesh.positions[mesh.indices[c]], &b = mesh.positions[mesh.indices[c + 1]],
                    &d = mesh.positions[mesh.indices[c + 2]];
        const Vec3f n = cross(b - a, d - a);
        for (int k = 0; k < 3; ++k) normals[mesh.indices[c + k]] = normals[mesh.indices[c + k]] + n;
    }
    for (Vec3f& n : normals) n = lengthSquared(n) > 0.0f ? normalize(n) : Vec3f(0.0f);
    return normals;
}

// The base triangle's per-corner data, gathered as flat floats for interpolate().
struct CornerData {
    float positions[9], normals[9], colors[9];
    std::vector<std::vector<float>> primvars;
};

}  // namespace

TriangleEdges::TriangleEdges(const render::MeshDesc& mesh) {
    std::map<std::pair<int, int>, std::size_t> index;
    sideEdges_.reserve(mesh.indices.size());
    for (std::size_t t = 0; 3 * t + 2 < mesh.indices.size(); ++t)
        for (int s = 0; s < 3; ++s) {
            int a = static_cast<int>(mesh.indices[3 * t + static_cast<std::size_t>(s)]);
            int b = static_cast<int>(mesh.indices[3 * t + static_cast<std::size_t>((s + 1) % 3)]);
            auto [it, inserted] = index.try_emplace(std::minmax(a, b), edges_.size());
            if (inserted) edges_.push_back(it->first);
            sideEdges_.push_back(it->second);
        }
}

std::size_t dicedTriangleCount(const TriangleEdges& edges, std::size_t triangles, const std::vector<int>& segments) {
    std::size_t count = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const auto n = static_cast<std::size_t>(triangleSegments(edges, t, segments));
        count += n * n;
    }
    return count;
}

DicedTriangles diceTriangles(const render::MeshDesc& mesh, const TriangleEdges& edges,
                             const std::vector<int>& segments) {
    DicedTriangles out;
    render::MeshDesc& diced = out.mesh;
    diced.name = mesh.name;
    diced.light = mesh.light;  // a mesh light displaced inside a prototype stays a light
    diced.material = mesh.material;
    for (const render::CornerPrimvar& pv : mesh.primvars) diced.primvars.push_back({pv.name, pv.components, {}});
    diced.motionPositions.resize(mesh.motionPositions.size());
    const std::vector<Vec3f> baseNormals = pointNormals(mesh);
    const bool colored = !mesh.cornerColors.empty();
    CornerData corner;
    corner.primvars.resize(mesh.primvars.size());
    std::vector<std::vector<float>> stepCorners(mesh.motionPositions.size(), std::vector<float>(9));
    std::vector<std::uint32_t> grid;
    for (std::size_t t = 0; 3 * t + 2 < mesh.indices.size(); ++t) {
        const std::uint32_t* points = &mesh.indices[3 * t];
        for (int k = 0; k < 3; ++k) {
            const Vec3f &p = mesh.positions[points[k]], &n = baseNormals[points[k]];
            std::copy_n(&p.x, 3, corner.positions + 3 * k);
            std::copy_n(&n.x, 3, corner.normals + 3 * k);
            if (colored)
                std::copy_n(&mesh.cornerColors[3 * t + static_cast<std::size_t>(k)].x, 3, corner.colors + 3 * k);
            for (std::size_t s = 0; s < mesh.motionPositions.size(); ++s)
                std::copy_n(&mesh.motionPositions[s][points[k]].x, 3, stepCorners[s].data() + 3 * k);
        }
        for (std::size_t i = 0; i < mesh.primvars.size(); ++i) {
            const std::size_t k = static_cast<std::size_t>(mesh.primvars[i].components);
            const float* first = mesh.primvars[i].values.data() + 3 * t * k;
            corner.primvars[i].assign(first, first + 3 * k);
        }
        const int n = triangleSegments(edges, t, segments);
        // Grid vertices row by row (j), i from 0 to n - j.
        grid.clear();
        std::vector<std::size_t> rowStart;
        for (int j = 0; j <= n; ++j) {
            rowStart.push_back(grid.size());
            for (int i = 0; i + j <= n; ++i) {
                const GridPoint p = gridPoint(i, j, n, points, edges, t, segments);
                grid.push_back(static_cast<std::uint32_t>(diced.positions.size()));
                Vec3f position, normal;
                interpolate(p, corner.positions, 3, &position.x);
                interpolate(p, corner.normals, 3, &normal.x);
                diced.positions.push_back(position);
                out.normals.push_back(lengthSquared(normal) > 0.0f ? normalize(normal) : normal);
                for (std::size_t s = 0; s < stepCorners.size(); ++s) {
                    Vec3f q;
                    interpolate(p, stepCorners[s].data(), 3, &q.x);
                    diced.motionPositions[s].push_back(q);
                }
            }
        }
        // Corner data per grid vertex, emitted per output corner.
        auto emitCorner = [&](int i, int j) {
            const std::uint32_t v = grid[rowStart[static_cast<std::size_t>(j)] + static_cast<std::size_t>(i)];
            diced.indices.push_back(v);
            const GridPoint p = gridPoint(i, j, n, points, edges, t, segments);
            if (colored) {
                RGB c;
                interpolate(p, corner.colors, 3, &c.x);
                diced.cornerColors.push_back(c);
            }
            for (std::size_t k = 0; k < mesh.primvars.size(); ++k) {
                std::vector<float>& values = diced.primvars[k].values;
                values.resize(values.size() + static_cast<std::size_t>(mesh.primvars[k].components));
                interpolate(p, corner.primvars[k].data(), mesh.primvars[k].components,
                            values.data() + values.size() - static_cast<std::size_t>(mesh.primvars[k].components));
            }
        };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i + j < n; ++i) {
                emitCorner(i, j), emitCorner(i + 1, j), emitCorner(i, j + 1);
                if (i + j + 1 < n) emitCorner(i + 1, j), emitCorner(i + 1, j + 1), emitCorner(i, j + 1);
            }
    }
    return out;
}

std::optional<render::MeshDesc> displacedPart(const render::MeshDesc& objectSpace, const std::string& materialPath,
                                              const std::vector<Matrix4>& placements, const DicingContext& context) {
    const MaterialDisplacement* displacement = materialPath.empty() ? nullptr : context.displacement(materialPath);
    if (!displacement || objectSpace.indices.empty()) return std::nullopt;
    const DicingSettings& settings = context.settings;
    const TriangleEdges edges(objectSpace);
    const std::size_t triangles = objectSpace.indices.size() / 3;
    auto segmentsAt = [&](float scale) {
        if (settings.uniformLevel >= 0)
            return std::vector<int>(edges.edges().size(),
                                    std::min(1 << std::min(settings.uniformLevel, 30), settings.maxSegments));
        return placedEdgeSegments(context.camera, settings, settings.rate, objectSpace.positions, edges.edges(),
                                  placements, scale);
    };
    float scale = context.scale;
    std::vector<int> segments = segmentsAt(scale);
    const std::size_t wanted = dicedTriangleCount(edges, triangles, segments);
    std::size_t count = wanted;
    for (int attempt = 0; count > settings.meshTriangleBudget && attempt < 8; ++attempt) {
        if (settings.uniformLevel >= 0)
            for (int& s : segments) s = std::max(1, s / 2);
        else
            segments = segmentsAt(
                scale *= 0.9f * std::sqrt(static_cast<float>(settings.meshTriangleBudget) / static_cast<float>(count)));
        count = dicedTriangleCount(edges, triangles, segments);
    }
    if (count < wanted)
        context.warn(objectSpace.name, "displacement dicing of " + std::to_string(wanted) +
                                           " triangles exceeds the per-mesh budget of " +
                                           std::to_string(settings.meshTriangleBudget) + "; diced coarser, to " +
                                           std::to_string(count) + " triangles");
    DicedTriangles diced = diceTriangles(objectSpace, edges, segments);
    std::vector<float> amounts(diced.mesh.positions.size(), 0.0f);
    displacement->atVertices(
        diced.mesh, [](std::size_t) { return true; }, amounts);
    const std::vector<Vec3f> before = diced.mesh.positions;
    displaceAlongNormals(diced.mesh, diced.normals, amounts);
    for (std::vector<Vec3f>& step : diced.mesh.motionPositions)  // each step moved as the frame's points are
        for (std::size_t v = 0; v < step.size(); ++v) step[v] = step[v] + (diced.mesh.positions[v] - before[v]);
    return std::move(diced.mesh);
}

}  // namespace fluence::delegate
