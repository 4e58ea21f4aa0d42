// End-to-end UsdSkel: a skinned mesh renders, frame by frame (-f 1 -n 2), as its statically posed
// twin whose points this test computes from the joint transforms by hand (delegate/skel_binding.h).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/matrix.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// A strip of 2 quads along x from -1 to 1: the left column bound to joint J, the middle half to J
// and half to J/K, the right column to K; K (bound at x = 0) turns about z by 0° at frame 1 and
// 50° at frame 2 while J moves.
struct Pose {
    double kDegrees;
    Vec3d jTranslate;
};
constexpr Pose kPoses[] = {{0.0, {0.25, 0.0, 0.0}}, {50.0, {-0.25, 0.5, 0.0}}};
constexpr double kWeightJ[] = {1.0, 0.5, 0.0};

const std::string kHeader = R"(#usda 1.0
(
    startTimeCode = 1
    endTimeCode = 2
)
def Camera "Cam"
{
    double3 xformOp:translate = (0, 0, 8)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def DistantLight "Sun"
{
    float inputs:intensity = 2
}
)";
const std::string kTopology = R"(
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4, 4]
        int[] faceVertexIndices = [0, 1, 4, 3, 1, 2, 5, 4]
)";

std::string number(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

std::string vec(const Vec3d& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

Vec3d restPoint(int i) { return {static_cast<double>(i % 3) - 1.0, i < 3 ? -0.5 : 0.5, 0.0}; }

std::string skinnedScene() {
    std::string points, indices, weights;
    for (int i = 0; i < 6; ++i) {
        points += vec(restPoint(i)) + ", ";
        indices += "0, 1, ";
        weights += number(kWeightJ[i % 3]) + ", " + number(1.0 - kWeightJ[i % 3]) + ", ";
    }
    std::string translations, rotations;
    for (int f = 0; f < 2; ++f) {
        const double half = kPoses[f].kDegrees * std::numbers::pi / 360.0;
        translations += std::to_string(f + 1) + ": [" + vec(kPoses[f].jTranslate) + ", (1, 0, 0)], ";
        rotations += std::to_string(f + 1) + ": [(1, 0, 0, 0), (" + number(std::cos(half)) + ", 0, 0, " +
                     number(std::sin(half)) + ")], ";
    }
    return kHeader + R"(
def SkelRoot "Root"
{
    def Skeleton "Skel"
    {
        uniform token[] joints = ["J", "J/K"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        rel skel:animationSource = </Root/Skel/Anim>
        def SkelAnimation "Anim"
        {
            uniform token[] joints = ["J", "J/K"]
            float3[] translations.timeSamples = {)" +
           translations + R"(}
            quatf[] rotations.timeSamples = {)" +
           rotations + R"(}
            half3[] scales = [(1, 1, 1), (1, 1, 1)]
        }
    }
    def Mesh "Strip" (prepend apiSchemas = ["SkelBindingAPI"])
    {)" + kTopology +
           R"(
        point3f[] points = [)" +
           points + R"(]
        int[] primvars:skel:jointIndices = [)" +
           indices + R"(] (
            interpolation = "vertex"
            elementSize = 2
        )
        float[] primvars:skel:jointWeights = [)" +
           weights + R"(] (
            interpolation = "vertex"
            elementSize = 2
        )
        rel skel:skeleton = </Root/Skel>
    }
}
)";
}

// The twin: the strip's points posed by hand, J = T(jTranslate), K = J · T(1, 0, 0) · Rz, bound
// at the origin (K's bind transform is the identity, so its skinning transform is K itself).
std::string twinScene() {
    std::string samples;
    for (int f = 0; f < 2; ++f) {
        const Matrix4 j = Matrix4::translate(kPoses[f].jTranslate);
        const Matrix4 k = j * Matrix4::translate({1, 0, 0}) * Matrix4::rotateZ(kPoses[f].kDegrees);
        samples += std::to_string(f + 1) + ": [";
        for (int i = 0; i < 6; ++i) {
            const double w = kWeightJ[i % 3];
            samples += vec(j.transformPoint(restPoint(i)) * w + k.transformPoint(restPoint(i)) * (1.0 - w)) + ", ";
        }
        samples += "], ";
    }
    return kHeader + R"(
def Mesh "Strip"
{)" + kTopology +
           R"(
    point3f[] points.timeSamples = {)" +
           samples + R"(}
}
)";
}

class SkelCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_skel_cli"};
    std::string write(const std::string& name, const std::string& usda) {
        const std::string path = tmp_.file(name);
        std::ofstream(path) << usda;
        return path;
    }
    void render(const std::string& scene, const std::string& output) {
        test::RunResult r = test::runFluence(
            "render " + scene + " -r 48 48 --spp 4 -f 1 -n 2 -o '" + tmp_.file(output) + "'", tmp_.path());
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("UsdSkel binding not applied"), std::string::npos) << r.err;
    }
};

TEST_F(SkelCli, ASkinnedMeshRendersAsItsHandPosedTwinAtEachFrame) {
    render(write("skinned.usda", skinnedScene()), "skinned.$F.exr");
    render(write("twin.usda", twinScene()), "twin.$F.exr");
    double covered[2] = {0.0, 0.0};
    for (int frame = 1; frame <= 2; ++frame) {
        const test::ExrImage skinned = test::readExr(tmp_.file("skinned." + std::to_string(frame) + ".exr"));
        const test::ExrImage twin = test::readExr(tmp_.file("twin." + std::to_string(frame) + ".exr"));
        ASSERT_EQ(skinned.pixels.size(), twin.pixels.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < skinned.pixels.size(); ++i)
            worst = std::max(worst, double(std::abs(skinned.pixels[i] - twin.pixels[i])));
        // The poses agree to float rounding (the animation's quaternions are floats): no sample
        // changes side of an edge, so the pixels agree to a rounding of the shading.
        EXPECT_LT(worst, 1e-3) << "frame " << frame;
        for (int y = 0; y < skinned.height; ++y)
            for (int x = 0; x < skinned.width; ++x) covered[frame - 1] += skinned.at(x, y, "A");
    }
    EXPECT_GT(covered[0], 20.0) << "the strip is in view";
    // Frame 2 bends the strip (the area seen changes with the fold): the frames differ.
    EXPECT_NE(covered[0], covered[1]);
}

}  // namespace
}  // namespace fluence
