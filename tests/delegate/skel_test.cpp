// UsdSkel through the delegate (delegate/skel_binding.h): a skinned mesh's points equal those its
// joint transforms give, computed here independently (inverse bind × joint skeleton-space
// transform, in the skeleton's space, placed by the skeleton's transform); dual-quaternion
// against linear blend on a pure rotation; blend shapes with an in-between; time samples; and
// malformed bindings that leave the mesh in its rest pose with one warning naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::Populated;

constexpr double kDegree = std::numbers::pi / 180.0;

// The warnings about prims (not the stage-wide ones at "/", such as the default light's).
std::vector<std::string> primWarnings(const std::vector<std::string>& warnings) {
    std::vector<std::string> out;
    for (const std::string& w : warnings)
        if (!w.starts_with("/: ")) out.push_back(w);
    return out;
}

// The arm: a skeleton of Root and Root/Elbow (bound 2 apart along x) under a moved SkelRoot, the
// skeleton itself moved; the root joint turns and lifts over frames 1 and 2, the elbow turns
// (the animation lists its joints in the other order); a strip of 4 quads along x, authored 1
// to the left of its bind pose (geomBindTransform moves it back), with a transform of its own
// that skinning ignores.
struct ArmFrame {
    double rootDegrees, rootLift, elbowDegrees;
};
constexpr ArmFrame kFrames[] = {{30.0, 0.25, 90.0}, {-20.0, 0.5, 45.0}};

std::string quat(double degrees) {  // about +z, real part first as USDA writes it
    std::ostringstream s;
    s.precision(17);
    s << "(" << std::cos(degrees * kDegree / 2) << ", 0, 0, " << std::sin(degrees * kDegree / 2) << ")";
    return s.str();
}

// Influences per point x = -1..3 (authored), elementSize 2.
const double kRootWeight[] = {1.0, 1.0, 0.5, 0.0, 0.0};

std::string armScene(const std::string& meshLines = "", const std::string& skeletonLines = "") {
    std::string indices, weights, points;
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i < 5; ++i) {
            points += "(" + std::to_string(i - 1) + ", " + (row ? "0.5" : "-0.5") + ", 0), ";
            indices += "0, 1, ";
            weights += std::to_string(kRootWeight[i]) + ", " + std::to_string(1.0 - kRootWeight[i]) + ", ";
        }
    std::string rotations;
    for (int f = 0; f < 2; ++f)
        rotations +=
            std::to_string(f + 1) + ": [" + quat(kFrames[f].elbowDegrees) + ", " + quat(kFrames[f].rootDegrees) + "], ";
    return R"(
def SkelRoot "Char"
{
    double3 xformOp:translate = (0, 1, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    rel skel:skeleton = </Char/Skel>
    def Skeleton "Skel"
    {
        double3 xformOp:translate = (0.5, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        uniform token[] joints = ["Root", "Root/Elbow"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(2,0,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(2,0,0,1))]
        rel skel:animationSource = </Char/Skel/Anim>
)" + skeletonLines +
           R"(
        def SkelAnimation "Anim"
        {
            uniform token[] joints = ["Root/Elbow", "Root"]
            float3[] translations.timeSamples = {1: [(2, 0, 0), (0, 0, )" +
           std::to_string(kFrames[0].rootLift) + R"()], 2: [(2, 0, 0), (0, 0, )" + std::to_string(kFrames[1].rootLift) +
           R"()]}
            quatf[] rotations.timeSamples = {)" +
           rotations + R"(}
            half3[] scales = [(1, 1, 1), (1, 1, 1)]
        }
    }
    def Mesh "Arm" (prepend apiSchemas = ["SkelBindingAPI"])
    {
        double3 xformOp:translate = (5, 5, 5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4, 4, 4, 4]
        int[] faceVertexIndices = [0, 1, 6, 5, 1, 2, 7, 6, 2, 3, 8, 7, 3, 4, 9, 8]
        point3f[] points = [)" +
           points + R"(]
        int[] primvars:skel:jointIndices = [)" +
           indices + R"(] (interpolation = "vertex"; elementSize = 2)
        float[] primvars:skel:jointWeights = [)" +
           weights + R"(] (interpolation = "vertex"; elementSize = 2)
        matrix4d primvars:skel:geomBindTransform = ((1,0,0,0),(0,1,0,0),(0,0,1,0),(1,0,0,1))
)" + meshLines +
           R"(
    }
}
)";
}

// Where the arm's authored points go at frame `f` (0 or 1): the joints' skeleton-space
// transforms composed here from the frame's rotations and translations.
std::vector<Vec3d> posedArm(const ArmFrame& frame) {
    const Matrix4 root = Matrix4::translate({0, 0, frame.rootLift}) * Matrix4::rotateZ(frame.rootDegrees);
    const Matrix4 elbow = root * Matrix4::translate({2, 0, 0}) * Matrix4::rotateZ(frame.elbowDegrees);
    const Matrix4 skinning[] = {root, elbow * Matrix4::translate({-2, 0, 0})};  // joint × inverse bind
    const Matrix4 skeletonToWorld = Matrix4::translate({0, 1, 0}) * Matrix4::translate({0.5, 0, 0});
    std::vector<Vec3d> out;
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i < 5; ++i) {
            const Vec3d bound{static_cast<double>(i), row ? 0.5 : -0.5, 0.0};  // geomBindTransform: +1 along x
            const Vec3d skel = skinning[0].transformPoint(bound) * kRootWeight[i] +
                               skinning[1].transformPoint(bound) * (1.0 - kRootWeight[i]);
            out.push_back(skeletonToWorld.transformPoint(skel));
        }
    return out;
}

void expectPoints(const render::MeshDesc& mesh, const std::vector<Vec3d>& expected, double tolerance = 1e-5) {
    ASSERT_EQ(mesh.positions.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_LT(length(Vec3d(mesh.positions[i]) - expected[i]), tolerance)
            << "point " << i << " at (" << mesh.positions[i].x << ", " << mesh.positions[i].y << ", "
            << mesh.positions[i].z << "), expected (" << expected[i].x << ", " << expected[i].y << ", " << expected[i].z
            << ")";
}

// The delegate over `usda` at frame 1, then moved to frame 2 (as `fluence render -f 1 -n 2` does).
struct TwoFrames {
    render::SceneDescription first, second;
    std::vector<std::string> warnings;
};

TwoFrames describeFrames(const std::string& usda) {
    TwoFrames out;
    std::unique_ptr<usd::Stage> stage = testing::stageFrom(testing::kCamera + usda);
    DelegateOptions options;
    options.time = 1.0;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&out](const std::string& path, const std::string& message) {
        out.warnings.push_back(path + ": " + message);
    };
    SceneDelegate delegate(*stage, options);
    delegate.sync();
    out.first = delegate.sceneDescription();
    delegate.setTime(2.0);
    delegate.sync();
    out.second = delegate.sceneDescription();
    return out;
}

const render::MeshDesc* meshNamed(const render::SceneDescription& scene, const std::string& name) {
    for (const render::MeshDesc& m : scene.meshes)
        if (m.name == name) return &m;
    return nullptr;
}

TEST(Skel, SkinnedPointsAreThoseTheJointTransformsGiveAtEachFrame) {
    TwoFrames frames = describeFrames(armScene());
    for (const std::string& w : primWarnings(frames.warnings)) ADD_FAILURE() << w;
    const render::MeshDesc* first = meshNamed(frames.first, "/Char/Arm");
    const render::MeshDesc* second = meshNamed(frames.second, "/Char/Arm");
    ASSERT_TRUE(first && second);
    expectPoints(*first, posedArm(kFrames[0]));
    expectPoints(*second, posedArm(kFrames[1]));
}

TEST(Skel, NoSkelRootMeansNoSkinning) {
    std::string usda = armScene();
    usda.replace(usda.find("def SkelRoot"), 12, "def Xform");
    Populated p = populate(usda);
    const render::MeshDesc* arm = p.mesh("/Char/Arm");
    ASSERT_TRUE(arm);
    // The authored points, moved by the mesh's own transform and the Xform's.
    EXPECT_LT(length(Vec3d(arm->positions[0]) - Vec3d{-1 + 5, -0.5 + 6, 5}), 1e-6);
}

// The elbow's rest pose alone: a point bound half to the root and half to an elbow turned 90°
// about z through the origin.
std::string rotationScene(const std::string& method) {
    return R"(
def SkelRoot "R"
{
    def Skeleton "Skel"
    {
        uniform token[] joints = ["A", "A/B"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((0,1,0,0),(-1,0,0,0),(0,0,1,0),(0,0,0,1))]
    }
    def Mesh "M" (prepend apiSchemas = ["SkelBindingAPI"])
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(2, 0, 0), (0, 0, 1), (0, 0, -1)]
        normal3f[] normals = [(1, 0, 0), (1, 0, 0), (1, 0, 0)] (interpolation = "vertex")
        int[] primvars:skel:jointIndices = [0, 1] (interpolation = "constant"; elementSize = 2)
        float[] primvars:skel:jointWeights = [0.5, 0.5] (interpolation = "constant"; elementSize = 2)
        uniform token primvars:skel:skinningMethod = ")" +
           method + R"("
        rel skel:skeleton = </R/Skel>
    }
}
)";
}

TEST(Skel, LinearBlendShrinksAPureRotationAndDualQuaternionKeepsItsLength) {
    // (2, 0, 0) blended between itself and its 90° turn (0, 2, 0): linear blend gives the
    // midpoint (1, 1, 0), of length √2; the dual quaternion the 45° turn (√2, √2, 0), of length 2.
    Populated linear = populate(rotationScene("classicLinear"));
    Populated dual = populate(rotationScene("dualQuaternion"));
    for (const std::string& w : primWarnings(linear.warnings)) ADD_FAILURE() << w;
    for (const std::string& w : primWarnings(dual.warnings)) ADD_FAILURE() << w;
    ASSERT_TRUE(linear.mesh("/R/M") && dual.mesh("/R/M"));
    expectPoints(*linear.mesh("/R/M"), {{1, 1, 0}, {0, 0, 1}, {0, 0, -1}});
    expectPoints(*dual.mesh("/R/M"), {{std::sqrt(2.0), std::sqrt(2.0), 0}, {0, 0, 1}, {0, 0, -1}});
    // Normals turn with their points: by the blended rotation with dual quaternions, by the
    // blended inverse transposes (the same direction here) with linear blend.
    const Vec3d turned = normalize(Vec3d{1, 1, 0});
    for (const Populated* p : {&linear, &dual}) {
        const render::MeshDesc& m = *p->mesh("/R/M");
        ASSERT_EQ(m.cornerNormals.size(), 3u);
        for (const auto& n : m.cornerNormals) EXPECT_LT(length(Vec3d(n) - turned), 1e-5);
    }
}

// A quad whose point 2 a blend shape lifts by 1 along z, with an in-between at weight 0.5 that
// lifts it by 0.8; the animation's weight is `weight`, at frame 1.
std::string blendShapeScene(const std::string& weights, const std::string& inbetween = "(0, 0, 0.8)] (weight = 0.5)") {
    return R"(
def SkelRoot "R"
{
    def Skeleton "Skel"
    {
        uniform token[] joints = ["A"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        rel skel:animationSource = </R/Skel/Anim>
        def SkelAnimation "Anim"
        {
            uniform token[] blendShapes = ["other", "lift"]
            float[] blendShapeWeights.timeSamples = {)" +
           weights + R"(}
        }
    }
    def Mesh "M" (prepend apiSchemas = ["SkelBindingAPI"])
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
        uniform token[] skel:blendShapes = ["lift"]
        rel skel:blendShapeTargets = </R/M/Lift>
        rel skel:skeleton = </R/Skel>
        def BlendShape "Lift"
        {
            uniform vector3f[] offsets = [(0, 0, 1)]
            uniform int[] pointIndices = [2]
            uniform vector3f[] inbetweens:half = [)" +
           inbetween + R"(
        }
    }
}
)";
}

TEST(Skel, BlendShapeWithAnInBetweenAtWeightsZeroHalfAndOne) {
    // weight -> lift of point 2: the in-between exactly at its weight, the shapes at 0 and 1
    // exactly there, linear interpolation between them and beyond (unbounded).
    for (auto [weight, lift] :
         {std::pair{0.0, 0.0}, {0.5, 0.8}, {1.0, 1.0}, {0.25, 0.4}, {0.75, 0.9}, {1.5, 1.2}, {-0.25, -0.4}}) {
        Populated p = populate(blendShapeScene("1: [0.7, " + std::to_string(weight) + "], 2: [0, 0]"));
        for (const std::string& w : primWarnings(p.warnings)) ADD_FAILURE() << w;
        ASSERT_TRUE(p.mesh("/R/M"));
        expectPoints(*p.mesh("/R/M"), {{0, 0, 0}, {1, 0, 0}, {1, 1, lift}, {0, 1, 0}});
    }
}

TEST(Skel, BlendShapeWeightsFollowTheFrame) {
    TwoFrames frames = describeFrames(blendShapeScene("1: [0, 0.5], 2: [0, 1]"));
    ASSERT_TRUE(meshNamed(frames.first, "/R/M") && meshNamed(frames.second, "/R/M"));
    EXPECT_NEAR(meshNamed(frames.first, "/R/M")->positions[2].z, 0.8, 1e-6);
    EXPECT_NEAR(meshNamed(frames.second, "/R/M")->positions[2].z, 1.0, 1e-6);
}

TEST(Skel, AnInBetweenAtWeightOneIsIgnoredWithAWarning) {
    Populated p = populate(blendShapeScene("1: [0, 0.5]", "(0, 0, 0.8)] (weight = 1)"));
    ASSERT_TRUE(p.mesh("/R/M"));
    EXPECT_NEAR(p.mesh("/R/M")->positions[2].z, 0.5, 1e-6);  // half the primary shape
    const std::vector<std::string> warnings = primWarnings(p.warnings);
    ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(warnings);
    EXPECT_NE(warnings[0].find("/R/M/Lift: in-between 'inbetweens:half'"), std::string::npos) << warnings[0];
}

// A malformed binding: the mesh keeps its rest pose (the authored points, under the SkelRoot's
// transform) and one warning names it and the reason.
void expectRestPoseWithOneWarning(const std::string& usda, const std::string& reason) {
    Populated p = populate(usda);
    const render::MeshDesc* arm = p.mesh("/Char/Arm");
    ASSERT_TRUE(arm) << "the mesh still renders";
    EXPECT_LT(length(Vec3d(arm->positions[0]) - Vec3d{-1 + 5, -0.5 + 6, 5}), 1e-6) << "rest pose";
    std::size_t matching = 0;
    for (const std::string& w : p.warnings)
        matching += w.starts_with("/Char/Arm: UsdSkel binding not applied") && w.find(reason) != std::string::npos;
    EXPECT_EQ(matching, 1u) << ::testing::PrintToString(p.warnings);
}

TEST(Skel, AJointIndexOutOfRangeLeavesTheRestPose) {
    std::string usda = armScene();
    usda.replace(usda.find("[0, 1, 0, 1,"), 12, "[0, 7, 0, 1,");
    expectRestPoseWithOneWarning(usda, "primvars:skel:jointIndices[1] = 7 is out of range (2 joints)");
}

TEST(Skel, WeightsThatDoNotMatchTheIndicesLeaveTheRestPose) {
    std::string usda = armScene();
    usda.replace(usda.find("float[] primvars:skel:jointWeights = [") + 39, 0, "1, ");
    expectRestPoseWithOneWarning(usda,
                                 "primvars:skel:jointIndices has 20 values but primvars:skel:jointWeights has 21");
}

TEST(Skel, TooFewInfluencesForThePointsLeaveTheRestPose) {
    std::string usda = armScene();
    usda.replace(usda.find("elementSize = 2)\n        float"), 16, "elementSize = 4)");
    usda.replace(usda.find("elementSize = 2)\n        matrix"), 16, "elementSize = 4)");
    expectRestPoseWithOneWarning(
        usda,
        "the joint influences have 20 values but vertex interpolation with elementSize 4 over 10 points needs 40");
}

TEST(Skel, AMissingSkeletonLeavesTheRestPose) {
    std::string usda = armScene();
    usda.replace(usda.find("rel skel:skeleton = </Char/Skel>"), 32, "rel skel:skeleton = </Char/Gone>");
    expectRestPoseWithOneWarning(usda, "skel:skeleton targets /Char/Gone, which does not exist");
}

TEST(Skel, ASkeletonWithoutBindTransformsForEveryJointLeavesTheRestPose) {
    std::string usda = armScene();
    const std::string bind = "uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ";
    usda.replace(usda.find(bind), bind.size(), "uniform matrix4d[] bindTransforms = [");
    expectRestPoseWithOneWarning(usda, "has 1 bindTransforms for 2 joints");
}

TEST(Skel, AnAnimationOfMismatchedArraysFallsBackToTheRestTransforms) {
    std::string usda = armScene();
    usda.replace(usda.find("half3[] scales = [(1, 1, 1), (1, 1, 1)]"), 39, "half3[] scales = [(1, 1, 1)]");
    Populated p = populate(usda);
    ASSERT_TRUE(p.mesh("/Char/Arm"));
    // Rest pose of the joints: skinning is the identity, so the bound points sit in skeleton space.
    EXPECT_LT(length(Vec3d(p.mesh("/Char/Arm")->positions[0]) - Vec3d{0.5, 0.5, 0}), 1e-6);
    const std::vector<std::string> warnings = primWarnings(p.warnings);
    ASSERT_EQ(warnings.size(), 1u) << ::testing::PrintToString(warnings);
    EXPECT_NE(warnings[0].find("/Char/Skel/Anim animates 2 joints but has 2 translations, 2 rotations and 1 scales"),
              std::string::npos)
        << warnings[0];
}

TEST(Skel, SkelPrimsAreNotUnsupportedTypes) {
    Populated p = populate(armScene());
    for (const std::string& w : p.warnings) EXPECT_EQ(w.find("not supported"), std::string::npos) << w;
}

}  // namespace
}  // namespace fluence::delegate
