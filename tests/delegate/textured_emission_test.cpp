// Emission driven by nodes, from USD to the render core: UsdPreviewSurface emissiveColor and
// Standard Surface emission_color (times emission) connected to a UsdUVTexture or to a primvar
// reader of displayColor, on a polygon mesh and on a subdivision surface. The binding reaches the
// material (no longer dropped), and rays that hit the mesh see the driven emission where they hit.
#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::delegate {
namespace {

// Two unit quads side by side, x in [0, 2], y in [0, 1], st = (x / 2, y), displayColor red on the
// left face and blue (3) on the right, bound to /Looks/M whose body is `material`.
std::string screen(const std::string& material, const std::string& scheme = "none") {
    return R"(
def Mesh "Screen"
{
    uniform token subdivisionScheme = ")" +
           scheme + R"("
    int[] faceVertexCounts = [4, 4]
    int[] faceVertexIndices = [0, 1, 4, 3, 1, 2, 5, 4]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0)]
    texCoord2f[] primvars:st = [(0, 0), (0.5, 0), (1, 0), (0, 1), (0.5, 1), (1, 1)] (interpolation = "vertex")
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 0, 3)] (interpolation = "uniform")
    rel material:binding = </Looks/M>
}
def Scope "Looks"
{
    def Material "M"
    {
)" + material +
           R"(
    }
}
)";
}

// A UsdUVTexture of `file` reading st, and the UsdPreviewSurface or Standard Surface (`surface`,
// with `inputs` authored) whose `input` it drives.
std::string texturedSurface(const std::string& file, const std::string& id, const std::string& input,
                            const std::string& inputs = "") {
    return R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = ")" +
           id + R"("
            color3f inputs:)" +
           input + R"(.connect = </Looks/M/Tex.outputs:rgb>
)" + inputs +
           R"(
            token outputs:surface
        }
        )" +
           testing::rawTextureAtSt(file) + R"(        def Shader "St"
        {
            uniform token info:id = "UsdPrimvarReader_float2"
            string inputs:varname = "st"
            float2 outputs:result
        }
)";
}

// The emission a ray straight down at (x, y) finds.
RGB emissionAt(const render::RenderScene& scene, float x, float y) {
    std::optional<render::SurfaceHit> hit = scene.intersect(render::Ray{{x, y, 1.0f}, {0.0f, 0.0f, -1.0f}});
    EXPECT_TRUE(hit);
    return hit ? hit->emission : RGB(-1.0f);
}

class TexturedEmissionFromUsd : public ::testing::Test {
protected:
    std::string halves() { return test::writeHalvesTexture(dir.file("halves.exr")); }
    test::TempDir dir{"fluence_textured_emission_usd"};
};

TEST_F(TexturedEmissionFromUsd, PreviewSurfaceEmissiveColorFromATextureOnPolygonsAndSubdivisionSurfaces) {
    for (const std::string scheme : {"none", "catmullClark"}) {
        testing::Populated p =
            testing::populate(screen(texturedSurface(halves(), "UsdPreviewSurface", "emissiveColor"), scheme));
        EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
        render::RenderScene scene(p.result.scene);
        EXPECT_GT(scene.stats().emissiveTriangles, 0u) << scheme;
        // At the texel centres s = 1/4 and 3/4 (the limit surface's st is x / 2 too, up to rounding).
        EXPECT_LT(length(emissionAt(scene, 0.5f, 0.5f) - RGB(0, 0.5f, 0)), 1e-3f) << scheme;
        EXPECT_LT(length(emissionAt(scene, 1.5f, 0.5f) - RGB(4.0f)), 1e-3f) << scheme;
    }
}

TEST_F(TexturedEmissionFromUsd, StandardSurfaceEmissionColorFromATextureTimesEmission) {
    testing::Populated p = testing::populate(screen(texturedSurface(
        halves(), "ND_standard_surface_surfaceshader", "emission_color", "            float inputs:emission = 2\n")));
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
    render::RenderScene scene(p.result.scene);
    EXPECT_EQ(emissionAt(scene, 0.5f, 0.5f), RGB(0, 1, 0));
    EXPECT_EQ(emissionAt(scene, 1.5f, 0.5f), RGB(8.0f));
}

TEST_F(TexturedEmissionFromUsd, EmissiveColorFromDisplayColorPerFace) {
    testing::Populated p = testing::populate(screen(R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:emissiveColor.connect = </Looks/M/Colour.outputs:result>
            token outputs:surface
        }
        def Shader "Colour"
        {
            uniform token info:id = "UsdPrimvarReader_float3"
            string inputs:varname = "displayColor"
            float3 outputs:result
        }
)"));
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
    render::RenderScene scene(p.result.scene);
    EXPECT_EQ(emissionAt(scene, 0.3f, 0.6f), RGB(1, 0, 0));
    EXPECT_EQ(emissionAt(scene, 1.7f, 0.2f), RGB(0, 0, 3));
    // The light selection by power chooses the blue face's triangles three times as often.
    ASSERT_EQ(scene.lightCount(), 4u);
    const float red = scene.lightSelection().pmf(0) + scene.lightSelection().pmf(1);
    const float blue = scene.lightSelection().pmf(2) + scene.lightSelection().pmf(3);
    EXPECT_NEAR(blue / red, luminance(RGB(0, 0, 3)) / luminance(RGB(1, 0, 0)), 1e-4f);
}

}  // namespace
}  // namespace fluence::delegate
