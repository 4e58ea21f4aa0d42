// SubdivisionSurface output is watertight (closed cages with different segment counts on different
// edges give closed, consistently oriented triangle meshes that no ray escapes through), and the
// tessellation converges to the limit surface (the area of a Catmull-Clark cube, second order in
// the segment length).
#include "delegate/subdivision.h"
#include "tests/delegate/subdivision_test_cage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "core/random.h"
#include "render/render_scene.h"

namespace fluence::delegate {
namespace {

using Scheme = SubdivisionTopology::Scheme;

struct Cage {
    std::string name;
    SubdivisionTopology topology;
    std::vector<Vec3f> points;
};

Cage cube() {
    Cage c;
    c.name = "cube";
    c.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    c.topology = testing::cubeTopology();
    return c;
}

// The cube with a semi-sharp crease, an infinitely sharp crease and a sharp corner.
Cage creasedCube() {
    Cage c = cube();
    c.name = "creased cube";
    c.topology.creaseIndices = {0, 1, 2, 4, 5};
    c.topology.creaseLengths = {3, 2};
    c.topology.creaseSharpnesses = {1.5f, 10.0f};
    c.topology.cornerIndices = {7};
    c.topology.cornerSharpnesses = {10.0f};
    return c;
}

// A pentagonal prism, one side split into two triangles, one cap raised to a point: pentagons,
// triangles, quads; valence 3, 4 and 5 points.
Cage mixedPrism() {
    Cage c;
    c.name = "mixed prism";
    for (int ring = 0; ring < 2; ++ring)
        for (int i = 0; i < 5; ++i) {
            double a = 2.0 * 3.14159265358979 * i / 5.0;
            c.points.emplace_back(float((1.0 + 0.1 * i) * std::cos(a)), float(std::sin(a)), ring == 0 ? -1.0f : 1.0f);
        }
    c.points.emplace_back(0.0f, 0.0f, 1.6f);  // apex of the top cap's fan
    c.topology.pointCount = 11;
    c.topology.faceVertexCounts = {5};
    c.topology.faceVertexIndices = {4, 3, 2, 1, 0};
    for (int i = 0; i < 5; ++i) {
        int j = (i + 1) % 5;
        c.topology.faceVertexCounts.push_back(3);  // top fan
        c.topology.faceVertexIndices.insert(c.topology.faceVertexIndices.end(), {i + 5, j + 5, 10});
        if (i == 2) {
            c.topology.faceVertexCounts.insert(c.topology.faceVertexCounts.end(), {3, 3});
            c.topology.faceVertexIndices.insert(c.topology.faceVertexIndices.end(), {i, j, j + 5, i, j + 5, i + 5});
        } else {
            c.topology.faceVertexCounts.push_back(4);
            c.topology.faceVertexIndices.insert(c.topology.faceVertexIndices.end(), {i, j, j + 5, i + 5});
        }
    }
    return c;
}

// A perturbed icosahedron: every point of valence 5.
Cage icosahedron(Scheme scheme) {
    Cage c;
    c.name = scheme == Scheme::Loop ? "loop icosahedron" : "catmull-clark icosahedron";
    const float g = 1.618034f;
    c.points = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (std::size_t i = 0; i < c.points.size(); ++i) c.points[i] *= 1.0f + 0.04f * float(i % 3);
    c.topology.scheme = scheme;
    c.topology.pointCount = 12;
    c.topology.faceVertexIndices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                    4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                    6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    c.topology.faceVertexCounts.assign(20, 3);
    return c;
}

std::vector<Cage> cages() {
    return {cube(), creasedCube(), mixedPrism(), icosahedron(Scheme::Loop), icosahedron(Scheme::CatmullClark)};
}

// Segment counts from 1 to 7 that differ between neighbouring edges.
std::vector<int> variedRates(std::size_t edges) {
    std::vector<int> rates(edges);
    for (std::size_t e = 0; e < edges; ++e) rates[e] = 1 + int((e * 5 + 3) % 7);
    return rates;
}

Vec3f centroid(const std::vector<Vec3f>& points) {
    Vec3d sum(0.0);
    for (const Vec3f& p : points) sum += Vec3d(p);
    return Vec3f(sum / double(points.size()));
}

// Output vertices on base points and base edges come first (the documented layout): how many.
std::size_t sharedVertexCount(const SubdivisionSurface& surface, const std::vector<int>& rates) {
    std::size_t n = std::size_t(surface.topology().pointCount);  // every point of these cages is used
    for (int r : rates) n += std::size_t(r - 1);
    return n;
}

// A point to aim at, the unit normals of the triangles it lies on (two along an edge, all of them
// around a vertex) and a tangent direction across the seam.
struct Target {
    Vec3f point, across;
    std::vector<Vec3f> sides;
};

Vec3f triangleNormal(const SubdivisionSurface::Result& r, std::size_t t) {
    const Vec3f a = r.positions[r.indices[3 * t]], b = r.positions[r.indices[3 * t + 1]],
                c = r.positions[r.indices[3 * t + 2]];
    return normalize(cross(b - a, c - a));
}

// Points on the seams: every 4th a shared vertex (a base point or a base-edge point), the others
// uniformly random along the triangle edges that join two shared vertices.
std::vector<Target> seamTargets(const SubdivisionSurface::Result& result, std::size_t shared, int count,
                                std::uint64_t seed) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> seamEdges;  // (a < b) -> its triangles
    std::vector<std::vector<std::size_t>> vertexTriangles(shared);
    for (std::size_t t = 0; t < result.indices.size() / 3; ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = result.indices[3 * t + k], b = result.indices[3 * t + (k + 1) % 3];
            if (a < shared) vertexTriangles[a].push_back(t);
            if (a < shared && b < shared) seamEdges[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& entry : seamEdges) edges.push_back(entry.first);
    std::vector<Target> targets;
    for (int i = 0; i < count; ++i) {
        SampleStream random(seed, 0, std::uint64_t(i));
        Target target;
        if (i % 4 == 0) {
            std::uint32_t v = std::uint32_t(random.next() * float(shared)) % std::uint32_t(shared);
            target.point = result.positions[v];
            for (std::size_t t : vertexTriangles[v]) target.sides.push_back(triangleNormal(result, t));
            const Vec3f n = result.normals[v];
            const Vec3f any = std::abs(n.x) < 0.5f ? Vec3f(1, 0, 0) : Vec3f(0, 1, 0);
            const Vec3f t1 = normalize(cross(n, any)), t2 = cross(n, t1);
            const float phi = 6.2831853f * random.next();
            target.across = t1 * std::cos(phi) + t2 * std::sin(phi);
        } else {
            const auto [a, b] = edges[std::size_t(random.next() * float(edges.size())) % edges.size()];
            const Vec3f pa = result.positions[a], pb = result.positions[b];
            const float s = random.next();
            target.point = pa * (1.0f - s) + pb * s;
            for (std::size_t t : seamEdges[{a, b}]) target.sides.push_back(triangleNormal(result, t));
            target.across = normalize(cross(normalize(result.normals[a] + result.normals[b]), pb - pa));
            if (random.next() < 0.5f) target.across = -target.across;
        }
        targets.push_back(std::move(target));
    }
    return targets;
}

// Rays at each target, alternately from inside (within `insideRadius` of `inside`) and from
// outside, `outsideDistance` away in a direction tilted across the seam (so that rays do not all
// lie in the seam's plane, and a crack shows whatever its orientation) but within 75 degrees of
// the normal of every triangle at the target: a ray grazing the surface at a silhouette may miss it
// without any crack. `hits` says whether a ray hits the mesh. Returns the number of misses.
template <typename Hits>
int misses(const std::vector<Target>& targets, Vec3f inside, float insideRadius, float outsideDistance, Hits&& hits) {
    int missed = 0;
    for (std::size_t i = 0; i < targets.size(); ++i) {
        SampleStream random(0x0419, 1, i);
        const Target& t = targets[i];
        Vec3f origin;
        if (i % 2 == 0) {
            origin = inside + Vec3f(random.next() - 0.5f, random.next() - 0.5f, random.next() - 0.5f) *
                                  (insideRadius / 0.8660254f);
        } else {
            Vec3f normal(0.0f);
            for (const Vec3f& n : t.sides) normal += n;
            normal = normalize(normal);
            Vec3f away = normal;
            for (int attempt = 0; attempt < 16; ++attempt) {
                Vec3f w = normalize(normal + t.across * (2.0f * random.next() - 1.0f));
                if (std::all_of(t.sides.begin(), t.sides.end(), [&](const Vec3f& n) { return dot(w, n) > 0.25f; })) {
                    away = w;
                    break;
                }
            }
            origin = t.point + away * outsideDistance;
        }
        if (!hits(render::Ray{origin, normalize(t.point - origin)})) ++missed;
    }
    return missed;
}

// The render scene of one mesh: Embree in robust mode, whose triangle test is watertight along
// shared edges and vertices, so a crack it falls through is a crack in the mesh.
struct MeshScene {
    explicit MeshScene(const std::string& name, const std::vector<Vec3f>& positions,
                       const std::vector<std::uint32_t>& indices)
        : scene(describe(name, positions, indices)) {}
    static render::SceneDescription describe(const std::string& name, const std::vector<Vec3f>& positions,
                                             const std::vector<std::uint32_t>& indices) {
        render::SceneDescription desc;
        desc.meshes.push_back({name, positions, indices, {}, {}, -1, {}});
        return desc;
    }
    bool hits(const render::Ray& ray) const { return scene.intersect(ray).has_value(); }
    render::RenderScene scene;
};

TEST(SubdivisionWatertight, ClosedCagesGiveClosedConsistentlyOrientedMeshes) {
    for (const Cage& c : cages()) {
        SCOPED_TRACE(c.name);
        SubdivisionSurface surface(c.topology);
        auto result = surface.tessellate(c.points, variedRates(surface.edges().size()));
        // Every directed triangle edge once, and its reverse once: a closed 2-manifold whose
        // triangles all face the same way. A vertex evaluated twice instead of shared would leave
        // an edge without its twin.
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
        for (std::size_t t = 0; t < result.indices.size(); t += 3)
            for (int k = 0; k < 3; ++k) {
                std::uint32_t a = result.indices[t + k], b = result.indices[t + (k + 1) % 3];
                ASSERT_NE(a, b) << "degenerate triangle " << t / 3;
                ++directed[{a, b}];
            }
        for (const auto& [edge, count] : directed) {
            EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
            auto twin = directed.find({edge.second, edge.first});
            EXPECT_TRUE(twin != directed.end() && twin->second == 1)
                << "edge " << edge.first << "-" << edge.second << " has no twin";
        }
        // Euler characteristic of a sphere (so every vertex is used, too).
        const long long V = (long long)result.positions.size(), E = (long long)directed.size() / 2,
                        F = (long long)result.triangleFaces.size();
        EXPECT_EQ(V - E + F, 2);
    }
}

constexpr int kRays = 4000;       // per cage: half from inside, half from outside
constexpr float kOutside = 6.0f;  // distance of outside origins (the cages fit a radius 2 ball)
constexpr float kInside = 0.25f;  // inside origins: within this of the centroid (inside every limit surface here)

TEST(SubdivisionWatertight, RaysAtTheSeamsAlwaysHitTheRenderScene) {
    for (const Cage& c : cages()) {
        SCOPED_TRACE(c.name);
        SubdivisionSurface surface(c.topology);
        const auto rates = variedRates(surface.edges().size());
        auto result = surface.tessellate(c.points, rates);
        MeshScene scene(c.name, result.positions, result.indices);
        auto targets = seamTargets(result, sharedVertexCount(surface, rates), kRays, 0x5eed);
        EXPECT_EQ(
            misses(targets, centroid(c.points), kInside, kOutside, [&](const render::Ray& r) { return scene.hits(r); }),
            0)
            << "of " << kRays << " rays";
    }
}

// The test above can fail: tessellating each face alone with its own rate (each face's vertices
// separate, and neighbouring faces sampling their common edge differently) leaves cracks along the
// seams, and the same rays find them.
TEST(SubdivisionWatertight, RaysFindTheCracksOfFacesTessellatedApart) {
    Cage c = cube();
    SubdivisionSurface surface(c.topology);
    const auto rates = variedRates(surface.edges().size());
    auto welded = surface.tessellate(c.points, rates);
    std::vector<Vec3f> positions;
    std::vector<std::uint32_t> indices;
    for (int f = 0; f < surface.faceCount(); ++f) {
        auto alone = surface.tessellate(c.points, std::vector<int>(rates.size(), 2 + f));
        const std::uint32_t base = std::uint32_t(positions.size());
        positions.insert(positions.end(), alone.positions.begin(), alone.positions.end());
        for (std::size_t t = 0; t < alone.triangleFaces.size(); ++t)
            if (alone.triangleFaces[t] == std::uint32_t(f))
                for (int k = 0; k < 3; ++k) indices.push_back(base + alone.indices[3 * t + k]);
    }
    // Aimed at the welded mesh's seams, where the cracked one has its gaps.
    MeshScene cracked("cracked", positions, indices);
    EXPECT_GT(misses(seamTargets(welded, sharedVertexCount(surface, rates), kRays, 0x5eed), centroid(c.points), kInside,
                     kOutside, [&](const render::Ray& r) { return cracked.hits(r); }),
              40);
}

double area(const SubdivisionSurface::Result& r) {
    double sum = 0.0;
    for (std::size_t t = 0; t < r.indices.size(); t += 3) {
        Vec3d a(r.positions[r.indices[t]]), b(r.positions[r.indices[t + 1]]), c(r.positions[r.indices[t + 2]]);
        sum += 0.5 * length(cross(b - a, c - a));
    }
    return sum;
}

TEST(SubdivisionConvergence, CatmullClarkCubeAreaConvergesQuadratically) {
    // A unit cube. The tessellation's vertices lie on the limit surface, so its area converges
    // to the limit surface's with the square of the segment length: doubling the rate divides the
    // error by 4 (3.5 to 4.5 allowed: the reference at rate 256 still carries 1/64 of the error at
    // rate 32, and the rates are not yet asymptotic).
    Cage c = cube();
    for (Vec3f& p : c.points) p *= 0.5f;
    SubdivisionSurface surface(c.topology);
    auto areaAt = [&](int rate) {
        return area(surface.tessellate(c.points, std::vector<int>(surface.edges().size(), rate)));
    };
    auto fine = surface.tessellate(c.points, std::vector<int>(surface.edges().size(), 256));
    const double reference = area(fine);
    // The limit surface is convex: its area lies between those of the spheres through its nearest
    // and farthest points from the centre.
    double nearest = 1.0, farthest = 0.0;
    for (const Vec3f& p : fine.positions)
        nearest = std::min(nearest, double(length(p))), farthest = std::max(farthest, double(length(p)));
    EXPECT_GT(reference, 4.0 * 3.14159265358979 * nearest * nearest);
    EXPECT_LT(reference, 4.0 * 3.14159265358979 * farthest * farthest);
    double previousError = std::abs(areaAt(4) - reference);
    for (int rate : {8, 16, 32}) {
        const double error = std::abs(areaAt(rate) - reference);
        EXPECT_GT(previousError / error, 3.5) << "rate " << rate << ": error " << error << " after " << previousError;
        EXPECT_LT(previousError / error, 4.5) << "rate " << rate << ": error " << error << " after " << previousError;
        previousError = error;
    }
    // Non-uniform rates between 32 and 64 land between the two uniform ones.
    std::vector<int> mixed(surface.edges().size());
    for (std::size_t e = 0; e < mixed.size(); ++e) mixed[e] = e % 2 ? 32 : 64;
    const double mixedArea = area(surface.tessellate(c.points, mixed));
    EXPECT_LT(std::abs(mixedArea - reference), std::abs(areaAt(32) - reference));
    EXPECT_GT(std::abs(mixedArea - reference), std::abs(areaAt(64) - reference));
}

}  // namespace
}  // namespace fluence::delegate
