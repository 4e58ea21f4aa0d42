// Skinned prims inside native instances (delegate/skinned_instances.h): an instanceable SkelRoot
// whose animation is bound above it, as crowds author it (arnold-usd test_1524), is de-instanced
// and each copy posed by its own animation, at the points its joint transforms give; a prototype
// whose whole binding lies inside it stays shared, and holds its mesh posed.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/delegate/delegate_test_support.h"
#include "tests/delegate/skel_agent.h"

namespace fluence::delegate {
namespace {

using testing::agentClass;
using testing::populate;
using testing::Populated;

// An animation of joint Root: a translation and a turn about +z by a quarter (`quarterTurn`).
std::string animation(const std::string& name, const std::string& translation, bool quarterTurn) {
    return "    def SkelAnimation \"" + name +
           "\"\n    {\n        uniform token[] joints = [\"Root\"]\n        float3[] translations = [" + translation +
           "]\n        quatf[] rotations = [" + (quarterTurn ? "(0.70710678, 0, 0, 0.70710678)" : "(1, 0, 0, 0)") +
           "]\n        half3[] scales = [(1, 1, 1)]\n    }\n";
}

// Two agents, /A at the origin and /B moved 5 along x, each an instance of /Agent whose animation
// is bound on its parent, outside the instance.
std::string crowd() {
    return agentClass() + R"(
def Xform "A" (prepend apiSchemas = ["SkelBindingAPI"])
{
    rel skel:animationSource = </A/Walk>
)" + animation("Walk", "(0, 2, 0)", false) +
           R"(
    def SkelRoot "Agent" (instanceable = true; references = </Agent>) {}
}
def Xform "B" (prepend apiSchemas = ["SkelBindingAPI"])
{
    double3 xformOp:translate = (5, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    rel skel:animationSource = </B/Jump>
)" + animation("Jump", "(0, -3, 1)", true) +
           R"(
    def SkelRoot "Agent" (instanceable = true; references = </Agent>) {}
}
)";
}

const Vec3d kQuad[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

void expectPositions(const render::MeshDesc& mesh, const Matrix4& pose) {
    ASSERT_EQ(mesh.positions.size(), 4u) << mesh.name;
    for (std::size_t i = 0; i < 4; ++i) {
        const Vec3d expected = pose.transformPoint(kQuad[i]);
        EXPECT_LT(length(Vec3d(mesh.positions[i]) - expected), 1e-6)
            << mesh.name << " point " << i << " at (" << mesh.positions[i].x << ", " << mesh.positions[i].y << ", "
            << mesh.positions[i].z << "), expected (" << expected.x << ", " << expected.y << ", " << expected.z << ")";
    }
}

std::size_t countContaining(const std::vector<std::string>& warnings, const std::string& text) {
    return static_cast<std::size_t>(std::count_if(
        warnings.begin(), warnings.end(), [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

TEST(SkinnedInstances, AnimationBoundAboveTheInstanceDeInstancesItAndPosesEachCopy) {
    const Populated p = populate(crowd());
    const render::SceneDescription& scene = p.result.scene;
    EXPECT_TRUE(scene.prototypes.empty());
    EXPECT_TRUE(scene.instances.empty());
    const render::MeshDesc* a = p.mesh("/A/Agent/Quad");
    const render::MeshDesc* b = p.mesh("/B/Agent/Quad");
    ASSERT_TRUE(a && b) << "each agent's quad is a mesh of its own, at its instance-proxy path";
    expectPositions(*a, Matrix4::translate({0, 2, 0}));
    expectPositions(*b, Matrix4::translate({5, 0, 0}) * Matrix4::translate({0, -3, 1}) * Matrix4::rotateZ(90.0));
    EXPECT_EQ(countContaining(p.warnings,
                              "/A/Agent: de-instanced: 1 skinned prim in it (/A/Agent/Quad) read "
                              "UsdSkel data outside the instance (/A)"),
              1u);
    EXPECT_EQ(countContaining(p.warnings, "/B/Agent: de-instanced"), 1u);
}

TEST(SkinnedInstances, ABindingInsideThePrototypeKeepsItSharedAndPosed) {
    const Populated p = populate(
        agentClass("        rel skel:animationSource = </Agent/Walk>\n", animation("Walk", "(0, 2, 0)", true)) +
        R"(
def SkelRoot "A" (instanceable = true; references = </Agent>) {}
def SkelRoot "B" (instanceable = true; references = </Agent>)
{
    double3 xformOp:translate = (5, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)");
    const render::SceneDescription& scene = p.result.scene;
    ASSERT_EQ(scene.prototypes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    ASSERT_EQ(scene.prototypes[0].meshes.size(), 1u);
    expectPositions(scene.prototypes[0].meshes[0], Matrix4::translate({0, 2, 0}) * Matrix4::rotateZ(90.0));
    EXPECT_EQ(scene.instances[1].transform, Matrix4::translate({5, 0, 0}));
    EXPECT_EQ(countContaining(p.warnings, "de-instanced"), 0u);
}

TEST(SkinnedInstances, AnUnskinnedInstanceStaysShared) {
    std::string usda = agentClass();
    usda.replace(usda.find("class SkelRoot"), 14, "class Xform");  // no SkelRoot: bindings mean nothing
    const Populated p = populate(usda + R"(
def Xform "A" (prepend apiSchemas = ["SkelBindingAPI"])
{
    rel skel:animationSource = </A/Walk>
)" + animation("Walk", "(0, 2, 0)", false) +
                                 R"(
    def Xform "Agent" (instanceable = true; references = </Agent>) {}
}
)");
    ASSERT_EQ(p.result.scene.prototypes.size(), 1u);
    ASSERT_EQ(p.result.scene.prototypes[0].meshes.size(), 1u);
    expectPositions(p.result.scene.prototypes[0].meshes[0], Matrix4::identity());
    EXPECT_EQ(countContaining(p.warnings, "de-instanced"), 0u);
}

}  // namespace
}  // namespace fluence::delegate
