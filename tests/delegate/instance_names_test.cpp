// The names the delegate gives instances (render::InstanceDesc::name), which Cryptomatte's object
// layer shows: a native instance's prim path, and a PointInstancer's path with the instance's id
// (its `ids` entry, else its index).
#include <gtest/gtest.h>

#include "delegate/scene_delegate.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

std::vector<std::string> instanceNames(const render::SceneDescription& scene) {
    std::vector<std::string> names;
    for (const render::InstanceDesc& instance : scene.instances) names.push_back(instance.name);
    return names;
}

TEST(InstanceNames, NativeInstancesAreNamedByTheirPrims) {
    auto p = populate(R"(
class Xform "_Prop"
{
    def Sphere "Ball"
    {
    }
}
def Xform "A" (
    instanceable = true
    prepend references = </_Prop>
)
{
}
def Xform "B" (
    instanceable = true
    prepend references = </_Prop>
)
{
}
)");
    EXPECT_EQ(instanceNames(p.result.scene), (std::vector<std::string>{"/A", "/B"}));
}

std::string pointInstancer(const std::string& idsLine) {
    return R"(
def PointInstancer "Scatter"
{
    int[] protoIndices = [0, 0, 0]
    )" + idsLine +
           R"(
    int64[] invisibleIds = [1]
    point3f[] positions = [(1, 0, 0), (2, 0, 0), (3, 0, 0)]
    rel prototypes = [</Scatter/Ball>]
    def Sphere "Ball"
    {
    }
}
)";
}

TEST(InstanceNames, PointInstancesAreNamedByTheirIds) {
    EXPECT_EQ(instanceNames(populate(pointInstancer("int64[] ids = [7, 1, 9]")).result.scene),
              (std::vector<std::string>{"/Scatter[7]", "/Scatter[9]"}));
    // Without ids, the index (here 1 is the hidden one).
    EXPECT_EQ(instanceNames(populate(pointInstancer("")).result.scene),
              (std::vector<std::string>{"/Scatter[0]", "/Scatter[2]"}));
}

}  // namespace
}  // namespace fluence::delegate
