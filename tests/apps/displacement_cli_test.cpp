// End-to-end displacement: a Sphere of radius 1 displaced by a UsdPreviewSurface constant, seen by an
// orthographic camera 4 x 4 units wide on 100 x 100 pixels (a pixel is 0.04 units), covers a disc
// of the displaced radius (alpha summed over the image against the analytic area); a displacement
// map that is missing is named, and --allow-missing renders the sphere undisplaced.
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// The sphere bound to a material whose displacement is `displacement` (a Surface input line).
std::string sphereScene(const std::string& displacement, const std::string& extraShaders = "") {
    return R"(#usda 1.0
def Camera "Camera"
{
    double3 xformOp:translate = (0, 0, 10)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    token projection = "orthographic"
    float horizontalAperture = 40
    float verticalAperture = 40
}
def DistantLight "Sun"
{
}
def Sphere "Ball"
{
    double radius = 1
    rel material:binding = </M>
}
def Material "M"
{
    token outputs:surface.connect = </M/Surface.outputs:surface>
    def Shader "Surface"
    {
        uniform token info:id = "UsdPreviewSurface"
        )" +
           displacement +
           R"(
        token outputs:surface
    }
)" + extraShaders +
           "}\n";
}

class DisplacementCli : public ::testing::Test {
protected:
    test::TempDir dir_{"displacement_cli"};

    test::RunResult render(const std::string& usda, const std::string& flags = "") {
        std::ofstream(dir_.file("scene.usda")) << usda;
        return test::runFluence("render " + dir_.file("scene.usda") + " -o " + dir_.file("out.exr") +
                                    " -r 100 100 --spp 16 --seed 0 " + flags,
                                dir_.path());
    }
    // The area the image's alpha covers, in square scene units.
    double coveredArea() {
        test::ExrImage image = test::readExr(dir_.file("out.exr"));
        double alpha = 0.0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) alpha += image.at(x, y, "A");
        return alpha * 0.04 * 0.04;
    }
};

// Tolerance: the tessellation's sag (0.1% of the radius, 0.2% of the area) and the edge pixels'
// alpha noise at 16 samples (about 200 edge pixels, each within 0.125: 0.06% of the area).
constexpr double kTolerance = 0.01;

TEST_F(DisplacementCli, DisplacedSphereCoversTheDisplacedDisc) {
    test::RunResult plain = render(sphereScene("float inputs:displacement = 0"));
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    EXPECT_NEAR(coveredArea() / std::numbers::pi, 1.0, kTolerance);
    test::RunResult displaced = render(sphereScene("float inputs:displacement = 0.25"));
    ASSERT_EQ(displaced.exitCode, 0) << displaced.err;
    EXPECT_NEAR(coveredArea() / (std::numbers::pi * 1.25 * 1.25), 1.0, kTolerance);
}

TEST_F(DisplacementCli, MissingHeightMapIsNamedAndAllowMissingDisplacesNothing) {
    const std::string scene = sphereScene("float inputs:displacement.connect = </M/Height.outputs:r>", R"(
    def Shader "Height"
    {
        uniform token info:id = "UsdUVTexture"
        asset inputs:file = @./no_such_height.exr@
        float4 inputs:bias = (0.5, 0.5, 0.5, 0)
        float outputs:r
    }
)");
    test::RunResult refused = render(scene);
    EXPECT_EQ(refused.exitCode, 4) << refused.err;
    EXPECT_NE(refused.err.find("no_such_height.exr"), std::string::npos) << refused.err;
    test::RunResult allowed = render(scene, "--allow-missing");
    ASSERT_EQ(allowed.exitCode, 0) << allowed.err;
    EXPECT_NE(allowed.err.find("no_such_height.exr"), std::string::npos) << allowed.err;
    // The texture's fallback (0), not its bias, is the displacement: the undisplaced disc.
    EXPECT_NEAR(coveredArea() / std::numbers::pi, 1.0, kTolerance);
}

}  // namespace
}  // namespace fluence
