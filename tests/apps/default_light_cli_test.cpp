// End-to-end tests of the default lights (delegate/default_lights.h): a scene in which nothing
// emits is lit by a distant light along the camera's view and a dim dome, with one warning;
// --no-default-light renders it black; a lit scene is unchanged; the key light casts no shadow.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "tests/support/cli.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

// Two grey (albedo 0.5) quads before a camera at z = 8: one facing it, one turned 60 degrees
// about +Y (normal (sin 60, 0, cos 60)). Neither sees the other from its front. `extra` is added.
std::string twoQuads(const std::string& extra = "") {
    return R"(#usda 1.0
def Camera "Cam"
{
    double3 xformOp:translate = (0, 0, 8)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Mesh "Facing"
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-1.5, -0.6, 0), (-0.3, -0.6, 0), (-0.3, 0.6, 0), (-1.5, 0.6, 0)]
    color3f[] primvars:displayColor = [(0.5, 0.5, 0.5)]
}
def Mesh "Turned"
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0.3, -0.6, 0), (0.9, -0.6, -1.03923), (0.9, 0.6, -1.03923), (0.3, 0.6, 0)]
    color3f[] primvars:displayColor = [(0.5, 0.5, 0.5)]
}
)" + extra;
}

class DefaultLightCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"default_light_cli"};
    const fs::path dir_ = tmp_.path();

    fs::path write(const std::string& name, const std::string& text) {
        fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p;
    }
    test::RunResult render(const fs::path& scene, const std::string& output, const std::string& options = "") {
        return test::runFluence(
            "render " + scene.string() + " -o " + (dir_ / output).string() + " -r 64 48 --spp 16 " + options, dir_);
    }
};

// Mean red of the pixels whose shading normal `select` accepts.
test::MeanEstimate redWhere(const test::ExrImage& img, const std::function<bool(float, float, float)>& select) {
    test::MeanEstimate e;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (select(img.at(x, y, "N.X"), img.at(x, y, "N.Y"), img.at(x, y, "N.Z"))) e.add(img.at(x, y, "R"));
    return e;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

constexpr const char* kWarning = "nothing in the scene emits light";

TEST_F(DefaultLightCli, UnlitSceneIsLitFromTheCameraWithOneWarning) {
    test::RunResult r = render(write("unlit.usda", twoQuads()), "unlit.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(occurrences(r.err, kWarning), 1u) << r.err;
    EXPECT_EQ(r.err.find("the image will be black"), std::string::npos) << r.err;
    const test::ExrImage img = test::readExr(dir_ / "unlit.exr");
    // Key light: irradiance pi along the view, so albedo x cos(angle to the view); the dome adds
    // 0.1 x albedo over an unoccluded hemisphere.
    const test::MeanEstimate facing = redWhere(img, [](float, float, float z) { return z > 0.999f; });
    const test::MeanEstimate turned = redWhere(
        img, [](float x, float, float z) { return std::abs(x - 0.866f) < 0.01f && std::abs(z - 0.5f) < 0.01f; });
    ASSERT_GT(facing.count(), 50);
    ASSERT_GT(turned.count(), 20);
    EXPECT_NEAR(facing.mean(), 0.5 * (1.0 + 0.1), 5 * facing.standardError() + 0.01);
    EXPECT_NEAR(turned.mean(), 0.5 * (0.5 + 0.1), 5 * turned.standardError() + 0.01);
    // The dome lights the quads but, as in usdview, is not the background: a camera ray that
    // escapes sees black, with alpha 0.
    for (const char* c : {"R", "G", "B", "A"}) EXPECT_EQ(img.at(32, 2, c), 0.0f) << c;
}

// usdchecker's clean.usdz: the camera inside a closed shape. As usdview's camera light, the key
// light casts no shadow, so the inside wall the camera faces shows its albedo (irradiance pi along
// the view) in direct light (--max-depth 1: the walls' interreflection left out); the dome, shut
// out by the box, adds nothing (its light samples, chosen beside the key light's, make the noise).
TEST_F(DefaultLightCli, CameraInsideAClosedBoxSeesItLit) {
    const fs::path scene = write("inside.usda", R"(#usda 1.0
def Camera "Cam"
{
}
def Cube "Box"
{
    double size = 10
    color3f[] primvars:displayColor = [(0.5, 0.5, 0.5)]
}
)");
    test::RunResult r = render(scene, "inside.exr", "--max-depth 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage img = test::readExr(dir_ / "inside.exr");
    const test::MeanEstimate back = redWhere(img, [](float, float, float z) { return std::abs(z) > 0.999f; });
    ASSERT_GT(back.count(), 100);
    EXPECT_NEAR(back.mean(), 0.5, 5 * back.standardError() + 0.01);
}

TEST_F(DefaultLightCli, NoDefaultLightRendersBlack) {
    test::RunResult r = render(write("unlit.usda", twoQuads()), "black.exr", "--no-default-light");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find(kWarning), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the scene has no lights; the image will be black"), std::string::npos) << r.err;
    const test::ExrImage img = test::readExr(dir_ / "black.exr");
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (const char* c : {"R", "G", "B"}) ASSERT_EQ(img.at(x, y, c), 0.0f) << x << "," << y << " " << c;
}

TEST_F(DefaultLightCli, RenderSettingsTurnTheDefaultLightOff) {
    const fs::path scene = write("settings.usda", twoQuads(R"(
def RenderSettings "Settings"
{
    bool fluence:defaultLight = false
}
)"));
    test::RunResult r = render(scene, "settings.exr", "-s /Settings");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find(kWarning), std::string::npos) << r.err;
    const test::ExrImage img = test::readExr(dir_ / "settings.exr");
    EXPECT_EQ(redWhere(img, [](float, float, float z) { return z > 0.999f; }).mean(), 0.0);
}

// A light, an emissive surface: the scene renders as it did, bit for bit, and nothing is added.
TEST_F(DefaultLightCli, SceneThatEmitsIsUnchanged) {
    const std::string lit = R"(
def DistantLight "Sun"
{
    float inputs:intensity = 2
}
)";
    const std::string emissive = R"(
def Mesh "Lamp" (prepend apiSchemas = ["MaterialBindingAPI"])
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(-1, 1, 1), (1, 1, 1), (1, 1, -1), (-1, 1, -1)]
    rel material:binding = </Glow>
}
def Material "Glow"
{
    token outputs:surface.connect = </Glow/Surface.outputs:surface>
    def Shader "Surface"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:emissiveColor = (1, 1, 1)
        token outputs:surface
    }
}
)";
    for (const std::string& extra : {lit, emissive}) {
        const fs::path scene = write("lit.usda", twoQuads(extra));
        test::RunResult withDefault = render(scene, "default.exr");
        ASSERT_EQ(withDefault.exitCode, 0) << withDefault.err;
        EXPECT_EQ(withDefault.err.find(kWarning), std::string::npos) << withDefault.err;
        ASSERT_EQ(render(scene, "off.exr", "--no-default-light").exitCode, 0);
        const test::ExrImage a = test::readExr(dir_ / "default.exr"), b = test::readExr(dir_ / "off.exr");
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        EXPECT_TRUE(a.pixels == b.pixels) << extra;
        EXPECT_GT(redWhere(a, [](float, float, float z) { return z > 0.999f; }).mean(), 0.0) << extra;
    }
}

}  // namespace
}  // namespace fluence
