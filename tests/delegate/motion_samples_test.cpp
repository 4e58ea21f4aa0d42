// Motion blur read from the stage (delegate/motion_samples.h): the same motion authored as a
// time-sampled xform, as time-sampled points and as velocities gives the same positions at the
// shutter's ends; motion keyed inside the shutter gets a step of its own; a shutter that is an
// instant, --no-motion-blur and the render settings' disableMotionBlur give no motion at all.
#include <gtest/gtest.h>

#include "delegate/motion_samples.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

// The camera's shutter opens a quarter frame before the frame and closes a quarter after.
std::string cameraWithShutter(double open, double close) {
    return "def Camera \"Cam\"\n{\n    double shutter:open = " + std::to_string(open) +
           "\n    double shutter:close = " + std::to_string(close) + "\n}\n";
}

const std::string kQuadBody = R"(
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
)";

// A unit quad moving along +x at one unit per time code (24 per second), three ways.
const std::string kTransformed = R"(
def Xform "Mover"
{
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 0), 2: (2, 0, 0) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Mesh "Quad"
    {)" + kQuadBody + R"(
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    }
}
)";
const std::string kDeformed = R"(
def Xform "Mover"
{
    def Mesh "Quad"
    {)" + kQuadBody + R"(
        point3f[] points.timeSamples = { 0: [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], 2: [(2, 0, 0), (3, 0, 0), (3, 1, 0), (2, 1, 0)] }
    }
}
)";
const std::string kWithVelocities = R"(
def Xform "Mover"
{
    def Mesh "Quad"
    {)" + kQuadBody + R"(
        point3f[] points = [(1, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0)]
        vector3f[] velocities = [(24, 0, 0), (24, 0, 0), (24, 0, 0), (24, 0, 0)]
    }
}
)";

using Described = testing::Populated;

Described describeAt(const std::string& usda, double frame, bool motionBlur = true) {
    Described d;
    d.stage = testing::stageFrom(usda);
    DelegateOptions options = testing::testOptions(d);
    options.cameraPath = "/Cam";
    options.time = frame;
    options.motionBlur = motionBlur;
    d.result = populateScene(*d.stage, options);
    return d;
}

const render::MeshDesc& quad(const Described& d) {
    const render::MeshDesc* m = nullptr;
    for (const render::MeshDesc& mesh : d.result.scene.meshes)
        if (mesh.name == "/Mover/Quad") m = &mesh;
    EXPECT_NE(m, nullptr);
    return *m;
}

TEST(MotionSamples, TransformDeformationAndVelocityBlurOfTheSameMotionAgree) {
    for (const std::string* motion : {&kTransformed, &kDeformed, &kWithVelocities}) {
        const Described d = describeAt(cameraWithShutter(-0.25, 0.25) + *motion, 1.0);
        const render::MeshDesc& m = quad(d);
        ASSERT_EQ(m.motionPositions.size(), 2u) << *motion;  // nothing keyed inside the shutter: one segment
        // The frame's positions, and a quarter unit either side at the shutter's ends.
        EXPECT_NEAR(m.positions[0].x, 1.0f, 1e-6f);
        for (std::size_t i = 0; i < 4; ++i) {
            EXPECT_NEAR(m.motionPositions[0][i].x, m.positions[i].x - 0.25f, 1e-5f) << *motion;
            EXPECT_NEAR(m.motionPositions[1][i].x, m.positions[i].x + 0.25f, 1e-5f) << *motion;
            EXPECT_EQ(m.motionPositions[1][i].y, m.positions[i].y);
        }
        EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
    }
}

TEST(MotionSamples, CurvesAndPointsMoveByTheirSampledPointsWidthsAndVelocities) {
    // Over [0.75, 1.25]: the hair's points move a quarter unit either side and its widths grow
    // from 0.175 to 0.225; the sparks, not time-sampled, move by their velocities.
    const Described d = describeAt(cameraWithShutter(-0.25, 0.25) + R"(
def BasisCurves "Hair"
{
    uniform token type = "linear"
    int[] curveVertexCounts = [2]
    point3f[] points.timeSamples = { 0: [(0, 0, 0), (0, 1, 0)], 2: [(2, 0, 0), (2, 1, 0)] }
    float[] widths.timeSamples = { 0: [0.1, 0.1], 2: [0.3, 0.3] }
    uniform token widths:interpolation = "vertex"
}
def Points "Sparks"
{
    point3f[] points = [(1, 0, 0), (1, 2, 0)]
    vector3f[] velocities = [(24, 0, 0), (0, 24, 0)]
    float[] widths = [0.1, 0.1]
}
def Points "Still"
{
    point3f[] points = [(5, 0, 0)]
}
)",
                                   1.0);
    ASSERT_EQ(d.result.scene.curves.size(), 1u);
    const render::CurvesDesc& hair = d.result.scene.curves.front();
    ASSERT_EQ(hair.motionPoints.size(), 2u);
    ASSERT_EQ(hair.motionRadii.size(), 2u);
    for (std::size_t i = 0; i < hair.points.size(); ++i) {
        EXPECT_NEAR(hair.motionPoints[0][i].x, hair.points[i].x - 0.25f, 1e-5f);
        EXPECT_NEAR(hair.motionPoints[1][i].x, hair.points[i].x + 0.25f, 1e-5f);
        EXPECT_NEAR(hair.motionRadii[0][i], 0.0875f, 1e-6f);
        EXPECT_NEAR(hair.motionRadii[1][i], 0.1125f, 1e-6f);
    }
    ASSERT_EQ(d.result.scene.points.size(), 2u);
    const render::PointsDesc& sparks = d.result.scene.points[0];
    ASSERT_EQ(sparks.motionPositions.size(), 2u);
    EXPECT_TRUE(sparks.motionRadii.empty());  // the widths do not change
    EXPECT_NEAR(sparks.motionPositions[0][0].x, 0.75f, 1e-5f);
    EXPECT_NEAR(sparks.motionPositions[1][0].x, 1.25f, 1e-5f);
    EXPECT_NEAR(sparks.motionPositions[0][1].y, 1.75f, 1e-5f);
    EXPECT_NEAR(sparks.motionPositions[1][1].y, 2.25f, 1e-5f);
    EXPECT_EQ(sparks.positions[0].x, 1.0f);  // the frame's
    EXPECT_TRUE(d.result.scene.points[1].motionPositions.empty());
    EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
}

TEST(MotionSamples, ATimeSampledCameraGetsItsTransformAtEachStep) {
    const Described d = describeAt(R"(
def Camera "Cam"
{
    double shutter:open = -0.25
    double shutter:close = 0.25
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 5), 2: (2, 0, 5) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)" + kDeformed,
                                   1.0);
    ASSERT_TRUE(d.result.scene.camera);
    const render::CameraDesc& camera = *d.result.scene.camera;
    ASSERT_EQ(camera.motionTransforms.size(), 2u);
    EXPECT_NEAR(camera.motionTransforms[0].m[0][3], 0.75, 1e-9);
    EXPECT_NEAR(camera.motionTransforms[1].m[0][3], 1.25, 1e-9);
    EXPECT_NEAR(camera.transform.m[0][3], 1.0, 1e-9);  // the frame's
    // A still camera gets none.
    EXPECT_TRUE(
        describeAt(cameraWithShutter(-0.25, 0.25) + kDeformed, 1.0).result.scene.camera->motionTransforms.empty());
}

// A zoom and a focus pull during the shutter: the lens at each step, interpolated as USD reads it.
TEST(MotionSamples, ATimeSampledLensGetsItsValuesAtEachStep) {
    const Described d = describeAt(R"(
def Camera "Cam"
{
    double shutter:open = -0.25
    double shutter:close = 0.25
    float focalLength.timeSamples = { 0: 30, 2: 70 }
    float focusDistance.timeSamples = { 0: 2, 2: 6 }
    float fStop = 4
}
)" + kDeformed,
                                   1.0);
    ASSERT_TRUE(d.result.scene.camera);
    const render::CameraDesc& camera = *d.result.scene.camera;
    EXPECT_TRUE(camera.motionTransforms.empty());  // it does not move
    ASSERT_EQ(camera.motionLenses.size(), 2u);
    EXPECT_NEAR(camera.motionLenses[0].focalLength, 45.0f, 1e-4f);
    EXPECT_NEAR(camera.motionLenses[1].focalLength, 55.0f, 1e-4f);
    EXPECT_NEAR(camera.motionLenses[0].focusDistance, 3.5f, 1e-5f);
    EXPECT_NEAR(camera.motionLenses[1].focusDistance, 4.5f, 1e-5f);
    EXPECT_EQ(camera.motionLenses[1].fStop, 4.0f);
    EXPECT_NEAR(camera.focalLength, 50.0f, 1e-4f);  // the frame's
    EXPECT_TRUE(describeAt(cameraWithShutter(-0.25, 0.25) + kDeformed, 1.0).result.scene.camera->motionLenses.empty());
}

TEST(MotionSamples, CurvesWhoseCountChangesRenderStillWithAWarning) {
    const Described d = describeAt(cameraWithShutter(-0.25, 0.25) + R"(
def BasisCurves "Hair"
{
    uniform token type = "linear"
    int[] curveVertexCounts.timeSamples = { 0: [2], 1.1: [3] }
    point3f[] points.timeSamples = { 0: [(0, 0, 0), (0, 1, 0)], 1.1: [(0, 0, 0), (0, 1, 0), (0, 2, 0)] }
    float[] widths = [0.1]
    uniform token widths:interpolation = "constant"
}
)",
                                   1.0);
    ASSERT_EQ(d.result.scene.curves.size(), 1u);
    EXPECT_TRUE(d.result.scene.curves.front().motionPoints.empty());
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings.front().find("its curves change during the shutter"), std::string::npos) << d.warnings.front();
}

TEST(MotionSamples, MotionKeyedInsideTheShutterGetsAStepOnEachKey) {
    // Right until the frame, then up: the key at time 1 lies inside [0.5, 1.5].
    const Described d = describeAt(cameraWithShutter(-0.5, 0.5) + R"(
def Xform "Mover"
{
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 0), 1: (1, 0, 0), 2: (1, 1, 0) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Mesh "Quad"
    {)" + kQuadBody + R"(
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    }
}
)",
                                   1.0);
    const render::MeshDesc& m = quad(d);
    ASSERT_EQ(m.motionPositions.size(), 3u);
    EXPECT_NEAR(m.motionPositions[0][0].x, 0.5f, 1e-6f);
    EXPECT_NEAR(m.motionPositions[0][0].y, 0.0f, 1e-6f);
    EXPECT_NEAR(m.motionPositions[1][0].x, 1.0f, 1e-6f);  // the corner of the path, exactly
    EXPECT_NEAR(m.motionPositions[1][0].y, 0.0f, 1e-6f);
    EXPECT_NEAR(m.motionPositions[2][0].x, 1.0f, 1e-6f);
    EXPECT_NEAR(m.motionPositions[2][0].y, 0.5f, 1e-6f);
}

TEST(MotionSamples, StepTimesAreEvenAndFewAsTheKeysAllow) {
    const auto stage = testing::stageFrom(R"(
def Xform "A"
{
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 0), 1.25: (1, 0, 0), 1.5: (2, 0, 0), 9: (3, 0, 0) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)");
    // Keys at 1.25 and 1.5 inside [1, 2]: quarter steps.
    EXPECT_EQ(motionStepTimes(*stage, 1.0, 0.0, 1.0), (std::vector<double>{1.0, 1.25, 1.5, 1.75, 2.0}));
    // No key inside [2, 3]: its two ends.
    EXPECT_EQ(motionStepTimes(*stage, 2.0, 0.0, 1.0), (std::vector<double>{2.0, 3.0}));
}

TEST(MotionSamples, AnInstantaneousOrDisabledShutterGivesNoMotion) {
    // open == close (USD's default is 0 and 0): the scene as without motion blur.
    const Described instant = describeAt(cameraWithShutter(0.25, 0.25) + kTransformed, 1.0);
    const Described none = describeAt(testing::kCamera + kTransformed, 1.0);
    EXPECT_TRUE(quad(instant).motionPositions.empty());
    EXPECT_EQ(quad(instant).positions, quad(none).positions);
    // --no-motion-blur.
    EXPECT_TRUE(quad(describeAt(cameraWithShutter(-0.25, 0.25) + kTransformed, 1.0, false)).motionPositions.empty());
    // The render settings' disableMotionBlur, as husk reads it.
    const std::string settings = R"(#usda 1.0
(
    renderSettingsPrimPath = "/Render/Settings"
)
def Scope "Render"
{
    def RenderSettings "Settings"
    {
        rel camera = </Cam>
        uniform bool disableMotionBlur = true
    }
}
)";
    EXPECT_TRUE(
        quad(describeAt(settings + cameraWithShutter(-0.25, 0.25) + kTransformed, 1.0)).motionPositions.empty());
    // Without a frame there is nothing for the shutter to open around.
    EXPECT_TRUE(
        quad(describeAt(cameraWithShutter(-0.25, 0.25) + kTransformed, usd::kDefaultTime)).motionPositions.empty());
}

TEST(MotionSamples, PointInstancerVelocitiesAndAngularVelocitiesMoveTheInstances) {
    const Described d = describeAt(cameraWithShutter(-0.5, 0.5) + R"(
def PointInstancer "Spray"
{
    rel prototypes = [</Spray/Protos/Dot>]
    int[] protoIndices = [0]
    point3f[] positions = [(1, 0, 0)]
    vector3f[] velocities = [(0, 48, 0)]
    vector3f[] angularVelocities = [(0, 0, 2160)]
    def Scope "Protos"
    {
        def Mesh "Dot"
        {)" + kQuadBody + R"(
            point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
        }
    }
}
)",
                                   1.0);
    const auto& instances = d.result.scene.instances;
    ASSERT_EQ(instances.size(), 1u);
    ASSERT_EQ(instances[0].motionTransforms.size(), 2u);
    // Half a frame is 1/48 s: one unit down and up along y, and a turn of 45 degrees either way.
    const Vec3d open = instances[0].motionTransforms[0].transformPoint({1, 0, 0});
    const Vec3d close = instances[0].motionTransforms[1].transformPoint({1, 0, 0});
    const double r = std::sqrt(0.5);
    EXPECT_NEAR(open.x, 1.0 + r, 1e-9);
    EXPECT_NEAR(open.y, -1.0 - r, 1e-9);
    EXPECT_NEAR(close.x, 1.0 + r, 1e-9);
    EXPECT_NEAR(close.y, 1.0 + r, 1e-9);
}

// A UsdLux light under a time-sampled xform keyed inside the shutter gets its light-to-world at
// each step (a step on the key: right, then back), and a still light none.
TEST(MotionSamples, ALightGetsItsTransformAtEachStep) {
    const Described d = describeAt(cameraWithShutter(-0.5, 0.5) + R"(
def Xform "Rig"
{
    double3 xformOp:translate.timeSamples = { 0: (0, 0, 3), 1: (1, 0, 3), 2: (0, 0, 3) }
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def SphereLight "Bulb"
    {
        float inputs:radius = 0.1
    }
}
def RectLight "Still"
{
}
)",
                                   1.0);
    const render::LightDesc* bulb = nullptr;
    const render::LightDesc* still = nullptr;
    for (const render::LightDesc& light : d.result.scene.lights) {
        if (light.name == "/Rig/Bulb") bulb = &light;
        if (light.name == "/Still") still = &light;
    }
    ASSERT_NE(bulb, nullptr);
    ASSERT_NE(still, nullptr);
    ASSERT_EQ(bulb->motionTransforms.size(), 3u);
    EXPECT_NEAR(bulb->motionTransforms[0].m[0][3], 0.5, 1e-9);
    EXPECT_NEAR(bulb->motionTransforms[1].m[0][3], 1.0, 1e-9);  // the key inside the shutter, exactly
    EXPECT_NEAR(bulb->motionTransforms[2].m[0][3], 0.5, 1e-9);
    EXPECT_NEAR(bulb->transform.m[0][3], 1.0, 1e-9);  // the frame's
    EXPECT_TRUE(still->motionTransforms.empty());
}

}  // namespace
}  // namespace fluence::delegate
