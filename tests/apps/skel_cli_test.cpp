// End-to-end UsdSkel: a skinned mesh renders, frame by frame (-f 1 -n 2), as its statically posed
// twin whose points this test computes from the joint transforms by hand (delegate/skel_binding.h).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/skel_strip_scene.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// The strip and its twin: tests/support/skel_strip_scene.h.
const std::string kHeader = test::skel_strip::stripStage("", 8);

std::string skinnedScene() { return kHeader + test::skel_strip::skinnedRoot("def", "Root"); }

std::string twinScene() { return kHeader + test::skel_strip::posedStrip(); }

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
