// UsdGeomHermiteCurves (delegate/curves_adapter.h), read and rendered: the tube's centre line
// passes where the cubic Hermite formula puts it (rays just inside the radius hit it, rays just
// outside miss), widths vary linearly along each segment, displayColor follows its
// interpolation, and bad tangents or too-short curves are reported.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

// Two curves in the plane z = 0: one of three vertices (two segments) with strong tangents, and
// one of two vertices.
const Vec3d kPoints[] = {{0, 0, 0}, {2, 1, 0}, {4, 0, 0}, {0, -2, 0}, {3, -2, 0}};
const Vec3d kTangents[] = {{0, 6, 0}, {4, 0, 0}, {0, -6, 0}, {2, 3, 0}, {2, -3, 0}};
constexpr double kRadius = 0.04;

std::string hermite(const std::string& extra = "") {
    return R"(def HermiteCurves "H"
{
    int[] curveVertexCounts = [3, 2]
    point3f[] points = [(0, 0, 0), (2, 1, 0), (4, 0, 0), (0, -2, 0), (3, -2, 0)]
    vector3f[] tangents = [(0, 6, 0), (4, 0, 0), (0, -6, 0), (2, 3, 0), (2, -3, 0)]
    float[] widths = [0.08]
)" + extra +
           "}\n";
}

// The cubic Hermite segment from vertex a to vertex a + 1 at u, and its derivative.
Vec3d hermiteAt(std::size_t a, double u) {
    const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u, h01 = -2 * u * u * u + 3 * u * u,
                 h11 = u * u * u - u * u;
    return kPoints[a] * h00 + kTangents[a] * h10 + kPoints[a + 1] * h01 + kTangents[a + 1] * h11;
}
Vec3d hermiteDerivative(std::size_t a, double u) {
    const double d00 = 6 * u * u - 6 * u, d10 = 3 * u * u - 4 * u + 1, d01 = -6 * u * u + 6 * u,
                 d11 = 3 * u * u - 2 * u;
    return kPoints[a] * d00 + kTangents[a] * d10 + kPoints[a + 1] * d01 + kTangents[a + 1] * d11;
}

TEST(HermiteCurves, TheCentreLineIsWhereTheHermiteFormulaPutsIt) {
    auto p = populate(hermite());
    ASSERT_EQ(p.result.scene.curves.size(), 1u) << (p.warnings.empty() ? "" : p.warnings.front());
    const render::CurvesDesc& c = p.result.scene.curves.front();
    EXPECT_EQ(c.segments.size(), 3u) << "two segments, then one";
    render::RenderScene scene(p.result.scene);
    int checked = 0;
    for (std::size_t a : {0u, 1u, 3u})
        for (double u : {0.1, 0.3, 0.5, 0.7, 0.9}) {
            const Vec3d centre = hermiteAt(a, u), along = normalize(hermiteDerivative(a, u));
            const Vec3d across(-along.y, along.x, 0.0);  // in the curve's plane
            // Looking straight down at points beside the centre line.
            auto downAt = [&](double offset) {
                const Vec3d from = centre + across * offset + Vec3d(0, 0, 5);
                return scene.intersect(render::Ray{Vec3f(from), Vec3f(0, 0, -1)});
            };
            const auto inside = downAt(0.8 * kRadius), outside = downAt(1.25 * kRadius);
            ASSERT_TRUE(inside.has_value()) << "segment from vertex " << a << ", u " << u;
            EXPECT_FALSE(outside.has_value()) << "segment from vertex " << a << ", u " << u;
            // The tube's top at 0.8 r from its axis is 0.6 r above the plane.
            EXPECT_NEAR(inside->point.z, 0.6 * kRadius, 0.05 * kRadius) << "segment from vertex " << a << ", u " << u;
            const auto farSide = downAt(-0.8 * kRadius);
            EXPECT_TRUE(farSide.has_value()) << "segment from vertex " << a << ", u " << u;
            ++checked;
        }
    EXPECT_EQ(checked, 15);
}

TEST(HermiteCurves, WidthsAndColoursFollowTheirInterpolation) {
    auto p = populate(R"(def HermiteCurves "H"
{
    int[] curveVertexCounts = [3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]
    vector3f[] tangents = [(1, 0, 0), (1, 0, 0), (1, 0, 0)]
    float[] widths = [0.2, 0.8, 0.2] (interpolation = "varying")
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 0, 1)] (interpolation = "uniform")
    normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1)] (interpolation = "vertex")
}
def HermiteCurves "Both"
{
    int[] curveVertexCounts = [2, 2]
    point3f[] points = [(0, 1, 0), (1, 1, 0), (0, 2, 0), (1, 2, 0)]
    vector3f[] tangents = [(1, 0, 0), (1, 0, 0), (1, 0, 0), (1, 0, 0)]
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0)] (interpolation = "uniform")
}
)");
    ASSERT_EQ(p.result.scene.curves.size(), 2u) << (p.warnings.empty() ? "" : p.warnings.front());
    const render::CurvesDesc& c = p.result.scene.curves[0];
    EXPECT_EQ(c.style, render::CurveStyle::Oriented) << "normals make a ribbon";
    ASSERT_EQ(c.points.size(), 7u);
    // Straight, evenly parameterised: the Bezier control points at thirds of each segment.
    for (std::size_t i = 0; i < 7; ++i) EXPECT_NEAR(c.points[i].x, double(i) / 3.0, 1e-6) << i;
    const float radii[] = {0.1f, 0.2f, 0.3f, 0.4f, 0.3f, 0.2f, 0.1f};
    for (std::size_t i = 0; i < 7; ++i) EXPECT_NEAR(c.radii[i], radii[i], 1e-6f) << i;
    EXPECT_EQ(c.colors.size(), 7u);
    const render::CurvesDesc& both = p.result.scene.curves[1];
    ASSERT_EQ(both.colors.size(), 8u);
    EXPECT_FLOAT_EQ(both.colors[3].x, 1.0f) << "the first curve is red";
    EXPECT_FLOAT_EQ(both.colors[4].y, 1.0f) << "the second green";
}

TEST(HermiteCurves, BadTangentsSkipThePrimAndShortCurvesAreLeftOut) {
    auto bad = populate(R"(def HermiteCurves "H"
{
    int[] curveVertexCounts = [2]
    point3f[] points = [(0, 0, 0), (1, 0, 0)]
    vector3f[] tangents = [(1, 0, 0)]
}
)");
    EXPECT_TRUE(bad.result.scene.curves.empty());
    ASSERT_FALSE(bad.warnings.empty());
    EXPECT_NE(bad.warnings.front().find("/H"), std::string::npos) << bad.warnings.front();
    EXPECT_NE(bad.warnings.front().find("tangents has 1 values for 2 points"), std::string::npos)
        << bad.warnings.front();

    auto shortCurve = populate(R"(def HermiteCurves "H"
{
    int[] curveVertexCounts = [1, 2]
    point3f[] points = [(5, 5, 5), (0, 0, 0), (1, 0, 0)]
    vector3f[] tangents = [(1, 0, 0), (1, 0, 0), (1, 0, 0)]
}
)");
    ASSERT_EQ(shortCurve.result.scene.curves.size(), 1u);
    EXPECT_EQ(shortCurve.result.scene.curves.front().segments.size(), 1u);
    ASSERT_FALSE(shortCurve.warnings.empty());
    EXPECT_NE(shortCurve.warnings.front().find("fewer than 2 vertices"), std::string::npos)
        << shortCurve.warnings.front();
}

}  // namespace
}  // namespace fluence::delegate
