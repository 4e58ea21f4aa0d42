// Primvars along curves and on points, from USD to the hit (delegate/curves_adapter.h,
// render/curve_primvars.h, delegate/points_adapter.h): rays straight down (an orthographic view)
// read the colour a hit shades with, against known answers — a linear curve's vertex colours ramp
// linearly along it; a cubic B-spline's are the B-spline of the colours; varying values are linear
// between segment ends; uniform ones colour each curve; points take theirs; a texture reads the
// st of each curve and point; and a primvar of the wrong length is ignored with a warning naming
// the prim, its reader falling back to its constant value.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "render/bsdfs/hair.h"
#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::delegate {
namespace {

using testing::populate;

// The reader's fallback, seen where the primvar is missing.
const RGB kFallback(0.2f, 0.3f, 0.4f);

// A UsdPreviewSurface whose diffuseColor is the primvar `varname` (a UsdPrimvarReader_float3), or
// the UsdUVTexture `file` at the primvar st when `file` is given.
std::string looks(const std::string& varname, const std::string& file = "") {
    const std::string diffuse = file.empty() ? "/Looks/M/Read.outputs:result" : "/Looks/M/Tex.outputs:rgb";
    return R"(
def Scope "Looks"
{
    def Material "M"
    {
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = <)" +
           diffuse + R"(>
            float inputs:roughness = 0.4
            token outputs:surface
        }
        def Shader "Read"
        {
            uniform token info:id = "UsdPrimvarReader_float3"
            string inputs:varname = ")" +
           varname + R"("
            float3 inputs:fallback = (0.2, 0.3, 0.4)
            float3 outputs:result
        }
        def Shader "St"
        {
            uniform token info:id = "UsdPrimvarReader_float2"
            string inputs:varname = "st"
            float2 outputs:result
        }
        )" +
           testing::rawTextureAtSt(file) + R"(    }
}
)";
}

// A curves prim of `type` and `basis` with `body`, bound to /Looks/M when `bound`.
std::string curves(const std::string& type, const std::string& basis, const std::string& body, bool bound) {
    return "def BasisCurves \"C\"\n{\n    uniform token type = \"" + type + "\"\n    uniform token basis = \"" + basis +
           "\"\n    float[] widths = [0.2]\n" + body + (bound ? "    rel material:binding = </Looks/M>\n" : "") + "}\n";
}

// The hit of a ray straight down at (x, y).
std::optional<render::SurfaceHit> downAt(const render::RenderScene& scene, float x, float y) {
    return scene.intersect(render::Ray{{x, y, 5.0f}, {0.0f, 0.0f, -1.0f}});
}

// The colour a hit straight down at (x, y) shades with (its albedo), and that its hair BSDF's
// absorption is the one of that colour.
RGB colourAt(const render::RenderScene& scene, float x, float y) {
    const std::optional<render::SurfaceHit> hit = downAt(scene, x, y);
    EXPECT_TRUE(hit) << "at (" << x << ", " << y << ")";
    if (!hit) return RGB(-1.0f);
    if (hit->curveGeometry >= 0) {
        EXPECT_TRUE(hit->material.hair);
        if (hit->material.hair) {
            const RGB absorption =
                render::hairAbsorptionFromColour(hit->material.diffuse, hit->material.hair->azimuthalRoughness);
            EXPECT_LT(length(hit->material.hair->absorption - absorption), 1e-5f) << "at (" << x << ", " << y << ")";
        }
    }
    return hit->material.diffuse;
}

RGB lerp(const RGB& a, const RGB& b, float t) { return a * (1.0f - t) + b * t; }

void expectColour(const RGB& got, const RGB& expected, const std::string& where) {
    EXPECT_LT(length(got - expected), 2e-3f)
        << where << ": got (" << got[0] << ", " << got[1] << ", " << got[2] << "), expected (" << expected[0] << ", "
        << expected[1] << ", " << expected[2] << ")";
}

TEST(CurvePrimvars, ALinearCurvesVertexColoursRampAlongIt) {
    const RGB red(1, 0, 0), blue(0, 0, 1);
    const std::string body = R"(    int[] curveVertexCounts = [2]
    point3f[] points = [(-2, 0, 0), (2, 0, 0)]
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 0, 1)] (interpolation = "vertex")
    float3[] primvars:tint = [(1, 0, 0), (0, 0, 1)] (interpolation = "vertex")
)";
    // displayColor with no material, and a material's primvar reader of another primvar.
    for (const bool bound : {false, true}) {
        auto p = populate(curves("linear", "bezier", body, bound) + (bound ? looks("tint") : ""));
        ASSERT_EQ(p.result.scene.curves.size(), 1u);
        EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
        render::RenderScene scene(p.result.scene);
        for (const float f : {0.05f, 0.25f, 0.5f, 0.75f, 0.95f})
            expectColour(colourAt(scene, -2.0f + 4.0f * f, 0.0f), lerp(red, blue, f),
                         std::string(bound ? "reader" : "displayColor") + " at " + std::to_string(f));
    }
}

// The uniform cubic B-spline basis at u.
std::array<float, 4> bspline(float u) {
    return {(1 - u) * (1 - u) * (1 - u) / 6, (3 * u * u * u - 6 * u * u + 4) / 6,
            (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6, u * u * u / 6};
}

TEST(CurvePrimvars, ACubicBSplinesVertexColoursAreTheBSplineOfTheColours) {
    // Control points evenly spaced along x: the curve runs from x = -1 to 1, segment s over
    // [s - 1, s] with u = x - (s - 1).
    const RGB colours[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}};
    const std::string body = R"(    int[] curveVertexCounts = [5]
    point3f[] points = [(-2, 0, 0), (-1, 0, 0), (0, 0, 0), (1, 0, 0), (2, 0, 0)]
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1)] (interpolation = "vertex")
)";
    for (const bool bound : {false, true}) {
        auto p = populate(curves("cubic", "bspline", body, bound) + (bound ? looks("displayColor") : ""));
        ASSERT_EQ(p.result.scene.curves.size(), 1u);
        render::RenderScene scene(p.result.scene);
        for (const float x : {-0.9f, -0.6f, -0.3f, 0.2f, 0.5f, 0.8f}) {
            const int s = x < 0.0f ? 0 : 1;
            const float u = x - float(s - 1);
            const std::array<float, 4> w = bspline(u);
            RGB expected(0.0f);
            for (int j = 0; j < 4; ++j) expected += colours[s + j] * w[std::size_t(j)];
            expectColour(colourAt(scene, x, 0.0f), expected,
                         std::string(bound ? "reader" : "displayColor") + " at x " + std::to_string(x));
        }
    }
}

TEST(CurvePrimvars, VaryingValuesAreLinearBetweenSegmentEndsWhateverTheBasis) {
    // A B-spline of 5 vertices has 2 segments and 3 varying values, at x = -1, 0 and 1.
    const RGB ends[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto p = populate(curves("cubic", "bspline", R"(    int[] curveVertexCounts = [5]
    point3f[] points = [(-2, 0, 0), (-1, 0, 0), (0, 0, 0), (1, 0, 0), (2, 0, 0)]
    float3[] primvars:tint = [(1, 0, 0), (0, 1, 0), (0, 0, 1)] (interpolation = "varying")
)",
                             true) +
                      looks("tint"));
    ASSERT_EQ(p.result.scene.curves.size(), 1u);
    render::RenderScene scene(p.result.scene);
    for (const float x : {-0.9f, -0.5f, -0.2f, 0.1f, 0.5f, 0.9f}) {
        const int s = x < 0.0f ? 0 : 1;
        expectColour(colourAt(scene, x, 0.0f), lerp(ends[s], ends[s + 1], x - float(s - 1)),
                     "varying at x " + std::to_string(x));
    }
}

TEST(CurvePrimvars, UniformColoursColourEachCurve) {
    const std::string body = R"(    int[] curveVertexCounts = [2, 2]
    point3f[] points = [(-2, 0, 0), (2, 0, 0), (-2, 1, 0), (2, 1, 0)]
    color3f[] primvars:displayColor = [(0.9, 0.1, 0.1), (0.1, 0.8, 0.2)] (interpolation = "uniform")
)";
    for (const bool bound : {false, true}) {
        auto p = populate(curves("linear", "bezier", body, bound) + (bound ? looks("displayColor") : ""));
        ASSERT_EQ(p.result.scene.curves.size(), 1u);
        render::RenderScene scene(p.result.scene);
        for (const float x : {-1.5f, 0.0f, 1.7f}) {
            const std::string how = std::string(bound ? "reader" : "displayColor") + " at x " + std::to_string(x);
            expectColour(colourAt(scene, x, 0.0f), RGB(0.9f, 0.1f, 0.1f), how + ", first curve");
            expectColour(colourAt(scene, x, 1.0f), RGB(0.1f, 0.8f, 0.2f), how + ", second curve");
        }
    }
}

TEST(CurvePrimvars, NurbsCurvesVertexPrimvarsFollowTheirBasis) {
    // Order 2 (linear) from x = -2 to 2: a vertex primvar ramps linearly along it.
    auto p = populate(R"(def NurbsCurves "N"
{
    int[] curveVertexCounts = [2]
    int[] order = [2]
    double[] knots = [0, 0, 1, 1]
    point3f[] points = [(-2, 0, 0), (2, 0, 0)]
    float[] widths = [0.2]
    float3[] primvars:tint = [(1, 0, 0), (0, 0, 1)] (interpolation = "vertex")
    rel material:binding = </Looks/M>
}
)" + looks("tint"));
    ASSERT_EQ(p.result.scene.curves.size(), 1u);
    render::RenderScene scene(p.result.scene);
    for (const float f : {0.1f, 0.4f, 0.7f})
        expectColour(colourAt(scene, -2.0f + 4.0f * f, 0.0f), lerp(RGB(1, 0, 0), RGB(0, 0, 1), f),
                     "at " + std::to_string(f));
}

TEST(CurvePrimvars, PointsTakeTheirPerPointColours) {
    const std::string points = R"(def Points "P"
{
    point3f[] points = [(-1, 0, 0), (0, 0, 0), (1, 0, 0)]
    float[] widths = [0.5]
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0), (0, 0, 1)] (interpolation = "vertex")
    float3[] primvars:tint = [(0.5, 0, 0), (0, 0.5, 0), (0, 0, 0.5)] (interpolation = "varying")
)";
    for (const bool bound : {false, true}) {
        auto p = populate(points + (bound ? "    rel material:binding = </Looks/M>\n}\n" + looks("tint") : "}\n"));
        ASSERT_EQ(p.result.scene.points.size(), 1u);
        render::RenderScene scene(p.result.scene);
        const float scale = bound ? 0.5f : 1.0f;
        expectColour(colourAt(scene, -1.0f, 0.0f), RGB(scale, 0, 0), "first point");
        expectColour(colourAt(scene, 0.0f, 0.0f), RGB(0, scale, 0), "second point");
        expectColour(colourAt(scene, 1.0f, 0.0f), RGB(0, 0, scale), "third point");
    }
}

class CurvePrimvarTextures : public ::testing::Test {
protected:
    std::string halves() { return test::writeHalvesTexture(dir.file("halves.exr")); }
    test::TempDir dir{"fluence_curve_primvar_textures"};
};

TEST_F(CurvePrimvarTextures, ATextureOnCurvesReadsEachCurvesSt) {
    // st per curve (uniform), as a groom's root position on the scalp.
    auto p = populate(curves("cubic", "catmullRom", R"(    int[] curveVertexCounts = [4, 4]
    point3f[] points = [(-2, 0, 0), (-1, 0, 0), (1, 0, 0), (2, 0, 0), (-2, 1, 0), (-1, 1, 0), (1, 1, 0), (2, 1, 0)]
    texCoord2f[] primvars:st = [(0.25, 0.5), (0.75, 0.5)] (interpolation = "uniform")
)",
                             true) +
                      looks("st", halves()));
    ASSERT_EQ(p.result.scene.curves.size(), 1u);
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
    render::RenderScene scene(p.result.scene);
    for (const float x : {-0.8f, 0.0f, 0.6f}) {
        expectColour(colourAt(scene, x, 0.0f), RGB(0, 0.5f, 0), "first curve at x " + std::to_string(x));
        expectColour(colourAt(scene, x, 1.0f), RGB(4.0f), "second curve at x " + std::to_string(x));
    }
}

TEST_F(CurvePrimvarTextures, ATextureOnPointsReadsEachPointsSt) {
    auto p = populate(R"(def Points "P"
{
    point3f[] points = [(-1, 0, 0), (1, 0, 0)]
    float[] widths = [0.5]
    texCoord2f[] primvars:st = [(0.75, 0.5), (0.25, 0.5)] (interpolation = "vertex")
    rel material:binding = </Looks/M>
}
)" + looks("st", halves()));
    ASSERT_EQ(p.result.scene.points.size(), 1u);
    render::RenderScene scene(p.result.scene);
    expectColour(colourAt(scene, -1.0f, 0.0f), RGB(4.0f), "first point");
    expectColour(colourAt(scene, 1.0f, 0.0f), RGB(0, 0.5f, 0), "second point");
}

TEST(CurvePrimvars, APrimvarOfTheWrongLengthIsIgnoredWithAWarningNamingThePrim) {
    // Three vertex values for four vertices, two uniform values for one curve on the points.
    auto p = populate(curves("linear", "bezier", R"(    int[] curveVertexCounts = [4]
    point3f[] points = [(-2, 0, 0), (-1, 0, 0), (1, 0, 0), (2, 0, 0)]
    float3[] primvars:tint = [(1, 0, 0), (0, 1, 0), (0, 0, 1)] (interpolation = "vertex")
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0)] (interpolation = "varying")
)",
                             true) +
                      R"(def Points "P"
{
    point3f[] points = [(-1, 2, 0), (0, 2, 0), (1, 2, 0)]
    float[] widths = [0.5]
    float3[] primvars:tint = [(1, 0, 0), (0, 1, 0)] (interpolation = "vertex")
    rel material:binding = </Looks/M>
}
)" + looks("tint"));
    ASSERT_EQ(p.result.scene.curves.size(), 1u);
    ASSERT_EQ(p.result.scene.points.size(), 1u);
    for (const std::string& w : p.warnings) std::printf("[ warning  ] %s\n", w.c_str());
    ASSERT_EQ(p.warnings.size(), 3u);
    EXPECT_NE(p.warnings[0].find("/C"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("displayColor"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[1].find("/C"), std::string::npos) << p.warnings[1];
    EXPECT_NE(p.warnings[1].find("tint"), std::string::npos) << p.warnings[1];
    EXPECT_NE(p.warnings[2].find("/P"), std::string::npos) << p.warnings[2];
    EXPECT_NE(p.warnings[2].find("tint"), std::string::npos) << p.warnings[2];
    render::RenderScene scene(p.result.scene);
    for (const float x : {-1.5f, 0.0f, 1.5f}) expectColour(colourAt(scene, x, 0.0f), kFallback, "curve");
    for (const float x : {-1.0f, 0.0f, 1.0f}) expectColour(colourAt(scene, x, 2.0f), kFallback, "point");
}

}  // namespace
}  // namespace fluence::delegate
