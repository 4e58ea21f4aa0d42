// End-to-end: several frames from one call (-f, -n, -i), frame tokens in output paths
// (apps/frame_tokens.h), --make-output-path; each frame's image is bit-identical to rendering that
// frame alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "apps/frame_tokens.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

TEST(FrameTokens, ExpandAsHuskWritesThem) {
    EXPECT_EQ(app::expandFrameTokens("out.$F4.exr", 7), "out.0007.exr");
    EXPECT_EQ(app::expandFrameTokens("out.$F.exr", 12), "out.12.exr");
    EXPECT_EQ(app::expandFrameTokens("out.$FF.exr", 7.5), "out.7.5.exr");
    EXPECT_EQ(app::expandFrameTokens("out.%04d.exr", 42), "out.0042.exr");
    EXPECT_EQ(app::expandFrameTokens("out.%d.exr", 42), "out.42.exr");
    EXPECT_EQ(app::expandFrameTokens("f$F3/img_$F2.exr", -7), "f-007/img_-07.exr");
    EXPECT_EQ(app::expandFrameTokens("100%.exr", 3), "100%.exr");
    EXPECT_TRUE(app::hasFrameToken("a.$F4.exr"));
    EXPECT_TRUE(app::hasFrameToken("a.%03d.exr"));
    EXPECT_FALSE(app::hasFrameToken("a.exr"));
    EXPECT_FALSE(app::hasFrameToken("100%.exr"));
}

class FramesCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_frames_cli"};

    // The furnace sphere moving along x over time codes 1 to 4.
    std::string animatedScene() {
        std::string usda = test::furnaceUsda(0.5);
        const std::string subdiv = "        uniform token subdivisionScheme = \"none\"\n";
        usda.replace(usda.find(subdiv), subdiv.size(),
                     subdiv +
                         "        double3 xformOp:translate.timeSamples = {1: (-0.6, 0, 0), 4: (0.6, 0, 0)}\n"
                         "        uniform token[] xformOpOrder = [\"xformOp:translate\"]\n");
        const std::string path = tmp_.file("animated.usda");
        std::ofstream(path) << usda;
        return path;
    }
    RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
};

bool samePixels(const test::ExrImage& a, const test::ExrImage& b) {
    return a.channels == b.channels && a.pixels == b.pixels;
}

TEST_F(FramesCli, EachFrameIsTheImageOfThatFrameAlone) {
    const std::string scene = animatedScene();
    RunResult r = run("render " + scene + " -r 12 12 --spp 2 -f 1 -n 3 -i 1.5 --make-output-path -o '" +
                      tmp_.file("seq/$F4/img.%03d.exr") + "'");  // quoted: the shell would expand $F4
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const auto& [time, file] :
         {std::pair{1.0, "seq/0001/img.001.exr"}, {2.5, "seq/0003/img.003.exr"}, {4.0, "seq/0004/img.004.exr"}}) {
        ASSERT_TRUE(fs::exists(tmp_.file(file))) << file;
        RunResult single =
            run("render " + scene + " -r 12 12 --spp 2 -f " + std::to_string(time) + " -o " + tmp_.file("single.exr"));
        ASSERT_EQ(single.exitCode, 0) << single.err;
        EXPECT_TRUE(samePixels(test::readExr(tmp_.file(file)), test::readExr(tmp_.file("single.exr")))) << file;
    }
    EXPECT_FALSE(
        samePixels(test::readExr(tmp_.file("seq/0001/img.001.exr")), test::readExr(tmp_.file("seq/0004/img.004.exr"))))
        << "the sphere moves";
}

TEST_F(FramesCli, SeveralFramesNeedAFrameToken) {
    RunResult r = run("render " + animatedScene() + " -r 8 8 --spp 1 -f 1 -n 2 -o " + tmp_.file("same.exr"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("frame token"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("same.exr")));
}

TEST_F(FramesCli, BadFrameOptionsAreUsageErrors) {
    EXPECT_EQ(run("render " + animatedScene() + " -n 0").exitCode, 2);
    EXPECT_EQ(run("render " + animatedScene() + " -i -1").exitCode, 2);
}

TEST_F(FramesCli, WithoutMakeOutputPathAMissingFolderIsAnOutputError) {
    RunResult r = run("render " + animatedScene() + " -r 8 8 --spp 1 -f 1 -o " + tmp_.file("nowhere/img.exr"));
    EXPECT_EQ(r.exitCode, 5) << r.err;
}

// --summary: one entry per frame with its output and sample counts; on failure the exit code.
TEST_F(FramesCli, SummaryRecordsEveryFrameAndTheExitCode) {
    RunResult r = run("render " + animatedScene() + " -r 8 8 --spp 2 -f 1 -n 2 -o '" + tmp_.file("f.$F.exr") +
                      "' --summary " + tmp_.file("run.json"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string json = test::slurp(tmp_.file("run.json"));
    EXPECT_NE(json.find("\"exitCode\": 0"), std::string::npos) << json;
    EXPECT_NE(json.find("\"output\": \"" + tmp_.file("f.1.exr") + "\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"output\": \"" + tmp_.file("f.2.exr") + "\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"samples\": 128"), std::string::npos) << json;  // 8 x 8 x 2 per frame
    EXPECT_NE(json.find("\"peakMemoryBytes\": "), std::string::npos) << json;
    EXPECT_NE(json.find("\"renderCpu\": "), std::string::npos) << json;
    EXPECT_NE(r.out.find(" s CPU), write "), std::string::npos) << r.out;  // beside the render's wall time

    r = run("render " + tmp_.file("missing.usda") + " --summary " + tmp_.file("failed.json"));
    EXPECT_EQ(r.exitCode, 4);
    const std::string failed = test::slurp(tmp_.file("failed.json"));
    EXPECT_NE(failed.find("\"exitCode\": 4"), std::string::npos) << failed;
    EXPECT_NE(failed.find("\"frames\": []"), std::string::npos) << failed;
}

}  // namespace
}  // namespace fluence
