// Deformation inside shared prototypes, rendered (delegate/motion_steps.h, PrototypeMotionSteps):
// two native instances of a skinned SkelRoot whose animation moves during the shutter blur as two
// un-instanced copies of its hand-posed twin (tests/support/skel_strip_scene.h), and two instances
// of a mesh with time-sampled points blur as two un-instanced copies of it. Same seed and samples:
// each pair of images may differ only where a sample's hit moves across an edge by float rounding
// (the instance's transform applied to the ray instead of the points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/skel_strip_scene.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// The shutter spans codes 1 to 2 from frame 1, where both motions are keyed.
const std::string kHeader =
    test::skel_strip::stripStage("    double shutter:open = 0\n    double shutter:close = 1\n", 16);

// Two places, apart and at different depths, each holding `content`.
std::string twoPlaces(const std::string& content) {
    return "def Xform \"A\"\n{\n    double3 xformOp:translate = (-1.2, 1, 0)\n"
           "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n" +
           content + "}\ndef Xform \"B\"\n{\n    double3 xformOp:translate = (1.2, -1.5, -1)\n" +
           "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n" + content + "}\n";
}

// An instance of the class prim `prototype`.
std::string instanceOf(const std::string& type, const std::string& prototype) {
    return "def " + type + " \"Copy\" (instanceable = true; references = </" + prototype + ">) {}\n";
}

// A quad whose right edge slides one unit right between codes 1 and 2.
std::string slidingQuad() {
    return R"(def Mesh "Quad"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points.timeSamples = {
        1: [(-1, -0.5, 0), (0, -0.5, 0), (0, 0.5, 0), (-1, 0.5, 0)],
        2: [(-1, -0.5, 0), (1, -0.5, 0), (1, 0.5, 0), (-1, 0.5, 0)],
    }
}
)";
}

// The prototype holding it (an instance's own prim is not part of its prototype).
std::string slidingThing() { return "class Xform \"Thing\"\n{\n" + slidingQuad() + "}\n"; }

constexpr int kSpp = 16;

class InstancedDeformationCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_instanced_deformation"};

    test::ExrImage render(const std::string& name, const std::string& usda, const std::string& options = "") {
        const std::string scene = tmp_.file(name + ".usda");
        std::ofstream(scene) << usda;
        const test::RunResult r = test::runFluence("render " + scene + " -r 64 64 --spp " + std::to_string(kSpp) +
                                                       " -f 1 " + options + " -o '" + tmp_.file(name + ".exr") + "'",
                                                   tmp_.path());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("without motion blur"), std::string::npos) << r.err;
        return test::readExr(tmp_.file(name + ".exr"));
    }

    // Pixels with partial coverage: what a blur smears.
    static int partiallyCovered(const test::ExrImage& image) {
        int n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) n += image.at(x, y, "A") > 0.05f && image.at(x, y, "A") < 0.95f;
        return n;
    }

    // `instanced` renders as `twin`: the same pixels but where a sample changes side of an edge,
    // which moves a pixel by at most one sample's share (the brightest pixel / kSpp per sample).
    static void expectSame(const test::ExrImage& instanced, const test::ExrImage& twin) {
        ASSERT_EQ(instanced.pixels.size(), twin.pixels.size());
        float brightest = 0.0f;
        for (float v : twin.pixels) brightest = std::max(brightest, v);
        int differing = 0, covered = 0;
        for (int y = 0; y < twin.height; ++y)
            for (int x = 0; x < twin.width; ++x) {
                covered += twin.at(x, y, "A") > 0.0f;
                double worst = 0.0;
                for (const char* c : {"R", "G", "B", "A"})
                    worst = std::max(worst, double(std::abs(instanced.at(x, y, c) - twin.at(x, y, c))));
                differing += worst > 1e-3;
                EXPECT_LE(worst, 2.0 * brightest / kSpp) << "pixel " << x << ", " << y;
            }
        EXPECT_GT(covered, 200) << "both copies are in view";
        EXPECT_LE(differing, covered / 50) << "at most 2% of the covered pixels differ, each by a sample or two";
    }
};

TEST_F(InstancedDeformationCli, AnInstancedSkinnedMeshBlursAsItsPosedTwin) {
    const test::ExrImage instanced = render("skinned", kHeader + test::skel_strip::skinnedRoot("class", "Agent") +
                                                           twoPlaces(instanceOf("SkelRoot", "Agent")));
    const test::ExrImage twin = render("twin", kHeader + twoPlaces(test::skel_strip::posedStrip()));
    expectSame(instanced, twin);
    const test::ExrImage still = render(
        "still", kHeader + test::skel_strip::skinnedRoot("class", "Agent") + twoPlaces(instanceOf("SkelRoot", "Agent")),
        "--no-motion-blur");
    EXPECT_GT(partiallyCovered(instanced), partiallyCovered(still) + 40) << "the turning half smears";
}

TEST_F(InstancedDeformationCli, AnInstancedMeshWithTimeSampledPointsBlursAsItsUninstancedTwin) {
    const test::ExrImage instanced =
        render("sliding", kHeader + slidingThing() + twoPlaces(instanceOf("Xform", "Thing")));
    const test::ExrImage twin = render("twin", kHeader + twoPlaces(slidingQuad()));
    expectSame(instanced, twin);
    const test::ExrImage still =
        render("still", kHeader + slidingThing() + twoPlaces(instanceOf("Xform", "Thing")), "--no-motion-blur");
    EXPECT_GT(partiallyCovered(instanced), partiallyCovered(still) + 40) << "the sliding edge smears";
}

}  // namespace
}  // namespace fluence
