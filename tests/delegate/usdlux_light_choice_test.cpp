// Shaped UsdLux lights beside a dome, as public scenes author them (arnold-usd testsuite
// test_0228: a treatAsPoint SphereLight with an 8-degree cone and exposure 10 aimed at a sphere
// under a dim DomeLight): USDA through the delegate to the render core's lights and light tree.
// Inside its cone, on the axis, a shaped light delivers exactly the irradiance of its unshaped
// twin (the shaping factor is 1 there), so the tree must choose it as often as it chooses the
// twin in its place. The cone's share of the power (0.5 % for 8 degrees) used to scale the
// tree's weight as well, and the spot, chosen about 1 time in 200 where it outshines the dome,
// rendered as sparse fireflies that 256 samples per pixel did not smooth.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/light_tree.h"
#include "render/lights/light_registry.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

// A dim dome, and a light of `type` 12 units above the origin aiming down (its -Z along world
// -Y), with `inputs` (USDA lines).
std::string domeAndLight(const std::string& type, const std::string& inputs) {
    return R"(
def DomeLight "Dome"
{
    float inputs:intensity = 0.5
}
def )" + type +
           R"( "Light"
{
)" + inputs +
           R"(
    double3 xformOp:translate = (0, 12, 0)
    float3 xformOp:rotateXYZ = (-90, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
}
)";
}

// The probability the light tree of the scene's lights gives /Light at the top of a unit sphere
// at the origin (normal up).
float chanceOfTheLight(const std::string& usda) {
    auto p = populate(usda);
    std::vector<std::unique_ptr<render::Light>> lights;
    int index = -1;
    for (const render::LightDesc& d : p.result.scene.lights) {
        if (d.name == "/Light") index = int(lights.size());
        lights.push_back(render::makeLight(d));
    }
    if (index < 0 || lights.size() != 2) throw std::runtime_error("expected the dome and /Light");
    const render::LightTree tree(lights, render::SceneBounds{Vec3f(0.0f), 13.0f});
    return tree.probability(Vec3f(0.0f, 1.0f, 0.0f), Vec3f(0.0f, 1.0f, 0.0f), index);
}

TEST(UsdLuxLightChoice, ANarrowSpotIsChosenAsItsUnshapedTwinOnItsAxis) {
    const std::string spot = R"(
    float inputs:exposure = 10
    bool inputs:normalize = 1
    bool treatAsPoint = 1)";
    const float shaped =
        chanceOfTheLight(domeAndLight("SphereLight", spot + "\n    float inputs:shaping:cone:angle = 8"));
    const float twin = chanceOfTheLight(domeAndLight("SphereLight", spot));
    EXPECT_GT(twin, 0.5f);  // the spot outshines the dome at the point
    EXPECT_NEAR(shaped, twin, 1e-6f * twin);
}

TEST(UsdLuxLightChoice, AConedRectIsChosenAsItsUnshapedTwinOnItsAxis) {
    const std::string rect = R"(
    float inputs:exposure = 10)";
    const float shaped =
        chanceOfTheLight(domeAndLight("RectLight", rect + "\n    float inputs:shaping:cone:angle = 8"));
    const float twin = chanceOfTheLight(domeAndLight("RectLight", rect));
    EXPECT_GT(twin, 0.5f);
    EXPECT_NEAR(shaped, twin, 1e-6f * twin);
}

}  // namespace
}  // namespace fluence::delegate
