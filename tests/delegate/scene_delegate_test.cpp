#include "delegate/scene_delegate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "delegate/xform.h"
#include "scene/usda_parser.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::kCamera;
using testing::populate;
using testing::populateStrict;

void expectNear(const Vec3f& a, const Vec3f& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(SceneDelegate, ComposesXformOpsInUsdOrder) {
    // translate then rotate then scale in xformOpOrder: points are scaled, rotated, translated.
    auto p = populate(R"(
def Xform "Parent"
{
    double3 xformOp:translate = (10, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Mesh "Tri"
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(1, 0, 0), (0, 1, 0), (0, 0, 1)]
        double3 xformOp:translate = (0, 5, 0)
        float xformOp:rotateZ = 90
        float3 xformOp:scale = (2, 2, 2)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateZ", "xformOp:scale"]
    }
}
)");
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    const auto& pts = p.result.scene.meshes[0].positions;
    expectNear(pts[0], Vec3f(10, 7, 0));  // (1,0,0) -> scale (2,0,0) -> rotZ (0,2,0) -> +(10,5,0)
    expectNear(pts[1], Vec3f(8, 5, 0));   // (0,1,0) -> (0,2,0) -> (-2,0,0) -> (8,5,0)
    expectNear(pts[2], Vec3f(10, 5, 2));
}

TEST(SceneDelegate, ResetXformStackAndInvertedOps) {
    auto p = populate(R"(
def Xform "Parent"
{
    double3 xformOp:translate = (100, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Mesh "Tri"
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
        double3 xformOp:translate:pivot = (1, 1, 0)
        float xformOp:rotateZ = 180
        uniform token[] xformOpOrder = ["!resetXformStack!", "xformOp:translate:pivot", "xformOp:rotateZ", "!invert!xformOp:translate:pivot"]
    }
}
)");
    const auto& pts = p.result.scene.meshes[0].positions;
    expectNear(pts[0], Vec3f(2, 2, 0));  // rotated 180 degrees about the pivot (1,1)
    expectNear(pts[1], Vec3f(1, 2, 0));
}

TEST(SceneDelegate, TriangulatesPolygonsAndReadsPrimvarsByInterpolation) {
    auto p = populate(R"(
def Mesh "Quad"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4, 3]
    int[] faceVertexIndices = [0, 1, 2, 3, 0, 2, 4]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 2, 0)]
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0)] (
        interpolation = "uniform"
    )
    normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1)] (
        interpolation = "faceVarying"
    )
}
)");
    const auto& m = p.result.scene.meshes[0];
    ASSERT_EQ(m.indices.size(), 9u);  // quad -> 2 triangles, triangle -> 1
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 2, 4}));
    ASSERT_EQ(m.cornerColors.size(), 9u);
    EXPECT_EQ(m.cornerColors[0], RGB(1, 0, 0));
    EXPECT_EQ(m.cornerColors[8], RGB(0, 1, 0));
    ASSERT_EQ(m.cornerNormals.size(), 9u);
}

TEST(SceneDelegate, IndexedPrimvarsAndLeftHandedOrientation) {
    auto p = populate(R"(
def Mesh "Tri"
{
    uniform token subdivisionScheme = "none"
    uniform token orientation = "leftHanded"
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    color3f[] primvars:displayColor = [(0.1, 0.2, 0.3), (0.9, 0.8, 0.7)] (
        interpolation = "vertex"
    )
    int[] primvars:displayColor:indices = [1, 1, 0]
}
)");
    const auto& m = p.result.scene.meshes[0];
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 2, 1}));
    EXPECT_NEAR(m.cornerColors[1].x, 0.1f, 1e-6f);  // corner 1 is point 2 -> index 0
    EXPECT_NEAR(m.cornerColors[0].x, 0.9f, 1e-6f);
}

TEST(SceneDelegate, TopologyErrorsNameThePrim) {
    const std::string bad = R"(
def Mesh "Broken"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
}
)";
    try {
        populateStrict(bad);
        FAIL() << "expected SceneError";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("/Broken"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("add up to 4"), std::string::npos) << e.what();
    }
}

TEST(SceneDelegate, UsdLuxUnitsAndFallbacks) {
    auto p = populate(R"(
def RectLight "Rect"
{
    float inputs:intensity = 2
    float inputs:exposure = 3
    color3f inputs:color = (1, 0.5, 0.25)
    float inputs:width = 4
    bool inputs:normalize = true
}
def DistantLight "Sun"
{
}
def SphereLight "OldStyle"
{
    float intensity = 7
    float radius = 2
}
def DomeLight "Dome"
{
}
)");
    const auto& lights = p.result.scene.lights;
    ASSERT_EQ(lights.size(), 4u);
    EXPECT_EQ(lights[0].radiance, RGB(16, 8, 4));  // 2 * 2^3 * colour
    EXPECT_TRUE(lights[0].normalize);
    EXPECT_EQ(lights[0].width, 4.0f);
    EXPECT_EQ(lights[0].height, 1.0f);
    EXPECT_EQ(lights[1].radiance, RGB(50000.0f));  // DistantLight's intensity fallback
    EXPECT_FLOAT_EQ(lights[1].angleDegrees, 0.53f);
    EXPECT_EQ(lights[2].radiance, RGB(7.0f));  // pre-21.05 attribute names
    EXPECT_EQ(lights[2].radius, 2.0f);
    EXPECT_EQ(lights[3].type, render::LightType::Dome);
}

TEST(SceneDelegate, MaterialBindingInheritanceAndStrength) {
    auto p = populate(R"(
def Scope "Looks"
{
    def Material "Red"
    {
        token outputs:surface.connect = </Looks/Red/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (1, 0, 0)
            color3f inputs:emissiveColor = (0, 0, 2)
        }
    }
    def Material "Blue"
    {
        color3f inputs:tint = (0, 0, 1)
        token outputs:surface.connect = </Looks/Blue/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = </Looks/Blue.inputs:tint>
        }
    }
}
def Xform "Group"
{
    rel material:binding = </Looks/Red>
    def Mesh "Inherits"
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    }
    def Mesh "Own"
    {
        uniform token subdivisionScheme = "none"
        rel material:binding = </Looks/Blue>
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    }
}
def Xform "Strong"
{
    rel material:binding = </Looks/Red> (
        bindMaterialAs = "strongerThanDescendants"
    )
    def Mesh "Overridden"
    {
        uniform token subdivisionScheme = "none"
        rel material:binding = </Looks/Blue>
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    }
}
)");
    const auto& s = p.result.scene;
    ASSERT_EQ(s.meshes.size(), 3u);
    auto materialOf = [&](int mesh) { return s.materials[s.meshes[mesh].material]; };
    EXPECT_EQ(materialOf(0).name, "/Looks/Red");
    EXPECT_EQ(materialOf(0).diffuse, RGB(1, 0, 0));
    EXPECT_EQ(materialOf(0).emission, RGB(0, 0, 2));
    EXPECT_EQ(materialOf(1).name, "/Looks/Blue");
    EXPECT_EQ(materialOf(1).diffuse, RGB(0, 0, 1)) << "connected to the material's interface input";
    EXPECT_EQ(materialOf(2).name, "/Looks/Red") << "strongerThanDescendants wins";
}

TEST(SceneDelegate, SkipsInvisibleGuidesAndWarnsOncePerUnsupportedType) {
    auto p = populate(R"(
def Hypersphere "A"
{
}
def Hypersphere "B"
{
}
def Mesh "Hidden"
{
    uniform token subdivisionScheme = "none"
    token visibility = "invisible"
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
}
def Mesh "Guide"
{
    uniform token subdivisionScheme = "none"
    uniform token purpose = "guide"
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
}
over "NotDefined"
{
    def Mesh "Child"
    {
        uniform token subdivisionScheme = "none"
    }
}
)");
    EXPECT_TRUE(p.result.scene.meshes.empty());
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("'Hypersphere' is not supported yet; skipped 2 prims"), std::string::npos)
        << p.warnings[0];
}

// UsdLux MeshLightAPI (delegate/mesh_light.h) is read on a mesh of its own and, inside a native
// instance, into the prototype's mesh, named by the instance's path, with no warning.
TEST(SceneDelegate, MeshLightApiInsideAnInstanceIsReadIntoThePrototype) {
    const std::string tri = R"( (
    prepend apiSchemas = ["MeshLightAPI"]
)
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
}
)";
    auto p = populate("#usda 1.0\n" + kCamera + "def Mesh \"A\"" + tri + "def Xform \"P\"\n{\ndef Mesh \"B\"" + tri +
                      "}\ndef Xform \"I\" (\n    instanceable = true\n    references = </P>\n)\n{\n}\n");
    ASSERT_TRUE(p.mesh("/A") && p.mesh("/P/B"));
    EXPECT_TRUE(p.mesh("/A")->light && p.mesh("/P/B")->light);
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
    ASSERT_EQ(p.result.scene.prototypes.size(), 1u);
    ASSERT_EQ(p.result.scene.prototypes[0].meshes.size(), 1u);
    const render::MeshDesc& instanced = p.result.scene.prototypes[0].meshes[0];
    ASSERT_TRUE(instanced.light) << "the instance's mesh emits (UsdLuxMeshLight.* check its light)";
    EXPECT_EQ(instanced.light->prim, "/I/B");
}

TEST(SceneDelegate, AuthoredColoursGoThroughTheColourConverterWithTheirColourSpace) {
    auto stage = std::make_unique<usd::Stage>(usd::parseUsdaString(R"(#usda 1.0
def Camera "Cam"
{
}
def Mesh "Tri"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    color3f[] primvars:displayColor = [(0.5, 0.5, 0.5)] (
        colorSpace = "srgb_texture"
    )
}
)",
                                                                   "c.usda"));
    std::vector<std::string> spaces;
    DelegateOptions options;
    options.convertColor = [&](const RGB& c, const std::string& space) {
        spaces.push_back(space);
        return c * 2.0f;
    };
    options.warn = [](const std::string&, const std::string&) {};
    DelegateResult result = populateScene(*stage, options);
    ASSERT_FALSE(spaces.empty());
    EXPECT_EQ(spaces.front(), "srgb_texture");
    EXPECT_EQ(result.scene.meshes[0].cornerColors[0], RGB(1.0f)) << "the converted value is what renders";
}

TEST(SceneDelegate, CameraSelectionAndRenderSettings) {
    auto p = populate(R"(#usda 1.0
(
    renderSettingsPrimPath = "/Render/Settings"
)
def Camera "First"
{
}
def Camera "Second"
{
    float focalLength = 35
    float2 clippingRange = (0.5, 500)
}
def Scope "Render"
{
    def RenderSettings "Settings"
    {
        rel camera = </Second>
        uniform int2 resolution = (320, 200)
    }
}
)");
    EXPECT_EQ(p.result.cameraPath, "/Second");
    EXPECT_FLOAT_EQ(p.result.scene.camera->focalLength, 35.0f);
    EXPECT_FLOAT_EQ(p.result.scene.camera->nearClip, 0.5f);
    ASSERT_TRUE(p.result.renderSettings);
    EXPECT_EQ(p.result.renderSettings->resolution, std::make_pair(320, 200));
    EXPECT_EQ(populate("#usda 1.0\n" + kCamera + "def Camera \"Other\"\n{\n}\n", "/Other").result.cameraPath, "/Other");
    EXPECT_THROW(populate("#usda 1.0\n" + kCamera, "/Missing"), SceneError);
    auto framed = populate("#usda 1.0\ndef Xform \"X\"\n{\n}\n");
    EXPECT_EQ(framed.result.cameraPath, "") << "no camera: a default one frames the scene";
    EXPECT_TRUE(framed.result.scene.camera);
}

TEST(SceneDelegate, RenderSettingsNameTheIntegrator) {
    const std::string settings = R"(#usda 1.0
(
    renderSettingsPrimPath = "/Render/Settings"
)
def Scope "Render"
{
    def RenderSettings "Settings"
    {
        INTEGRATOR
    }
}
)";
    auto withIntegrator = [&](const std::string& attribute) {
        std::string text = settings;
        text.replace(text.find("INTEGRATOR"), 10, attribute);
        return populate(text).result.renderSettings->integrator;
    };
    EXPECT_EQ(withIntegrator("uniform token fluence:integrator = \"bdpt\""), "bdpt");
    EXPECT_EQ(withIntegrator(""), "") << "not authored: the command line's choice";
    EXPECT_THROW(withIntegrator("uniform int fluence:integrator = 3"), SceneError);
}

TEST(SceneDelegate, TheRenderedProductsCameraOverridesTheSettingsCamera) {
    auto p = populate(R"(#usda 1.0
(
    renderSettingsPrimPath = "/Render/Settings"
)
def Camera "Wide"
{
}
def Camera "Close"
{
    float focalLength = 85
}
def Scope "Render"
{
    def RenderSettings "Settings"
    {
        rel camera = </Wide>
        rel products = </Render/Product>
    }
    def RenderProduct "Product"
    {
        rel camera = </Close>
        token productName = "close.exr"
    }
}
)");
    EXPECT_EQ(p.result.cameraPath, "/Close");
    EXPECT_FLOAT_EQ(p.result.scene.camera->focalLength, 85.0f);
}

TEST(SceneDelegate, RenderSettingsFramingAndItsProductOverride) {
    const std::string scene = R"(#usda 1.0
(
    renderSettingsPrimPath = "/Render/Settings"
)
def Camera "Cam"
{
}
def Scope "Render"
{
    def RenderSettings "Settings"
    {
        float pixelAspectRatio = 2
        token aspectRatioConformPolicy = "cropAperture"
        rel products = </Render/Product>
    }
    def RenderProduct "Product"
    {
        token aspectRatioConformPolicy = "POLICY"
    }
}
)";
    auto p = populate(std::regex_replace(scene, std::regex("POLICY"), "adjustPixelAspectRatio"));
    const render::ImageFraming& settings = p.result.renderSettings->framing;
    EXPECT_FLOAT_EQ(settings.pixelAspectRatio, 2.0f);
    EXPECT_EQ(settings.conform, render::ApertureConform::CropAperture);
    const render::ImageFraming& product = p.result.renderSettings->renderedFraming();
    EXPECT_FLOAT_EQ(product.pixelAspectRatio, 2.0f) << "inherited from the settings";
    EXPECT_EQ(product.conform, render::ApertureConform::AdjustPixelAspectRatio);
    try {
        populate(std::regex_replace(scene, std::regex("POLICY"), "squash"));
        FAIL() << "an unknown policy was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("/Render/Product"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'squash' is not one of"), std::string::npos) << e.what();
    }
}

TEST(SceneDelegate, TimeSamplesAreInterpolated) {
    auto stage = std::make_unique<usd::Stage>(usd::parseUsdaString(R"(#usda 1.0
def Xform "X"
{
    double3 xformOp:translate.timeSamples = {
        1: (0, 0, 0),
        3: (4, 0, 0),
    }
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)",
                                                                   "t.usda"));
    const usd::PrimSpec* x = stage->prim("/X");
    ASSERT_NE(x, nullptr);
    const auto noWarning = [](const std::string& message) { ADD_FAILURE() << message; };
    EXPECT_NEAR(localTransform(PrimReader(*x, 2.0), noWarning).matrix.m[0][3], 2.0, 1e-12);
    EXPECT_NEAR(localTransform(PrimReader(*x, 0.0), noWarning).matrix.m[0][3], 0.0, 1e-12);  // held before the first
    EXPECT_NEAR(localTransform(PrimReader(*x, 9.0), noWarning).matrix.m[0][3], 4.0, 1e-12);  // and after the last
}

// No frame asked for and no startTimeCode (OpenUSD's UsdImagingGL renders at EarliestTime then):
// an attribute with only time samples gives its earliest sample, not "no value".
TEST(SceneDelegate, WithoutAFrameTimeSampledAttributesGiveTheirEarliestSample) {
    const std::string scene = R"(
def Xform "X"
{
    double3 xformOp:translate.timeSamples = {
        5: (0, 0, 9),
        2: (1, 2, 3),
    }
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Mesh "Quad"
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
        float3 xformOp:scale = (1, 1, 1)
        float3 xformOp:scale.timeSamples = {
            7: (2, 2, 2),
            3: (3, 3, 3),
        }
        uniform token[] xformOpOrder = ["xformOp:scale"]
    }
}
)";
    testing::Populated p = populate(scene);
    EXPECT_TRUE(p.warnings.empty()) << p.warnings[0];
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    // The earliest samples: translate (1, 2, 3) at 2, and scale 3 at 3 (as Hydra, over the default (1, 1, 1)).
    const std::vector<Vec3f>& positions = p.result.scene.meshes[0].positions;
    ASSERT_EQ(positions.size(), 4u);
    EXPECT_EQ(positions[0], Vec3f(1, 2, 3));
    EXPECT_EQ(positions[2], Vec3f(4, 5, 3));
    const usd::PrimSpec* x = p.stage->prim("/X");
    const auto noWarning = [](const std::string& message) { ADD_FAILURE() << message; };
    EXPECT_NEAR(localTransform(PrimReader(*x, usd::kDefaultTime), noWarning).matrix.m[2][3], 3.0, 1e-12);
    EXPECT_NEAR(localTransform(PrimReader(*x, 5.0), noWarning).matrix.m[2][3], 9.0, 1e-12)
        << "a frame still reads its own time";
}

}  // namespace
}  // namespace fluence::delegate
