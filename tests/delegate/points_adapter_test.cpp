// UsdGeomPoints through the delegate (delegate/points_adapter.h, delegate/points_rprim.h).
#include <gtest/gtest.h>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

TEST(PointsPrim, WidthsColoursStyleAndTransform) {
    auto p = populate(R"(def Xform "X" (
)
{
    double3 xformOp:translate = (1, 0, 0)
    double3 xformOp:scale = (2, 2, 2)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    def Points "P"
    {
        point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]
        float[] widths = [0.1, 0.2, 0.3] (interpolation = "vertex")
        color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0), (0, 0, 1)] (interpolation = "vertex")
        float[] primvars:heat = [5] (interpolation = "constant")
    }
}
)");
    EXPECT_TRUE(p.warnings.empty()) << (p.warnings.empty() ? "" : p.warnings.front());
    ASSERT_EQ(p.result.scene.points.size(), 1u);
    const render::PointsDesc& d = p.result.scene.points[0];
    EXPECT_EQ(d.name, "/X/P");
    EXPECT_EQ(d.style, render::PointStyle::Sphere);
    ASSERT_EQ(d.positions.size(), 3u);
    EXPECT_NEAR(d.positions[2].x, 5.0f, 1e-6f);
    EXPECT_NEAR(d.radii[1], 0.2f, 1e-6f) << "half the width, doubled by the scale";
    ASSERT_EQ(d.colors.size(), 3u);
    EXPECT_EQ(d.colors[2].z, 1.0f);
    bool heat = false;
    for (const render::PointPrimvar& v : d.primvars)
        if (v.name == "heat") heat = v.values == std::vector<float>{5, 5, 5};
    EXPECT_TRUE(heat) << "a constant primvar repeated per point";
}

TEST(PointsPrim, DefaultWidthConstantWidthAndDiscs) {
    auto p = populate(R"(def Points "A"
{
    point3f[] points = [(0, 0, 0), (1, 0, 0)]
}
def Points "B"
{
    point3f[] points = [(0, 0, 0), (1, 0, 0)]
    float[] widths = [0.5] (interpolation = "constant")
    normal3f[] normals = [(0, 0, 2)] (interpolation = "constant")
    uniform token primvars:fluence:pointStyle = "orientedDisc"
}
def Points "C"
{
    point3f[] points = [(0, 0, 0)]
    uniform token primvars:fluence:pointStyle = "disc"
}
)");
    EXPECT_TRUE(p.warnings.empty()) << (p.warnings.empty() ? "" : p.warnings.front());
    ASSERT_EQ(p.result.scene.points.size(), 3u);
    EXPECT_EQ(p.result.scene.points[0].radii, (std::vector<float>{0.5f, 0.5f})) << "width 1 where none is authored";
    const render::PointsDesc& b = p.result.scene.points[1];
    EXPECT_EQ(b.style, render::PointStyle::OrientedDisc);
    EXPECT_EQ(b.radii, (std::vector<float>{0.25f, 0.25f}));
    ASSERT_EQ(b.normals.size(), 2u);
    EXPECT_NEAR(b.normals[1].z, 1.0f, 1e-6f);
    EXPECT_EQ(p.result.scene.points[2].style, render::PointStyle::Disc);
}

TEST(PointsPrim, BadCountsSkipThePrimWithAWarningNamingIt) {
    auto p = populate(R"(def Points "Bad"
{
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]
    float[] widths = [0.1, 0.2] (interpolation = "vertex")
}
def Points "Style"
{
    point3f[] points = [(0, 0, 0)]
    uniform token primvars:fluence:pointStyle = "cube"
}
def Points "Good"
{
    point3f[] points = [(0, 0, 0)]
}
)");
    ASSERT_EQ(p.result.scene.points.size(), 1u);
    EXPECT_EQ(p.result.scene.points[0].name, "/Good");
    ASSERT_EQ(p.warnings.size(), 2u);
    EXPECT_NE(p.warnings[0].find("/Bad"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("widths"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[1].find("/Style"), std::string::npos) << p.warnings[1];
}

TEST(PointsPrim, BoundMaterialReplacesDisplayColor) {
    const std::string blue = R"(        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0, 0, 1)
            token outputs:surface
        }
)";
    auto p = populate(testing::quadBoundTo(blue) + R"(def Points "P" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{
    point3f[] points = [(0, 0, 0)]
    color3f[] primvars:displayColor = [(1, 0, 0)]
    rel material:binding = </Looks/M>
}
)");
    ASSERT_EQ(p.result.scene.points.size(), 1u);
    const render::PointsDesc& d = p.result.scene.points[0];
    ASSERT_GE(d.material, 0);
    EXPECT_TRUE(d.colors.empty());
    EXPECT_EQ(p.result.scene.materials[std::size_t(d.material)].diffuse.z, 1.0f);
}

}  // namespace
}  // namespace fluence::delegate
