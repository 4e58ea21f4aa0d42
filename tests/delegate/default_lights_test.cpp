// The default lights of a scene in which nothing emits (delegate/default_lights.h): when they are
// added, what they are, and the default camera's framing that ignores lights' extents.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "delegate/camera_adapter.h"
#include "delegate/default_lights.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::Populated;
using testing::stageFrom;

// Populates `usda` as the render command does: default lights on unless `defaultLight` is false.
Populated populateWithDefaultLight(const std::string& usda, bool defaultLight = true) {
    Populated p;
    p.stage = stageFrom(usda);
    DelegateOptions options;
    options.defaultLight = defaultLight;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&p](const std::string& path, const std::string& message) {
        p.warnings.push_back(path + ": " + message);
    };
    p.result = populateScene(*p.stage, options);
    return p;
}

std::size_t defaultLightWarnings(const Populated& p) {
    return static_cast<std::size_t>(std::count_if(p.warnings.begin(), p.warnings.end(), [](const std::string& w) {
        return w.find("nothing in the scene emits light") != std::string::npos;
    }));
}

const std::string kCube = "def Cube \"Box\"\n{\n    double size = 0.03\n}\n";
const std::string kTurnedCamera = R"(
def Camera "Cam"
{
    double3 xformOp:rotateXYZ = (0, 90, 0)
    double3 xformOp:translate = (5, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
}
)";

TEST(DefaultLights, UnlitSceneGetsAKeyLightAlongTheViewAndADimDome) {
    const Populated p = populateWithDefaultLight(kTurnedCamera + kCube);
    const std::vector<render::LightDesc>& lights = p.result.scene.lights;
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_EQ(defaultLightWarnings(p), 1u);
    const render::LightDesc& key = lights[0];
    EXPECT_EQ(key.type, render::LightType::Distant);
    EXPECT_EQ(key.angleDegrees, 0.0f);
    EXPECT_EQ(key.radiance, RGB(kDefaultKeyIrradiance));
    // The camera at +X looks down -X; the light travels the same way (emits along its local -Z).
    const Vec3d travel = normalize(key.transform.transformVector(Vec3d(0.0, 0.0, -1.0)));
    EXPECT_NEAR(travel.x, -1.0, 1e-9);
    const Vec3d view = normalize(p.result.scene.camera->transform.transformVector(Vec3d(0.0, 0.0, -1.0)));
    EXPECT_NEAR(dot(travel, view), 1.0, 1e-12);
    EXPECT_EQ(lights[1].type, render::LightType::Dome);
    EXPECT_EQ(lights[1].radiance, RGB(kDefaultDomeRadiance));
    EXPECT_EQ(lights[1].texture, nullptr);
    EXPECT_FALSE(lights[1].visibleToCamera);  // lights the scene, not the background
}

TEST(DefaultLights, OffByOptionOrRenderSettings) {
    const Populated off = populateWithDefaultLight(kTurnedCamera + kCube, false);
    EXPECT_TRUE(off.result.scene.lights.empty());
    EXPECT_EQ(defaultLightWarnings(off), 0u);
    const Populated settings = populateWithDefaultLight(
        "#usda 1.0\n(\n    renderSettingsPrimPath = \"/Settings\"\n)\n" + kTurnedCamera + kCube +
        "def RenderSettings \"Settings\"\n{\n    bool fluence:defaultLight = false\n}\n");
    EXPECT_TRUE(settings.result.scene.lights.empty());
    EXPECT_EQ(defaultLightWarnings(settings), 0u);
}

TEST(DefaultLights, NotAddedWhenALightOrAnEmissiveSurfaceIsThere) {
    const Populated lit = populateWithDefaultLight(kTurnedCamera + kCube + "def SphereLight \"Bulb\"\n{\n}\n");
    ASSERT_EQ(lit.result.scene.lights.size(), 1u);
    EXPECT_EQ(lit.result.scene.lights[0].name, "/Bulb");
    EXPECT_EQ(defaultLightWarnings(lit), 0u);
    const Populated glowing = populateWithDefaultLight(kTurnedCamera + testing::quadBoundTo(R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:emissiveColor = (0.2, 0.1, 0)
            token outputs:surface
        }
)"));
    EXPECT_TRUE(glowing.result.scene.lights.empty());
    EXPECT_EQ(defaultLightWarnings(glowing), 0u);
}

TEST(DefaultLights, EmitsLightSeesEmissiveMaterialsPrototypesAndVolumes) {
    render::SceneDescription scene;
    EXPECT_FALSE(emitsLight(scene));
    scene.materials.resize(3);  // 0 grey; 1 emission driven by a texture; 2 constant emission
    render::InputBinding emission;
    emission.input = render::MaterialInput::Emission;
    scene.materials[1].bindings.push_back(emission);
    scene.materials[2].emission = RGB(0.0f, 0.0f, 0.5f);
    render::MeshDesc grey;
    grey.material = 0;
    scene.meshes.push_back(grey);
    EXPECT_FALSE(emitsLight(scene));
    render::MeshDesc textured = grey, glowing = grey;
    textured.material = 1;
    glowing.material = 2;
    scene.prototypes.push_back({"/Textured", {textured}});
    EXPECT_TRUE(emitsLight(scene));
    scene.prototypes.clear();
    scene.meshes.push_back(glowing);
    EXPECT_TRUE(emitsLight(scene));
    scene.meshes.pop_back();

    render::VolumeDesc smoke;
    smoke.params.blackbodyIntensity = 1.0f;  // without a temperature grid: no blackbody emission
    scene.volumes.push_back(smoke);
    EXPECT_FALSE(emitsLight(scene));
    scene.volumes[0].temperature = render::VolumeFieldDesc{"fire.vdb", "temperature", -1};
    EXPECT_TRUE(emitsLight(scene));
    scene.volumes[0] = smoke;
    scene.volumes[0].params.emissionScale = 2.0f;
    EXPECT_TRUE(emitsLight(scene));
    scene.volumes[0].params.emissionColor = RGB(0.0f);
    EXPECT_FALSE(emitsLight(scene));
}

// A 3 cm cube and a 5-unit rect light beside it, no camera: the default camera frames the cube
// (lights' extents do not count), and the default lights are not added (the scene has a light).
TEST(DefaultCameraFraming, IgnoresLightsExtents) {
    const Populated p = populateWithDefaultLight(kCube + R"(
def RectLight "Panel"
{
    float inputs:width = 5
    float inputs:height = 5
    double3 xformOp:translate = (10, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)");
    ASSERT_TRUE(p.result.cameraPath.empty());
    ASSERT_TRUE(p.result.scene.camera);
    const Vec3d position = p.result.scene.camera->transform.transformPoint(Vec3d(0.0));
    // The cube's bounding sphere, radius 0.015 sqrt(3), fills the narrower field of view.
    const render::CameraDesc lens;
    const double halfAngle = std::atan(0.5 * lens.verticalAperture / lens.focalLength);
    EXPECT_NEAR(position.z, 0.015 * std::sqrt(3.0) / std::sin(halfAngle), 1e-4);
    EXPECT_NEAR(position.x, 0.0, 1e-9);
    EXPECT_NEAR(position.y, 0.0, 1e-9);
    ASSERT_EQ(p.result.scene.lights.size(), 1u);
    EXPECT_EQ(defaultLightWarnings(p), 0u);
}

// A Catmull-Clark cube, no camera: the default camera frames its limit surface (the bounding
// sphere of the diced surface's bounds fills the narrower field of view, within 2%), from a uniform
// refinement rather than a dicing for a provisional camera.
TEST(DefaultCameraFraming, FramesSubdivisionSurfacesByTheirLimitSurface) {
    const Populated p = populateWithDefaultLight(R"(
def Mesh "Box"
{
    int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
    int[] faceVertexIndices = [0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4]
    point3f[] points = [(-1, -1, 1), (1, -1, 1), (-1, 1, 1), (1, 1, 1), (-1, 1, -1), (1, 1, -1), (-1, -1, -1), (1, -1, -1)]
}
)");
    const render::MeshDesc* limit = p.mesh("/Box");
    ASSERT_NE(limit, nullptr);
    EXPECT_GT(limit->indices.size(), 6u * 2u * 16u) << "diced for the final camera";
    float extent = 0.0f;
    for (const Vec3f& point : limit->positions)
        extent = std::max({extent, std::abs(point.x), std::abs(point.y), std::abs(point.z)});
    const render::CameraDesc lens;
    const double framedRadius = p.result.scene.camera->transform.transformPoint(Vec3d(0.0)).z *
                                std::sin(std::atan(0.5 * lens.verticalAperture / lens.focalLength));
    EXPECT_NEAR(framedRadius / (std::sqrt(3.0) * extent), 1.0, 0.02);
}

}  // namespace
}  // namespace fluence::delegate
