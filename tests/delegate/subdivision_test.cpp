// SubdivisionSurface: USD token mapping and input checks, closed forms of the limit surface
// (bicubic B-spline on a regular patch, bilinear scheme, linear face-varying), creases, corners,
// holes, face-varying seams and continuity, vertex and varying primvars, orientation, and the
// uniform triangle counts.
//
// Tolerances: the tessellator evaluates in double and rounds each value to float once, so a value
// of magnitude up to M is within 2^-24 M of the exact double result; the checks allow 2^-23 M
// (twice that, for the double arithmetic of the reference) unless stated. Segment counts are
// powers of two so the (u, v) of every tessellation point is exact in float.
#include "delegate/subdivision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "delegate/subdivision_topology.h"
#include "render/render_scene.h"

namespace fluence::delegate {
namespace {

using Scheme = SubdivisionTopology::Scheme;

// An nx x ny grid of points (spacing 1, z = height(x, y)) and its (nx-1) x (ny-1) quads, wound
// counter-clockwise seen from +z. Point (x, y) is y * nx + x; face (x, y) is y * (nx - 1) + x.
struct Grid {
    SubdivisionTopology topology;
    std::vector<Vec3f> points;
    int nx = 0, ny = 0;
    int point(int x, int y) const { return y * nx + x; }
    int face(int x, int y) const { return y * (nx - 1) + x; }
};

Grid grid(int nx, int ny, const std::function<float(int, int)>& height) {
    Grid g;
    g.nx = nx;
    g.ny = ny;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) g.points.emplace_back(float(x), float(y), height(x, y));
    g.topology.pointCount = nx * ny;
    for (int y = 0; y + 1 < ny; ++y)
        for (int x = 0; x + 1 < nx; ++x) {
            g.topology.faceVertexCounts.push_back(4);
            g.topology.faceVertexIndices.insert(
                g.topology.faceVertexIndices.end(),
                {g.point(x, y), g.point(x + 1, y), g.point(x + 1, y + 1), g.point(x, y + 1)});
        }
    return g;
}

float bumps(int x, int y) {
    return 0.4f * std::sin(1.7f * float(x) + 0.3f) * std::cos(1.1f * float(y) - 0.2f) + 0.05f * float(x * y);
}

// An axis-aligned cube of side 2 centred at the origin, faces wound counter-clockwise seen from
// outside.
struct Cage {
    SubdivisionTopology topology;
    std::vector<Vec3f> points;
};

Cage cube() {
    Cage c;
    c.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    c.topology.pointCount = 8;
    c.topology.faceVertexCounts = {4, 4, 4, 4, 4, 4};
    c.topology.faceVertexIndices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    return c;
}

double maxAbs(const Vec3d& v) { return maxComponent(vmax(v, -v)); }

// The uniform cubic B-spline basis functions and their derivatives at t.
std::array<double, 4> bspline(double t) {
    double s = 1.0 - t;
    return {s * s * s / 6.0, (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
            (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0, t * t * t / 6.0};
}
std::array<double, 4> bsplineDerivative(double t) {
    double s = 1.0 - t;
    return {-s * s / 2.0, (9.0 * t * t - 12.0 * t) / 6.0, (-9.0 * t * t + 6.0 * t + 3.0) / 6.0, t * t / 2.0};
}

template <typename F>
std::string messageOf(F&& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(no std::invalid_argument thrown)";
}

// ---------------------------------------------------------------------------------------------
// Tokens and input checks

TEST(Subdivision, UsdTokensMapToOpenSubdivOptions) {
    using OpenSubdiv::Sdc::Options;
    auto options = [](const std::string& boundary, const std::string& fvar, const std::string& triangles) {
        SubdivisionTopology t;
        t.interpolateBoundary = boundary;
        t.faceVaryingLinearInterpolation = fvar;
        t.triangleSubdivisionRule = triangles;
        return subdivision_detail::sdcOptions(t);
    };
    const std::map<std::string, Options::VtxBoundaryInterpolation> boundaries = {
        {"none", Options::VTX_BOUNDARY_NONE},
        {"edgeOnly", Options::VTX_BOUNDARY_EDGE_ONLY},
        {"edgeAndCorner", Options::VTX_BOUNDARY_EDGE_AND_CORNER}};
    for (const auto& [token, value] : boundaries)
        EXPECT_EQ(options(token, "cornersPlus1", "catmullClark").GetVtxBoundaryInterpolation(), value) << token;
    const std::map<std::string, Options::FVarLinearInterpolation> fvars = {
        {"none", Options::FVAR_LINEAR_NONE},
        {"cornersOnly", Options::FVAR_LINEAR_CORNERS_ONLY},
        {"cornersPlus1", Options::FVAR_LINEAR_CORNERS_PLUS1},
        {"cornersPlus2", Options::FVAR_LINEAR_CORNERS_PLUS2},
        {"boundaries", Options::FVAR_LINEAR_BOUNDARIES},
        {"all", Options::FVAR_LINEAR_ALL}};
    for (const auto& [token, value] : fvars)
        EXPECT_EQ(options("edgeAndCorner", token, "catmullClark").GetFVarLinearInterpolation(), value) << token;
    EXPECT_EQ(options("edgeAndCorner", "cornersPlus1", "catmullClark").GetTriangleSubdivision(),
              Options::TRI_SUB_CATMARK);
    EXPECT_EQ(options("edgeAndCorner", "cornersPlus1", "smooth").GetTriangleSubdivision(), Options::TRI_SUB_SMOOTH);
    EXPECT_EQ(options("edgeAndCorner", "cornersPlus1", "smooth").GetCreasingMethod(), Options::CREASE_UNIFORM);
    EXPECT_EQ(subdivision_detail::sdcScheme(Scheme::CatmullClark), OpenSubdiv::Sdc::SCHEME_CATMARK);
    EXPECT_EQ(subdivision_detail::sdcScheme(Scheme::Loop), OpenSubdiv::Sdc::SCHEME_LOOP);
    EXPECT_EQ(subdivision_detail::sdcScheme(Scheme::Bilinear), OpenSubdiv::Sdc::SCHEME_BILINEAR);
    // USD's defaults are the struct's defaults.
    SubdivisionTopology defaults;
    EXPECT_EQ(subdivision_detail::sdcOptions(defaults).GetVtxBoundaryInterpolation(),
              Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    EXPECT_EQ(subdivision_detail::sdcOptions(defaults).GetFVarLinearInterpolation(),
              Options::FVAR_LINEAR_CORNERS_PLUS1);
}

TEST(Subdivision, RejectsBadTopologyAndTokensWithClearMessages) {
    struct BadCase {
        std::string expected;  // part of the message
        std::function<void(SubdivisionTopology&, std::vector<FaceVaryingData>&)> edit;
    };
    const std::vector<BadCase> bad = {
        {"unknown interpolateBoundary \"edgesAndCorners\"",
         [](auto& t, auto&) { t.interpolateBoundary = "edgesAndCorners"; }},
        {"unknown faceVaryingLinearInterpolation \"cornersPlus3\"",
         [](auto& t, auto&) { t.faceVaryingLinearInterpolation = "cornersPlus3"; }},
        {"unknown triangleSubdivisionRule \"loop\"", [](auto& t, auto&) { t.triangleSubdivisionRule = "loop"; }},
        {"faceVertexCounts[1] is 2",
         [](auto& t, auto&) {
             t.faceVertexCounts[1] = 2;
             t.faceVertexIndices.erase(t.faceVertexIndices.begin() + 4, t.faceVertexIndices.begin() + 6);
         }},
        {"faceVertexCounts add up to 24 but faceVertexIndices has 23",
         [](auto& t, auto&) { t.faceVertexIndices.pop_back(); }},
        {"faceVertexIndices[5] = 8 is not a point", [](auto& t, auto&) { t.faceVertexIndices[5] = 8; }},
        {"face 0 uses point 3 twice in a row", [](auto& t, auto&) { t.faceVertexIndices[2] = 3; }},
        {"the loop scheme needs triangles, but face 0 has 4 points", [](auto& t, auto&) { t.scheme = Scheme::Loop; }},
        {"creaseLengths[0] is 1",
         [](auto& t, auto&) {
             t.creaseIndices = {0};
             t.creaseLengths = {1};
             t.creaseSharpnesses = {1.0f};
         }},
        {"creaseLengths add up to 3 but creaseIndices has 2",
         [](auto& t, auto&) {
             t.creaseIndices = {0, 1};
             t.creaseLengths = {3};
             t.creaseSharpnesses = {1.0f};
         }},
        {"creaseSharpnesses has 2 entries: expected one per crease (1) or one per crease edge (3)",
         [](auto& t, auto&) {
             t.creaseIndices = {0, 1, 2, 3};
             t.creaseLengths = {4};
             t.creaseSharpnesses = {1.0f, 2.0f};
         }},
        {"crease 0 runs from point 0 to point 6, which is not an edge",
         [](auto& t, auto&) {
             t.creaseIndices = {0, 6};
             t.creaseLengths = {2};
             t.creaseSharpnesses = {1.0f};
         }},
        {"creaseSharpnesses[0] is NaN",
         [](auto& t, auto&) {
             t.creaseIndices = {0, 1};
             t.creaseLengths = {2};
             t.creaseSharpnesses = {std::nanf("")};
         }},
        {"cornerIndices has 1 entries but cornerSharpnesses has 0", [](auto& t, auto&) { t.cornerIndices = {0}; }},
        {"cornerIndices[0] = -1 is not a point",
         [](auto& t, auto&) {
             t.cornerIndices = {-1};
             t.cornerSharpnesses = {10.0f};
         }},
        {"holeIndices[0] = 6 is not a face", [](auto& t, auto&) { t.holeIndices = {6}; }},
    };
    for (std::size_t i = 0; i < bad.size(); ++i) {
        Cage c = cube();
        std::vector<FaceVaryingData> fvar;
        bad[i].edit(c.topology, fvar);
        std::string message = messageOf([&] { SubdivisionSurface(c.topology, fvar); });
        EXPECT_NE(message.find(bad[i].expected), std::string::npos)
            << "expected \"" << bad[i].expected << "\" in \"" << message << "\"";
    }

    // Face-varying channels.
    Cage c = cube();
    FaceVaryingData uv{2, {0, 0, 1, 0, 1, 1, 0, 1}, std::vector<int>(24, 0)};
    EXPECT_NO_THROW(SubdivisionSurface(c.topology, {uv}));
    auto fvarMessage = [&](FaceVaryingData channel) {
        return messageOf([&] { SubdivisionSurface(c.topology, {uv, channel}); });
    };
    FaceVaryingData badIndex = uv;
    badIndex.indices[7] = 4;
    EXPECT_NE(fvarMessage(badIndex).find("face-varying channel 1: indices[7] = 4 is not a value (4 values)"),
              std::string::npos)
        << fvarMessage(badIndex);
    FaceVaryingData shortIndices = uv;
    shortIndices.indices.resize(23);
    EXPECT_NE(fvarMessage(shortIndices).find("has 23 indices, but the mesh has 24 face-vertices"), std::string::npos);
    FaceVaryingData ragged = uv;
    ragged.values.push_back(0.5f);
    EXPECT_NE(fvarMessage(ragged).find("has 9 floats, not a multiple of its 2 components"), std::string::npos);
    FaceVaryingData unindexed{2, std::vector<float>(2 * 23, 0.0f), {}};
    EXPECT_NE(fvarMessage(unindexed).find("has no indices and 23 values, but the mesh has 24 face-vertices"),
              std::string::npos);

    // Tessellation inputs.
    SubdivisionSurface surface(c.topology);
    std::vector<int> rates(surface.edges().size(), 2);
    auto tessMessage = [&](std::span<const Vec3f> points, std::vector<int> r, std::vector<VertexData> data = {}) {
        return messageOf([&] { surface.tessellate(points, r, data); });
    };
    EXPECT_NE(tessMessage(std::span(c.points).first(7), rates).find("7 points given for 8 control points"),
              std::string::npos);
    EXPECT_NE(tessMessage(c.points, std::vector<int>(11, 2)).find("11 edge segment counts given for 12 edges"),
              std::string::npos);
    auto zero = rates;
    zero[3] = 0;
    EXPECT_NE(tessMessage(c.points, zero).find("edge 3 has 0 segments"), std::string::npos);
    auto huge = rates;
    huge[3] = SubdivisionSurface::kMaxEdgeSegments + 1;
    EXPECT_NE(tessMessage(c.points, huge).find("edge 3 has 4097 segments"), std::string::npos);
    EXPECT_NE(tessMessage(c.points, rates, {VertexData{3, std::vector<float>(23), false}})
                  .find("vertex data channel 0 has 23 floats, expected 3 per point"),
              std::string::npos);
    EXPECT_NE(messageOf([&] { surface.tessellateUniform(c.points, 13); }).find("uniform level 13 is not in [0, 12]"),
              std::string::npos);
    EXPECT_NE(messageOf([&] { surface.tessellateUniform(c.points, -1); }).find("uniform level -1"), std::string::npos);
}

TEST(Subdivision, MeshWithoutFacesTessellatesToNothing) {
    SubdivisionTopology t;
    t.pointCount = 3;
    SubdivisionSurface surface(t);
    EXPECT_TRUE(surface.edges().empty());
    auto result = surface.tessellateUniform(std::vector<Vec3f>(3), 2);
    EXPECT_TRUE(result.positions.empty());
    EXPECT_TRUE(result.indices.empty());
}

TEST(Subdivision, EdgesAreSortedPairsAndFacesReferToThem) {
    Cage c = cube();
    SubdivisionSurface surface(c.topology);
    const auto& edges = surface.edges();
    ASSERT_EQ(edges.size(), 12u);
    EXPECT_TRUE(std::is_sorted(edges.begin(), edges.end()));
    for (const auto& [a, b] : edges) EXPECT_LT(a, b);
    for (int f = 0; f < surface.faceCount(); ++f) {
        auto faceEdges = surface.faceEdges(f);
        ASSERT_EQ(faceEdges.size(), 4u);
        for (int i = 0; i < 4; ++i) {
            int a = c.topology.faceVertexIndices[4 * f + i], b = c.topology.faceVertexIndices[4 * f + (i + 1) % 4];
            EXPECT_EQ(edges[std::size_t(faceEdges[i])], std::pair(std::min(a, b), std::max(a, b)));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Counts

TEST(Subdivision, UniformLevelGivesTwiceFourToTheLevelTrianglesPerQuad) {
    Cage c = cube();
    Grid g = grid(5, 4, bumps);  // open: 12 quads, 31 edges, 20 points
    for (int level = 0; level <= 4; ++level) {
        const std::size_t r = std::size_t(1) << level;
        auto closed = SubdivisionSurface(c.topology).tessellateUniform(c.points, level);
        EXPECT_EQ(closed.triangleFaces.size(), 2 * (r * r) * 6) << "level " << level;
        EXPECT_EQ(closed.indices.size(), 3 * closed.triangleFaces.size());
        // Shared points counted once: V + E (r - 1) + F (r - 1)^2.
        EXPECT_EQ(closed.positions.size(), 8 + 12 * (r - 1) + 6 * (r - 1) * (r - 1)) << "level " << level;
        auto open = SubdivisionSurface(g.topology).tessellateUniform(g.points, level);
        EXPECT_EQ(open.triangleFaces.size(), 2 * (r * r) * 12) << "level " << level;
        EXPECT_EQ(open.positions.size(), 20 + 31 * (r - 1) + 12 * (r - 1) * (r - 1)) << "level " << level;
    }
}

// ---------------------------------------------------------------------------------------------
// Closed forms

TEST(Subdivision, RegularInteriorPatchIsTheUniformBicubicBSpline) {
    // 6x6 control points, 5x5 faces: the faces whose four corners are interior (x, y in 1..3) are
    // regular patches, each the bicubic B-spline of the 4x4 points around it.
    Grid g = grid(6, 6, bumps);
    SubdivisionSurface surface(g.topology);
    auto result = surface.tessellateUniform(g.points, 3);
    int checked = 0;
    for (std::size_t i = 0; i < result.positions.size(); ++i) {
        const auto& sc = result.surfaceCoords[i];
        const int fx = int(sc.face) % 5, fy = int(sc.face) / 5;
        if (fx < 1 || fx > 3 || fy < 1 || fy > 3) continue;
        auto bu = bspline(sc.u), bv = bspline(sc.v), du = bsplineDerivative(sc.u), dv = bsplineDerivative(sc.v);
        Vec3d P(0.0), Pu(0.0), Pv(0.0);
        for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a) {
                Vec3d cp(g.points[std::size_t(g.point(fx - 1 + a, fy - 1 + b))]);
                P += bu[a] * bv[b] * cp;
                Pu += du[a] * bv[b] * cp;
                Pv += bu[a] * dv[b] * cp;
            }
        EXPECT_LE(maxAbs(Vec3d(result.positions[i]) - P), 0x1p-23 * 5.0)
            << "face " << sc.face << " at (" << sc.u << ", " << sc.v << ")";
        EXPECT_LE(maxAbs(Vec3d(result.dPdu[i]) - Pu), 0x1p-23 * maxAbs(Pu))
            << "face " << sc.face << " at (" << sc.u << ", " << sc.v << ")";
        EXPECT_LE(maxAbs(Vec3d(result.dPdv[i]) - Pv), 0x1p-23 * maxAbs(Pv))
            << "face " << sc.face << " at (" << sc.u << ", " << sc.v << ")";
        EXPECT_LE(length(Vec3d(result.normals[i]) - normalize(cross(Pu, Pv))), 0x1p-21);
        ++checked;
    }
    // 9 faces with 9x9 points each, less the shared boundary points owned by the faces before them.
    EXPECT_GT(checked, 9 * 7 * 7);
}

TEST(Subdivision, BilinearSchemeInterpolatesEachQuadBilinearly) {
    Grid g = grid(4, 3, bumps);
    g.topology.scheme = Scheme::Bilinear;
    SubdivisionSurface surface(g.topology);
    auto result = surface.tessellateUniform(g.points, 2);
    for (std::size_t i = 0; i < result.positions.size(); ++i) {
        const auto& sc = result.surfaceCoords[i];
        const int fx = int(sc.face) % 3, fy = int(sc.face) / 3;
        double u = sc.u, v = sc.v;
        Vec3d p00(g.points[std::size_t(g.point(fx, fy))]), p10(g.points[std::size_t(g.point(fx + 1, fy))]);
        Vec3d p11(g.points[std::size_t(g.point(fx + 1, fy + 1))]), p01(g.points[std::size_t(g.point(fx, fy + 1))]);
        Vec3d expected = (1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + u * v * p11 + (1 - u) * v * p01;
        EXPECT_LE(maxAbs(Vec3d(result.positions[i]) - expected), 0x1p-23 * 4.0) << "vertex " << i;
    }
}

// ---------------------------------------------------------------------------------------------
// Creases and corners

// A bumpy 5x5 grid whose middle row (y = 2) is a straight polyline on the x axis at z = 0, and
// whose rows on either side bulge differently: a smooth surface leaves that line.
Grid creaseGrid() {
    return grid(5, 5, [](int x, int y) {
        return y == 2 ? 0.0f : (y < 2 ? 0.8f + 0.1f * float(x) : -0.5f + 0.2f * float(x % 2));
    });
}

// Output vertices on the middle row's edges: the faces below it (y = 1) meet it at v = 1, those
// above (y = 2) at v = 0.
std::vector<std::size_t> middleRowVertices(const SubdivisionSurface::Result& result) {
    std::vector<std::size_t> on;
    for (std::size_t i = 0; i < result.positions.size(); ++i) {
        const auto& sc = result.surfaceCoords[i];
        const int fy = int(sc.face) / 4;
        if ((fy == 1 && sc.v == 1.0f) || (fy == 2 && sc.v == 0.0f)) on.push_back(i);
    }
    return on;
}

TEST(Subdivision, InfinitelySharpCreaseStaysOnItsStraightControlPolygon) {
    Grid g = creaseGrid();
    // Control: without the crease the limit curve of that row leaves the line.
    {
        auto smooth = SubdivisionSurface(g.topology).tessellateUniform(g.points, 3);
        double maxZ = 0.0;
        for (std::size_t i : middleRowVertices(smooth)) maxZ = std::max(maxZ, double(std::abs(smooth.positions[i].z)));
        EXPECT_GT(maxZ, 0.05);
    }
    // One USD crease chain of five points, sharpness "infinite" (given as +inf: 10 or more).
    g.topology.creaseIndices = {g.point(0, 2), g.point(1, 2), g.point(2, 2), g.point(3, 2), g.point(4, 2)};
    g.topology.creaseLengths = {5};
    g.topology.creaseSharpnesses = {std::numeric_limits<float>::infinity()};
    auto creased = SubdivisionSurface(g.topology).tessellateUniform(g.points, 3);
    auto on = middleRowVertices(creased);
    EXPECT_EQ(on.size(), 5u + 4u * 7u);  // 5 base points and 7 inner points on each of 4 edges
    for (std::size_t i : on) {
        const Vec3f& p = creased.positions[i];
        EXPECT_LE(std::abs(p.y - 2.0f), 0x1p-23f * 4.0f) << to_string(p);
        EXPECT_LE(std::abs(p.z), 0x1p-23f * 4.0f) << to_string(p);
        EXPECT_GE(p.x, 0.0f);
        EXPECT_LE(p.x, 4.0f);
    }
    // Sharpness 10 (finite, at OpenSubdiv's infinite threshold) is the same surface.
    g.topology.creaseSharpnesses = {10.0f};
    auto ten = SubdivisionSurface(g.topology).tessellateUniform(g.points, 3);
    EXPECT_EQ(ten.positions, creased.positions);
}

TEST(Subdivision, SharpCornerKeepsItsControlPoint) {
    // Interior point (2, 2) of a bumpy grid raised into a spike, and the boundary corner (0, 0)
    // with edgeOnly boundaries (which round corners off unless they are sharp).
    Grid g = grid(5, 5, [](int x, int y) { return x == 2 && y == 2 ? 1.5f : bumps(x, y); });
    g.topology.interpolateBoundary = "edgeOnly";
    const int spike = g.point(2, 2), corner = g.point(0, 0);
    auto smooth = SubdivisionSurface(g.topology).tessellateUniform(g.points, 2);
    // Every point is used, so output vertex p is base point p (the documented layout).
    EXPECT_GT(length(smooth.positions[std::size_t(spike)] - g.points[std::size_t(spike)]), 0.1f);
    EXPECT_GT(length(smooth.positions[std::size_t(corner)] - g.points[std::size_t(corner)]), 0.1f);
    g.topology.cornerIndices = {spike, corner};
    g.topology.cornerSharpnesses = {10.0f, 12.0f};
    auto sharp = SubdivisionSurface(g.topology).tessellateUniform(g.points, 2);
    EXPECT_LE(maxAbs(Vec3d(sharp.positions[std::size_t(spike)] - g.points[std::size_t(spike)])), 0x1p-23 * 4.0);
    EXPECT_LE(maxAbs(Vec3d(sharp.positions[std::size_t(corner)] - g.points[std::size_t(corner)])), 0x1p-23 * 4.0);
}

TEST(Subdivision, CubeWithInfinitelySharpEdgesIsTheCubeWithFaceNormalsPerCorner) {
    // Every edge and corner infinitely sharp: the limit surface is the cube itself. Each triangle
    // corner carries its own face's normal, while a shared vertex has only one normal.
    Cage c = cube();
    SubdivisionSurface plain(c.topology);
    for (const auto& [a, b] : plain.edges()) {
        c.topology.creaseIndices.insert(c.topology.creaseIndices.end(), {a, b});
        c.topology.creaseLengths.push_back(2);
    }
    c.topology.creaseSharpnesses.assign(c.topology.creaseLengths.size(), 10.0f);
    for (int p = 0; p < 8; ++p) c.topology.cornerIndices.push_back(p), c.topology.cornerSharpnesses.push_back(10.0f);
    auto result = SubdivisionSurface(c.topology).tessellate(c.points, std::vector<int>(12, 4));
    for (const Vec3f& p : result.positions) EXPECT_NEAR(maxComponent(vmax(p, -p)), 1.0f, 0x1p-23f) << to_string(p);
    for (std::size_t t = 0; t < result.triangleFaces.size(); ++t) {
        const int f = int(result.triangleFaces[t]);
        // The face's outward axis: the cube's points of face f all share one coordinate.
        Vec3f a = c.points[std::size_t(c.topology.faceVertexIndices[4 * f])],
              b = c.points[std::size_t(c.topology.faceVertexIndices[4 * f + 2])];
        Vec3f axis = (a + b) * 0.5f;
        for (int k = 0; k < 3; ++k)
            EXPECT_LE(length(result.cornerNormals[3 * t + k] - axis), 0x1p-22f) << "triangle " << t;
    }
}

// ---------------------------------------------------------------------------------------------
// Holes

TEST(Subdivision, HoleFacesProduceNoTrianglesAndRaysPassThroughThem) {
    // A flat 6x6 grid: its limit surface is the plane z = 0, and on a regular grid face (x, y)
    // covers the unit square [x, x+1] x [y, y+1] away from the boundary.
    Grid g = grid(6, 6, [](int, int) { return 0.0f; });
    const int hole = g.face(2, 2);
    g.topology.holeIndices = {hole};
    SubdivisionSurface surface(g.topology);
    EXPECT_FALSE(surface.faceHasLimitSurface(hole));
    EXPECT_TRUE(surface.faceHasLimitSurface(g.face(1, 2)));
    auto result = surface.tessellateUniform(g.points, 2);
    EXPECT_EQ(result.triangleFaces.size(), (25u - 1u) * 2u * 16u);
    EXPECT_EQ(std::count(result.triangleFaces.begin(), result.triangleFaces.end(), std::uint32_t(hole)), 0);

    render::SceneDescription desc;
    desc.meshes.push_back({"grid", result.positions, result.indices, {}, {}, -1, {}});
    render::RenderScene scene(desc);
    auto down = [&](float x, float y) {
        render::Ray ray{{x, y, 1.0f}, {0.0f, 0.0f, -1.0f}};
        return scene.intersect(ray).has_value();
    };
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            float s = (float(i) + 0.5f) / 8.0f, t = (float(j) + 0.5f) / 8.0f;
            EXPECT_FALSE(down(2.0f + s, 2.0f + t)) << "hole at (" << 2.0f + s << ", " << 2.0f + t << ")";
            EXPECT_TRUE(down(1.0f + s, 2.0f + t)) << "face (1, 2) at (" << 1.0f + s << ", " << 2.0f + t << ")";
            EXPECT_TRUE(down(3.0f + s, 3.0f + t)) << "face (3, 3) at (" << 3.0f + s << ", " << 3.0f + t << ")";
        }
}

TEST(Subdivision, InterpolateBoundaryNoneDropsBoundaryFaces) {
    Grid g = grid(5, 5, bumps);
    g.topology.interpolateBoundary = "none";
    SubdivisionSurface surface(g.topology);
    auto result = surface.tessellateUniform(g.points, 1);
    // Only the 2x2 faces away from the boundary have a limit surface.
    std::set<std::uint32_t> faces(result.triangleFaces.begin(), result.triangleFaces.end());
    EXPECT_EQ(faces, (std::set<std::uint32_t>{std::uint32_t(g.face(1, 1)), std::uint32_t(g.face(2, 1)),
                                              std::uint32_t(g.face(1, 2)), std::uint32_t(g.face(2, 2))}));
    EXPECT_FALSE(surface.faceHasLimitSurface(g.face(0, 0)));
}

// ---------------------------------------------------------------------------------------------
// Face-varying data

// UVs for a 5x5-point grid with a seam down the middle column (x = 2): faces left of it use
// values 0..14, faces right of it their own copies of the seam column. uv = (x / 4, y / 4), and
// the right island is shifted by (0.5, 0).
FaceVaryingData seamUVs(const Grid& g) {
    FaceVaryingData uv{2, {}, {}};
    std::map<std::pair<int, int>, int> leftIndex, rightIndex;  // (x, y) -> value
    auto value = [&](int x, int y, bool right) {
        auto& table = right ? rightIndex : leftIndex;
        auto [it, inserted] = table.try_emplace({x, y}, int(uv.values.size() / 2));
        if (inserted) uv.values.insert(uv.values.end(), {float(x) / 4.0f + (right ? 0.5f : 0.0f), float(y) / 4.0f});
        return it->second;
    };
    for (int y = 0; y + 1 < g.ny; ++y)
        for (int x = 0; x + 1 < g.nx; ++x) {
            bool right = x >= 2;
            for (auto [px, py] : {std::pair(x, y), std::pair(x + 1, y), std::pair(x + 1, y + 1), std::pair(x, y + 1)})
                uv.indices.push_back(value(px, py, right));
        }
    return uv;
}

TEST(Subdivision, FaceVaryingIsContinuousAcrossEdgesAndSplitAtSeams) {
    Grid g = grid(5, 5, bumps);
    FaceVaryingData uv = seamUVs(g);
    for (const std::string interpolation : {"cornersPlus1", "none", "all"}) {
        SCOPED_TRACE(interpolation);
        g.topology.faceVaryingLinearInterpolation = interpolation;
        SubdivisionSurface surface(g.topology, {uv});
        // Rates differ per edge (1, 2, 4 or 8): the face-varying points of an edge follow its rate.
        std::vector<int> rates(surface.edges().size());
        for (std::size_t e = 0; e < rates.size(); ++e) rates[e] = 1 << (e % 4);
        auto result = surface.tessellate(g.points, rates);
        ASSERT_EQ(result.faceVarying.size(), 1u);
        const FaceVaryingData& out = result.faceVarying[0];
        ASSERT_EQ(out.components, 2);
        ASSERT_EQ(out.indices.size(), result.indices.size());

        // Group triangle corners by output vertex; compare the corners of different faces.
        std::map<std::uint32_t, std::vector<std::size_t>> corners;
        for (std::size_t k = 0; k < result.indices.size(); ++k) corners[result.indices[k]].push_back(k);
        int continuousPairs = 0, seamPairs = 0;
        for (const auto& [vertex, list] : corners)
            for (std::size_t a : list)
                for (std::size_t b : list) {
                    const int fa = int(result.triangleFaces[a / 3]), fb = int(result.triangleFaces[b / 3]);
                    if (fa >= fb) continue;
                    const bool sameSide = (fa % 4 >= 2) == (fb % 4 >= 2);
                    const std::uint32_t ia = out.indices[a], ib = out.indices[b];
                    if (sameSide) {
                        // Continuous face-varying topology: one value, shared by index.
                        EXPECT_EQ(ia, ib) << "faces " << fa << " and " << fb << " at vertex " << vertex;
                        ++continuousPairs;
                    } else {
                        // A seam stays a seam: different values (the islands are 0.5 apart in u; a
                        // smoothed island corner moves a little), the same v.
                        EXPECT_NE(ia, ib);
                        EXPECT_GT(std::abs(out.values[2 * ib] - out.values[2 * ia]), 0.25f)
                            << "faces " << fa << " and " << fb;
                        EXPECT_NEAR(out.values[2 * ib + 1], out.values[2 * ia + 1], 0x1p-23f);
                        ++seamPairs;
                    }
                }
        EXPECT_GT(continuousPairs, 100);
        EXPECT_GT(seamPairs, 10);
    }
}

TEST(Subdivision, FaceVaryingLinearAllIsBilinearPerFace) {
    // With "all", face-varying data is interpolated bilinearly over each face's (u, v).
    Grid g = grid(4, 4, bumps);
    g.topology.faceVaryingLinearInterpolation = "all";
    FaceVaryingData uv{2, {}, {}};
    for (std::size_t k = 0; k < g.topology.faceVertexIndices.size(); ++k) {
        // Arbitrary per-face-vertex values (no sharing: every face its own).
        uv.values.insert(uv.values.end(), {std::sin(float(k)), std::cos(1.3f * float(k))});
        uv.indices.push_back(int(k));
    }
    SubdivisionSurface surface(g.topology, {uv});
    auto result = surface.tessellateUniform(g.points, 2);
    const FaceVaryingData& out = result.faceVarying[0];
    for (std::size_t k = 0; k < result.indices.size(); ++k) {
        const std::uint32_t vertex = result.indices[k];
        const int f = int(result.triangleFaces[k / 3]);
        const auto& sc = result.surfaceCoords[vertex];
        if (int(sc.face) != f) continue;  // (u, v) of this face known only where it evaluated the vertex
        double u = sc.u, v = sc.v;
        const double w[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
        for (int c = 0; c < 2; ++c) {
            double expected = 0.0;
            for (int i = 0; i < 4; ++i)
                expected += w[i] * uv.values[2 * std::size_t(uv.indices[std::size_t(4 * f + i)]) + std::size_t(c)];
            EXPECT_NEAR(out.values[2 * std::size_t(out.indices[k]) + std::size_t(c)], expected, 0x1p-23)
                << "face " << f;
        }
    }
}

TEST(Subdivision, UnindexedFaceVaryingGivesEveryFaceItsOwnValues) {
    Grid g = grid(3, 3, bumps);
    FaceVaryingData uv{1, std::vector<float>(16, 0.0f), {}};
    for (std::size_t k = 0; k < 16; ++k) uv.values[k] = float(k);
    SubdivisionSurface surface(g.topology, {uv});
    auto result = surface.tessellateUniform(g.points, 1);
    // No two faces share a face-varying value.
    std::map<std::uint32_t, std::set<std::uint32_t>> facesOfValue;
    for (std::size_t k = 0; k < result.indices.size(); ++k)
        facesOfValue[result.faceVarying[0].indices[k]].insert(result.triangleFaces[k / 3]);
    for (const auto& [value, faces] : facesOfValue) EXPECT_EQ(faces.size(), 1u) << "value " << value;
}

// ---------------------------------------------------------------------------------------------
// Vertex and varying primvars, orientation

TEST(Subdivision, VertexDataIsRefinedLikePointsAndVaryingDataLinearly) {
    Cage c = cube();
    for (std::size_t i = 0; i < c.points.size(); ++i)
        c.points[i] += Vec3f(0.1f * float(i % 3), -0.07f * float(i % 2), 0.05f * float(i));
    VertexData asPoints{3, {}, false}, varying{3, {}, true};
    for (const Vec3f& p : c.points) {
        asPoints.values.insert(asPoints.values.end(), {p.x, p.y, p.z});
        varying.values.insert(varying.values.end(), {p.x, p.y, p.z});
    }
    std::vector<VertexData> data = {asPoints, varying};
    SubdivisionSurface surface(c.topology);
    auto result = surface.tessellateUniform(c.points, 2, data);
    ASSERT_EQ(result.vertexData.size(), 2u);
    for (std::size_t i = 0; i < result.positions.size(); ++i) {
        // A vertex primvar equal to the points refines to the limit positions.
        Vec3d vertex(result.vertexData[0][3 * i], result.vertexData[0][3 * i + 1], result.vertexData[0][3 * i + 2]);
        EXPECT_LE(maxAbs(vertex - Vec3d(result.positions[i])), 0x1p-23 * 2.0) << "vertex " << i;
        // A varying one is the bilinear interpolation of the face's points.
        const auto& sc = result.surfaceCoords[i];
        double u = sc.u, v = sc.v;
        const double w[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
        Vec3d expected(0.0);
        for (int k = 0; k < 4; ++k)
            expected +=
                w[k] * Vec3d(c.points[std::size_t(c.topology.faceVertexIndices[4 * sc.face + std::uint32_t(k)])]);
        Vec3d got(result.vertexData[1][3 * i], result.vertexData[1][3 * i + 1], result.vertexData[1][3 * i + 2]);
        EXPECT_LE(maxAbs(got - expected), 0x1p-23 * 2.0) << "vertex " << i;
    }
}

TEST(Subdivision, TrianglesAndNormalsFaceTheWayTheControlFacesDo) {
    // The cube's faces are counter-clockwise seen from outside: every triangle and every normal
    // must face outward; reversing every face turns them all inward.
    for (bool reversed : {false, true}) {
        Cage c = cube();
        if (reversed)
            for (std::size_t f = 0; f < 6; ++f)
                std::reverse(c.topology.faceVertexIndices.begin() + 4 * f,
                             c.topology.faceVertexIndices.begin() + 4 * f + 4);
        auto result =
            SubdivisionSurface(c.topology).tessellate(c.points, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 1, 2, 3, 4});
        const float sign = reversed ? -1.0f : 1.0f;
        for (std::size_t t = 0; t < result.triangleFaces.size(); ++t) {
            const std::uint32_t* tri = &result.indices[3 * t];
            Vec3f a = result.positions[tri[0]], b = result.positions[tri[1]], d = result.positions[tri[2]];
            Vec3f centroid = (a + b + d) / 3.0f;
            EXPECT_GT(sign * dot(cross(b - a, d - a), centroid), 0.0f) << "triangle " << t;
            for (int k = 0; k < 3; ++k)
                EXPECT_GT(sign * dot(result.cornerNormals[3 * t + k], result.positions[tri[k]]), 0.0f);
        }
        for (std::size_t i = 0; i < result.positions.size(); ++i) {
            EXPECT_NEAR(length(result.normals[i]), 1.0f, 0x1p-22f);
            EXPECT_GT(sign * dot(result.normals[i], result.positions[i]), 0.0f) << "vertex " << i;
            // The normal is the derivatives' cross product, in the face's orientation.
            EXPECT_GT(dot(result.normals[i], cross(result.dPdu[i], result.dPdv[i])), 0.0f);
        }
    }
}

TEST(Subdivision, LoopAndNonQuadCatmullClarkFacesTessellate) {
    // A square pyramid: a quad base and four triangles (Catmull-Clark), then its triangulation
    // under Loop.
    Cage pyramid;
    pyramid.points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1.5f}};
    pyramid.topology.pointCount = 5;
    pyramid.topology.faceVertexCounts = {4, 3, 3, 3, 3};
    pyramid.topology.faceVertexIndices = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    auto cc = SubdivisionSurface(pyramid.topology).tessellateUniform(pyramid.points, 2);
    std::set<std::uint32_t> faces(cc.triangleFaces.begin(), cc.triangleFaces.end());
    EXPECT_EQ(faces.size(), 5u);
    EXPECT_EQ(std::count(cc.triangleFaces.begin(), cc.triangleFaces.end(), 0u), 2 * 16);

    Cage loop = pyramid;
    loop.topology.scheme = Scheme::Loop;
    loop.topology.faceVertexCounts = {3, 3, 3, 3, 3, 3};
    loop.topology.faceVertexIndices = {0, 3, 2, 0, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    auto result = SubdivisionSurface(loop.topology).tessellateUniform(loop.points, 2);
    // A uniformly tessellated triangle at rate r has r^2 triangles.
    EXPECT_EQ(result.triangleFaces.size(), 6u * 16u);
    EXPECT_EQ(result.positions.size(), 5u + 9u * 3u + 6u * 3u);  // V + E (r - 1) + F (r - 1)(r - 2) / 2
}

}  // namespace
}  // namespace fluence::delegate
