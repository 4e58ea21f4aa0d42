// Deformation inside shared prototypes (delegate/motion_steps.h, PrototypeMotionSteps): the
// meshes, curves and points of a native instance's or a point instancer's prototype that deform
// over the shutter (time-sampled points, velocities, a skinned pose) get time steps in prototype
// space, which each instance's transform places exactly where its un-instanced twin's world-space
// steps are; the prototype stays shared.
#include <gtest/gtest.h>

#include "tests/delegate/delegate_test_support.h"
#include "tests/delegate/skel_agent.h"

namespace fluence::delegate {
namespace {

// The shutter spans codes 1 to 2 from frame 1 (24 codes per second).
const std::string kCamera = "def Camera \"Cam\"\n{\n    double shutter:open = 0\n    double shutter:close = 1\n}\n";

// A triangle whose third point moves from x = 0 to x = 1, a linear curve moving by its velocities
// (24 units per second along y: one unit over the shutter) and two points whose second moves up.
const std::string kThing = R"(
    def Mesh "Sail"
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points.timeSamples = { 1: [(0, 0, 0), (1, 0, 0), (0, 1, 0)], 2: [(0, 0, 0), (1, 0, 0), (1, 1, 0)] }
    }
    def BasisCurves "Hair"
    {
        uniform token type = "linear"
        int[] curveVertexCounts = [2]
        float[] widths = [0.1]
        point3f[] points = [(0, 0, 1), (1, 0, 1)]
        vector3f[] velocities = [(0, 24, 0), (0, 24, 0)]
    }
    def Points "Dust"
    {
        float[] widths = [0.2, 0.2]
        point3f[] points.timeSamples = { 1: [(0, 0, 2), (1, 0, 2)], 2: [(0, 0, 2), (1, 2, 2)] }
    }
)";

// /Thing's content instanced at /I (x + 5) and, not instanced, at /Twin (x + 5, so the world
// positions must agree).
std::string instancedAndTwin() {
    return kCamera + "class Xform \"Thing\"\n{\n" + kThing + R"(}
def Xform "I" (instanceable = true; references = </Thing>)
{
    double3 xformOp:translate = (5, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Xform "Twin" (references = </Thing>)
{
    double3 xformOp:translate = (5, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)";
}

testing::Populated describe(const std::string& usda) {
    testing::Populated d;
    d.stage = testing::stageFrom(usda);
    DelegateOptions options = testing::testOptions(d);
    options.cameraPath = "/Cam";
    options.time = 1.0;
    d.result = populateScene(*d.stage, options);
    return d;
}

// `placed` (prototype space, placed by `toWorld`) has the time steps of `world`.
void expectSameSteps(const std::vector<std::vector<Vec3f>>& placed, const Matrix4& toWorld,
                     const std::vector<std::vector<Vec3f>>& world, const std::string& what) {
    ASSERT_EQ(placed.size(), 2u) << what;
    ASSERT_EQ(world.size(), 2u) << what;
    for (std::size_t step = 0; step < 2; ++step) {
        ASSERT_EQ(placed[step].size(), world[step].size()) << what;
        for (std::size_t i = 0; i < world[step].size(); ++i)
            EXPECT_LT(length(toWorld.transformPoint(Vec3d(placed[step][i])) - Vec3d(world[step][i])), 1e-5)
                << what << " step " << step << " point " << i;
    }
}

TEST(PrototypeMotion, APrototypesMeshCurvesAndPointsGetTheTimeStepsOfTheirUninstancedTwins) {
    const testing::Populated d = describe(instancedAndTwin());
    const render::SceneDescription& scene = d.result.scene;
    ASSERT_EQ(scene.instances.size(), 1u);
    ASSERT_EQ(scene.prototypes.size(), 1u);
    const render::PrototypeDesc& prototype = scene.prototypes[0];
    const Matrix4& toWorld = scene.instances[0].transform;
    EXPECT_TRUE(scene.instances[0].motionTransforms.empty()) << "the instance itself does not move";
    ASSERT_EQ(prototype.meshes.size(), 1u);
    ASSERT_EQ(prototype.curves.size(), 1u);
    ASSERT_EQ(prototype.points.size(), 1u);
    const render::MeshDesc* twinSail = d.mesh("/Twin/Sail");
    ASSERT_NE(twinSail, nullptr);
    ASSERT_EQ(scene.curves.size(), 1u);
    ASSERT_EQ(scene.points.size(), 1u);
    expectSameSteps(prototype.meshes[0].motionPositions, toWorld, twinSail->motionPositions, "mesh");
    expectSameSteps(prototype.curves[0].motionPoints, toWorld, scene.curves[0].motionPoints, "curve");
    expectSameSteps(prototype.points[0].motionPositions, toWorld, scene.points[0].motionPositions, "points");
    // The known motion: the sail's third point from x = 0 to 1, the hair a unit up, the second
    // dust point two units up (prototype space).
    EXPECT_NEAR(prototype.meshes[0].motionPositions[1][2].x - prototype.meshes[0].motionPositions[0][2].x, 1.0, 1e-6);
    EXPECT_NEAR(prototype.curves[0].motionPoints[1][0].y - prototype.curves[0].motionPoints[0][0].y, 1.0, 1e-5);
    EXPECT_NEAR(prototype.points[0].motionPositions[1][1].y - prototype.points[0].motionPositions[0][1].y, 2.0, 1e-6);
    EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
}

TEST(PrototypeMotion, APointInstancerPrototypeSkinnedByAnAnimationOutsideItIsPosedAtEachStep) {
    // The one-joint agent (tests/delegate/skel_agent.h) as the prototype, its animation (a unit
    // move along x over the shutter) outside it: every instance poses alike, and the prototype moves.
    const testing::Populated d = describe(kCamera + testing::agentClass() + R"(
def Xform "Anims"
{
    def SkelAnimation "Slide"
    {
        uniform token[] joints = ["Root"]
        float3[] translations.timeSamples = { 1: [(0, 0, 0)], 2: [(1, 0, 0)] }
        quatf[] rotations = [(1, 0, 0, 0)]
        half3[] scales = [(1, 1, 1)]
    }
}
def PointInstancer "Crowd"
{
    rel prototypes = [</Crowd/Agent>]
    int[] protoIndices = [0, 0]
    point3f[] positions = [(0, 0, 0), (0, 3, 0)]
    def SkelRoot "Agent" (prepend apiSchemas = ["SkelBindingAPI"]; references = </Agent>)
    {
        rel skel:animationSource = </Anims/Slide>
    }
}
)");
    const render::SceneDescription& scene = d.result.scene;
    ASSERT_EQ(scene.instances.size(), 2u);
    ASSERT_EQ(scene.prototypes.size(), 1u) << "shared";
    ASSERT_EQ(scene.prototypes[0].meshes.size(), 1u);
    const render::MeshDesc& quad = scene.prototypes[0].meshes[0];
    ASSERT_EQ(quad.motionPositions.size(), 2u);
    for (std::size_t i = 0; i < quad.positions.size(); ++i) {
        EXPECT_NEAR(quad.motionPositions[1][i].x - quad.motionPositions[0][i].x, 1.0, 1e-6) << i;
        EXPECT_NEAR(quad.motionPositions[1][i].y - quad.motionPositions[0][i].y, 0.0, 1e-6) << i;
    }
}

}  // namespace
}  // namespace fluence::delegate
