// UsdLux lights read by delegate/light_adapter: the new light types and their attributes (2021+
// and legacy names), colour temperature, ShapingAPI, dome and rect textures with their warnings,
// and DomeLight_1's pole axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "core/blackbody.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::delegate {
namespace {

using testing::populate;

const render::LightDesc& light(const testing::Populated& p, const std::string& name) {
    for (const auto& l : p.result.scene.lights)
        if (l.name == name) return l;
    throw std::runtime_error("no light " + name);
}

bool warned(const testing::Populated& p, const std::string& text) {
    return std::any_of(p.warnings.begin(), p.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(LightAdapter, DiskCylinderAndTheirPointAndLineForms) {
    auto p = populate(R"(
def DiskLight "Disk"
{
    float inputs:radius = 0.3
}
def CylinderLight "Tube"
{
    float inputs:length = 3
    float inputs:radius = 0.2
}
def CylinderLight "OldTube"
{
    float length = 2
    float radius = 0.1
    bool treatAsLine = true
}
def SphereLight "Bulb"
{
    bool treatAsPoint = true
}
def SphereLight "Dot"
{
    float inputs:radius = 0
    bool inputs:normalize = true
}
def SphereLight "Nothing"
{
    float inputs:radius = 0
}
)");
    EXPECT_EQ(light(p, "/Disk").type, render::LightType::Disk);
    EXPECT_FLOAT_EQ(light(p, "/Disk").radius, 0.3f);
    EXPECT_EQ(light(p, "/Tube").type, render::LightType::Cylinder);
    EXPECT_FLOAT_EQ(light(p, "/Tube").length, 3.0f);
    EXPECT_FLOAT_EQ(light(p, "/Tube").radius, 0.2f);
    EXPECT_FALSE(light(p, "/Tube").treatAsLine);
    EXPECT_FLOAT_EQ(light(p, "/OldTube").length, 2.0f);
    EXPECT_TRUE(light(p, "/OldTube").treatAsLine);
    EXPECT_TRUE(light(p, "/Bulb").treatAsPoint);
    EXPECT_FLOAT_EQ(light(p, "/Bulb").radius, 0.5f);
    EXPECT_TRUE(light(p, "/Dot").treatAsPoint) << "a normalized sphere of radius 0 is a point light";
    EXPECT_EQ(p.result.scene.lights.size(), 5u);
    EXPECT_TRUE(warned(p, "/Nothing: a SphereLight of radius 0 emits nothing unless inputs:normalize is on"));
}

TEST(LightAdapter, ColourTemperatureTintsWithTheBlackbody) {
    auto p = populate(R"(
def RectLight "Warm"
{
    float inputs:intensity = 2
    bool inputs:enableColorTemperature = true
    float inputs:colorTemperature = 3000
}
def RectLight "TooCold"
{
    bool enableColorTemperature = true
    float colorTemperature = 500
}
def RectLight "Off"
{
    float inputs:colorTemperature = 3000
}
)");
    // UsdLux (OpenUSD PR 3182): the blackbody colour relative to 6500 K's, which is white, at
    // luminance 1.
    auto tint = [](double kelvin) {
        RGB ratio = blackbodyRgb(kelvin) / blackbodyRgb(6500.0);
        return ratio / luminance(ratio);
    };
    RGB warm = tint(3000.0) * 2.0f;
    EXPECT_NEAR(light(p, "/Warm").radiance.x, warm.x, 1e-5f);
    EXPECT_NEAR(light(p, "/Warm").radiance.z, warm.z, 1e-5f);
    EXPECT_GT(warm.x, warm.z);
    EXPECT_NEAR(light(p, "/TooCold").radiance.x, tint(1000.0).x, 1e-5f);
    EXPECT_TRUE(warned(p, "/TooCold: colorTemperature 500"));
    EXPECT_EQ(light(p, "/Off").radiance, RGB(1.0f)) << "only with enableColorTemperature";
}

// An input connected to a shader Fluence does not evaluate (an Arnold light shader here) keeps its
// own value, or UsdLux's fallback, with a warning naming the light, the input and the source: the
// light is never black (as in Storm, which reads the attribute's value).
TEST(LightAdapter, InputConnectedToAnUnknownShaderUsesItsOwnValue) {
    auto p = populate(R"(
def RectLight "Authored"
{
    color3f inputs:color = (0.5, 0.25, 1)
    color3f inputs:color.connect = </Tint.outputs:out>
    float inputs:intensity = 4
}
def RectLight "Unauthored"
{
    color3f inputs:color.connect = </Tint.outputs:out>
}
def Shader "Tint"
{
    uniform token info:id = "arnold:color_correct"
    color3f inputs:multiply = (5, 0, 0)
    color4f outputs:out
}
)");
    EXPECT_EQ(light(p, "/Authored").radiance, RGB(2.0f, 1.0f, 4.0f));
    EXPECT_EQ(light(p, "/Unauthored").radiance, RGB(1.0f));
    for (const char* name : {"/Authored", "/Unauthored"})
        EXPECT_TRUE(warned(p, std::string(name) +
                                  ": inputs:color is connected to </Tint.outputs:out>, a light shader Fluence "
                                  "does not evaluate; the input's own value is used"))
            << name;
    EXPECT_EQ(std::count_if(p.warnings.begin(), p.warnings.end(),
                            [](const std::string& w) { return w.find("is connected to") != std::string::npos; }),
              2);
}

TEST(LightAdapter, ShapingApiIsReadOnAreaLights) {
    auto p = populate(R"(
def RectLight "Applied" (
    prepend apiSchemas = ["ShapingAPI"]
)
{
}
def DiskLight "Spot"
{
    float inputs:shaping:cone:angle = 30
    float inputs:shaping:cone:softness = 0.2
    float inputs:shaping:focus = 4
    color3f inputs:shaping:focusTint = (0.1, 0.2, 0.3)
}
def SphereLight "Legacy"
{
    float shaping:cone:angle = 45
}
def SphereLight "Plain"
{
}
def DomeLight "Dome" (
    prepend apiSchemas = ["ShapingAPI"]
)
{
    asset inputs:shaping:ies:file = @lamp.ies@
}
)");
    ASSERT_TRUE(light(p, "/Applied").shaping);
    EXPECT_EQ(light(p, "/Applied").shaping->coneAngleDegrees, 90.0f);
    const auto& spot = *light(p, "/Spot").shaping;
    EXPECT_EQ(spot.coneAngleDegrees, 30.0f);
    EXPECT_FLOAT_EQ(spot.coneSoftness, 0.2f);
    EXPECT_EQ(spot.focus, 4.0f);
    EXPECT_FLOAT_EQ(spot.focusTint.z, 0.3f);
    EXPECT_EQ(light(p, "/Legacy").shaping->coneAngleDegrees, 45.0f);
    EXPECT_FALSE(light(p, "/Plain").shaping);
    EXPECT_FALSE(light(p, "/Dome").shaping);
    EXPECT_TRUE(warned(p, "/Dome: shaping is not applied to DomeLights"));
}

TEST(LightAdapter, DomeAndRectTexturesAreLoadedOrWarnedAbout) {
    test::TempDir dir;
    std::vector<float> sky(8 * 4 * 3, 0.25f);
    sky[0] = 5.0f;  // top-left texel, red
    test::writeImage(dir.file("sky.exr"), 8, 4, 3, OIIO::TypeDesc::FLOAT, sky);
    test::writeImage(dir.file("square.exr"), 4, 4, 3, OIIO::TypeDesc::FLOAT, std::vector<float>(48, 1.0f));
    auto p = populate(R"(
def DomeLight "Sky"
{
    asset inputs:texture:file = @)" +
                      dir.file("sky.exr") + R"(@
    token inputs:texture:format = "latlong"
}
def DomeLight "Lost"
{
    color3f inputs:color = (0.5, 0.5, 0.5)
    asset inputs:texture:file = @)" +
                      dir.file("lost.hdr") + R"(@
}
def DomeLight "Ball"
{
    asset inputs:texture:file = @)" +
                      dir.file("sky.exr") + R"(@
    token inputs:texture:format = "mirroredBall"
}
def DomeLight "Square"
{
    asset texture:file = @)" +
                      dir.file("square.exr") + R"(@
}
def RectLight "Panel"
{
    asset inputs:texture:file = @)" +
                      dir.file("sky.exr") + R"(@
}
)");
    const auto& sky1 = light(p, "/Sky");
    ASSERT_TRUE(sky1.texture);
    EXPECT_EQ(sky1.texture->width, 8);
    EXPECT_EQ(sky1.texture->height, 4);
    EXPECT_EQ(sky1.texture->at(0, 0), RGB(5.0f, 0.25f, 0.25f));
    EXPECT_EQ(sky1.texture->at(7, 3), RGB(0.25f));
    EXPECT_FALSE(light(p, "/Lost").texture);
    EXPECT_EQ(light(p, "/Lost").radiance, RGB(0.5f)) << "the constant colour remains";
    EXPECT_TRUE(warned(p, "/Lost: cannot read image '" + dir.file("lost.hdr") + "'"));
    EXPECT_FALSE(light(p, "/Ball").texture);
    EXPECT_TRUE(warned(p, "/Ball: texture:format 'mirroredBall' is not supported"));
    EXPECT_TRUE(light(p, "/Square").texture) << "pre-21.05 name";
    EXPECT_TRUE(warned(p, "/Square: texture '" + dir.file("square.exr") + "' is 4x4, not 2:1"));
    EXPECT_TRUE(light(p, "/Panel").texture);
}

TEST(LightAdapter, IesProfilesAreReadOrWarnedAbout) {
    test::TempDir dir;
    std::ofstream(dir.file("lamp.ies")) << "IESNA:LM-63-2002\nTILT=NONE\n1 -1 2 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n5 3\n";
    std::ofstream(dir.file("bad.ies")) << "IESNA:LM-63-2002\nTILT=NONE\n1 -1 2 2 1 1 2 0 0 0\n1 1 10\n0 90\n0\n5 x\n";
    auto p = populate(R"(
def SphereLight "Lamp"
{
    asset inputs:shaping:ies:file = @)" +
                      dir.file("lamp.ies") + R"(@
    float inputs:shaping:ies:angleScale = -0.25
    bool inputs:shaping:ies:normalize = 1
}
def DiskLight "Default"
{
    asset inputs:shaping:ies:file = @)" +
                      dir.file("lamp.ies") + R"(@
}
def RectLight "Lost"
{
    asset inputs:shaping:ies:file = @)" +
                      dir.file("lost.ies") + R"(@
}
def CylinderLight "Bad"
{
    asset inputs:shaping:ies:file = @)" +
                      dir.file("bad.ies") + R"(@
}
)");
    const auto& lamp = *light(p, "/Lamp").shaping;
    ASSERT_TRUE(lamp.ies);
    EXPECT_EQ(lamp.ies->candela, (std::vector<float>{10.0f, 6.0f})) << "times the candela multiplier";
    EXPECT_EQ(lamp.iesAngleScale, -0.25f);
    EXPECT_TRUE(lamp.iesNormalize);
    const auto& plain = *light(p, "/Default").shaping;
    ASSERT_TRUE(plain.ies);
    EXPECT_EQ(plain.iesAngleScale, 0.0f);
    EXPECT_FALSE(plain.iesNormalize);
    EXPECT_EQ(plain.coneAngleDegrees, 90.0f);
    EXPECT_FALSE(light(p, "/Lost").shaping->ies);
    EXPECT_TRUE(warned(p, "/Lost: " + dir.file("lost.ies") + ": cannot be opened; the light is rendered without"));
    EXPECT_FALSE(light(p, "/Bad").shaping->ies);
    EXPECT_TRUE(warned(p, "/Bad: " + dir.file("bad.ies") + ":7: 'x' is not a number (the candela values)"));
}

TEST(LightAdapter, DomeLight1PoleAxisTurnsOnlyTheDome) {
    const std::string lights = R"(
def DomeLight_1 "Z"
{
    uniform token poleAxis = "Z"
}
def DomeLight_1 "Y"
{
    uniform token poleAxis = "Y"
}
def DomeLight_1 "Scene"
{
}
def DomeLight "Classic"
{
}
)";
    auto yUp = populate(lights);
    EXPECT_EQ(light(yUp, "/Z").transform, Matrix4::rotateX(90.0));
    EXPECT_EQ(light(yUp, "/Y").transform, Matrix4::identity());
    EXPECT_EQ(light(yUp, "/Scene").transform, Matrix4::identity());
    auto zUp = populate("#usda 1.0\n(\n    upAxis = \"Z\"\n)\n" + testing::kCamera + lights);
    EXPECT_EQ(light(zUp, "/Scene").transform, Matrix4::rotateX(90.0)) << "poleAxis scene follows the stage's upAxis";
    EXPECT_EQ(light(zUp, "/Classic").transform, Matrix4::identity()) << "DomeLight keeps its pole on +Y";
    // Turned +90 degrees about X, the dome's top (+Y) is +Z and its longitude 0 (+Z) is -Y.
    Vec3d top = light(yUp, "/Z").transform.transformVector({0, 1, 0}),
          front = light(yUp, "/Z").transform.transformVector({0, 0, 1});
    EXPECT_NEAR(top.z, 1.0, 1e-12);
    EXPECT_NEAR(front.y, -1.0, 1e-12);
}

}  // namespace
}  // namespace fluence::delegate
