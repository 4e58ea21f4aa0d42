// Curves whose `points` are not time-sampled move by their `velocities` and `accelerations` over
// the shutter (delegate/motion_samples.h), as meshes and points do: a curve with velocities gets
// the time steps of its twin whose points are sampled along the same motion, control point for
// control point (pinned phantom points and NURBS samples included); accelerations add their
// half a t squared.
#include <gtest/gtest.h>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

// The shutter opens a quarter frame before the frame and closes a quarter after (24 codes per second).
const std::string kCamera =
    "def Camera \"Cam\"\n{\n    double shutter:open = -0.25\n    double shutter:close = 0.25\n}\n";

// Four points, the second and third moving at 24 and 48 units per second.
const std::string kPoints = "[(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)]";
const std::string kVelocities = "[(0, 0, 0), (24, 0, 0), (0, 48, 0), (0, 0, 0)]";
// The same motion keyed: at codes 0 and 2, one second's 24th before and after the frame (1).
const std::string kSampledPoints =
    "{ 0: [(0, 0, 0), (0, 1, 0), (2, -2, 0), (3, 1, 0)], 2: [(0, 0, 0), (2, 1, 0), (2, 2, 0), (3, 1, 0)] }";

// A pinned Catmull-Rom curve (phantom end points) and a cubic NURBS curve over the points.
std::string curves(const std::string& pointsLine) {
    return R"(
def BasisCurves "Pinned"
{
    uniform token type = "cubic"
    uniform token basis = "catmullRom"
    uniform token wrap = "pinned"
    int[] curveVertexCounts = [4]
    float[] widths = [0.1]
)" + pointsLine +
           R"(
}
def NurbsCurves "Nurbs"
{
    int[] curveVertexCounts = [4]
    int[] order = [4]
    double[] knots = [0, 0, 0, 0, 1, 1, 1, 1]
    float[] widths = [0.1]
)" + pointsLine +
           R"(
}
)";
}

// A linear BasisCurves prim of one curve of two vertices; `lines` authors its points and motion.
std::string linearCurve(const std::string& name, const std::string& lines) {
    return "def BasisCurves \"" + name +
           "\"\n{\n    uniform token type = \"linear\"\n    int[] curveVertexCounts = [2]" + lines + "}\n";
}

testing::Populated describe(const std::string& usda) {
    testing::Populated d;
    d.stage = testing::stageFrom(kCamera + usda);
    DelegateOptions options = testing::testOptions(d);
    options.cameraPath = "/Cam";
    options.time = 1.0;
    d.result = populateScene(*d.stage, options);
    return d;
}

TEST(CurveVelocities, ACurveWithVelocitiesBlursAsItsTwinWithSampledPoints) {
    const testing::Populated moving =
        describe(curves("point3f[] points = " + kPoints + "\nvector3f[] velocities = " + kVelocities));
    const testing::Populated sampled = describe(curves("point3f[] points.timeSamples = " + kSampledPoints));
    ASSERT_EQ(moving.result.scene.curves.size(), 2u);
    ASSERT_EQ(sampled.result.scene.curves.size(), 2u);
    for (std::size_t c = 0; c < 2; ++c) {
        const render::CurvesDesc& a = moving.result.scene.curves[c];
        const render::CurvesDesc& b = sampled.result.scene.curves[c];
        ASSERT_EQ(a.motionPoints.size(), 2u) << a.name;
        ASSERT_EQ(b.motionPoints.size(), 2u) << b.name;
        ASSERT_EQ(a.points.size(), b.points.size()) << a.name;
        for (std::size_t step = 0; step < 2; ++step)
            for (std::size_t i = 0; i < a.points.size(); ++i)
                EXPECT_LT(length(Vec3d(a.motionPoints[step][i]) - Vec3d(b.motionPoints[step][i])), 1e-5)
                    << a.name << " step " << step << " control point " << i;
        for (std::size_t i = 0; i < a.points.size(); ++i)  // the frame's own points are the authored ones
            EXPECT_LT(length(Vec3d(a.points[i]) - Vec3d(b.points[i])), 1e-6) << a.name << " control point " << i;
        EXPECT_TRUE(a.motionRadii.empty());
    }
    // The second point of the pinned curve (its control point 2, after the phantom one) moves a
    // quarter unit either side along x.
    const render::CurvesDesc& pinned = moving.result.scene.curves[0];
    EXPECT_NEAR(pinned.motionPoints[0][2].x, 0.75f, 1e-6f);
    EXPECT_NEAR(pinned.motionPoints[1][2].x, 1.25f, 1e-6f);
    EXPECT_TRUE(moving.warnings.empty()) << moving.warnings.front();
}

TEST(CurveVelocities, AccelerationsAddHalfATSquared) {
    const testing::Populated d = describe(linearCurve("Hair", R"(
    point3f[] points = [(0, 0, 0), (0, 1, 0)]
    vector3f[] velocities = [(24, 0, 0), (24, 0, 0)]
    vector3f[] accelerations = [(0, 0, 0), (0, 0, 1152)]
)"));
    ASSERT_EQ(d.result.scene.curves.size(), 1u);
    const render::CurvesDesc& hair = d.result.scene.curves[0];
    ASSERT_EQ(hair.motionPoints.size(), 2u);
    const double dt = 0.25 / 24.0;  // seconds from the frame to either end of the shutter
    for (int step = 0; step < 2; ++step) {
        const double t = step == 0 ? -dt : dt;
        EXPECT_NEAR(hair.motionPoints[step][0].x, 24.0 * t, 1e-6);
        EXPECT_NEAR(hair.motionPoints[step][1].x, 24.0 * t, 1e-6);
        EXPECT_NEAR(hair.motionPoints[step][1].z, 0.5 * 1152.0 * t * t, 1e-6);
        EXPECT_EQ(hair.motionPoints[step][0].z, 0.0f);
    }
}

TEST(CurveVelocities, VelocitiesOfTheWrongCountOrSampledPointsLeaveThemToTheirSamples) {
    // Three velocities for two points move nothing; sampled points ignore velocities.
    const testing::Populated d = describe(linearCurve("Wrong", R"(
    point3f[] points = [(0, 0, 0), (0, 1, 0)]
    vector3f[] velocities = [(24, 0, 0), (24, 0, 0), (24, 0, 0)]
)") + linearCurve("Keyed", R"(
    point3f[] points.timeSamples = { 0: [(0, 0, 0), (0, 1, 0)], 2: [(0, 0, 2), (0, 1, 2)] }
    vector3f[] velocities = [(24, 0, 0), (24, 0, 0)]
)"));
    ASSERT_EQ(d.result.scene.curves.size(), 2u);
    EXPECT_TRUE(d.result.scene.curves[0].motionPoints.empty());
    const render::CurvesDesc& keyed = d.result.scene.curves[1];
    ASSERT_EQ(keyed.motionPoints.size(), 2u);
    EXPECT_EQ(keyed.motionPoints[0][0].x, 0.0f);
    EXPECT_NEAR(keyed.motionPoints[0][0].z, 0.75f, 1e-6f);
    EXPECT_NEAR(keyed.motionPoints[1][0].z, 1.25f, 1e-6f);
}

}  // namespace
}  // namespace fluence::delegate
