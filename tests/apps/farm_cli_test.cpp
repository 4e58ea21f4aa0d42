// End-to-end: `fluence farm` with the local backend. A 2x2 tile render whose task 2 fails on its
// first attempt (the FLUENCE_FARM_FAIL_TASK test hook) is reported by `farm status`, completed by
// `farm resume`, and merges into the image rendered in one process, bit for bit; no file under a
// final name is ever partial. Frames become tasks and images named by frame; bad input gives the
// documented exit codes. (tests/farm/slurm_farm_test.sh runs the same on a Slurm cluster.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

const std::string kCornellBox = (fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda").string();
const std::string kRenderArgs = " -r 21 15 --spp 4";

// Sets an environment variable for the commands a test runs, and removes it afterwards.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
    ~ScopedEnvironment() { ::unsetenv(name_); }

private:
    const char* name_;
};

class FarmCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_farm_cli"};
    RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
    std::string farm() const { return tmp_.file("farm"); }

    // Every file under the farm folder is whole: no temporary file is left, every EXR reads.
    void expectNoPartialFiles() const {
        for (const auto& entry : fs::recursive_directory_iterator(farm())) {
            const std::string name = entry.path().filename().string();
            EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "temporary file left: " << entry.path();
            if (entry.path().extension() == ".exr") {
                EXPECT_NO_THROW(test::readExr(entry.path())) << entry.path();
            }
        }
    }
};

TEST_F(FarmCli, AFailedTileIsReportedResumedAndTheMergeIsTheImageRenderedInOnePiece) {
    RunResult r = run("render " + kCornellBox + kRenderArgs + " -o " + tmp_.file("whole.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const ScopedEnvironment failTask2("FLUENCE_FARM_FAIL_TASK", "2");  // stays set: it fails the first attempt only
    r = run("farm submit " + kCornellBox + " --tiles 2 2 --backend local --jobs 2 --output-dir " + farm() + " --" +
            kRenderArgs);
    EXPECT_EQ(r.exitCode, 9) << r.out << r.err;  // incomplete
    for (int tile : {0, 1, 3})
        EXPECT_TRUE(fs::exists(farm() + "/tiles/cornell_box_tile" + std::to_string(tile) + ".exr")) << tile;
    EXPECT_FALSE(fs::exists(farm() + "/tiles/cornell_box_tile2.exr"));
    EXPECT_FALSE(fs::exists(farm() + "/cornell_box.exr")) << "merged although a tile is missing";
    EXPECT_NE(test::slurp(farm() + "/logs/task_2.log").find("FLUENCE_FARM_FAIL_TASK"), std::string::npos);
    expectNoPartialFiles();

    r = run("farm status " + farm());
    EXPECT_EQ(r.exitCode, 9) << r.out;
    EXPECT_NE(r.out.find("task 2     tile 2   failed   exit 1 on attempt 1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3 done, 0 queued, 0 running, 1 failed, 0 missing; 0 of 1 images done"), std::string::npos)
        << r.out;

    r = run("farm resume " + farm());
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("resubmitting 1 task and the merge"), std::string::npos) << r.out;
    EXPECT_NE(test::slurp(farm() + "/tasks/task_2.json").find("\"attempts\": 2, \"exitCode\": 0"), std::string::npos);
    EXPECT_NE(test::slurp(farm() + "/tasks/task_0.json").find("\"attempts\": 1,"), std::string::npos)
        << "task 0 ran again";
    expectNoPartialFiles();

    const test::ExrImage whole = test::readExr(tmp_.file("whole.exr")),
                         merged = test::readExr(farm() + "/cornell_box.exr");
    ASSERT_EQ(merged.width, whole.width);
    ASSERT_EQ(merged.height, whole.height);
    ASSERT_EQ(merged.channels, whole.channels);
    EXPECT_TRUE(merged.pixels == whole.pixels) << "the farm's image differs from the render in one piece";

    r = run("farm status " + farm());
    EXPECT_EQ(r.exitCode, 0) << r.out;
    r = run("farm resume " + farm());
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("nothing to resume"), std::string::npos) << r.out;
}

TEST_F(FarmCli, FramesAreTasksAndImagesNamedByFrame) {
    RunResult r = run("farm submit " + kCornellBox + " --frames 1-3x2 --backend local --output-dir " + farm() + " --" +
                      kRenderArgs);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_TRUE(fs::exists(farm() + "/cornell_box.0001.exr"));
    EXPECT_TRUE(fs::exists(farm() + "/cornell_box.0003.exr"));
    EXPECT_FALSE(fs::exists(farm() + "/cornell_box.0002.exr"));
    EXPECT_NE(r.out.find("2 done, 0 queued, 0 running, 0 failed, 0 missing; 2 of 2 images done"), std::string::npos)
        << r.out;
    EXPECT_NE(test::slurp(farm() + "/logs/task_1.log").find("'-f' '3'"), std::string::npos);

    // A task whose output is removed is missing, and resume renders it alone.
    fs::remove(farm() + "/cornell_box.0003.exr");
    r = run("farm status " + farm());
    EXPECT_EQ(r.exitCode, 9);
    EXPECT_NE(r.out.find("1 done, 0 queued, 0 running, 0 failed, 1 missing"), std::string::npos) << r.out;
    r = run("farm resume " + farm());
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_TRUE(fs::exists(farm() + "/cornell_box.0003.exr"));
}

TEST_F(FarmCli, BadInputGivesTheDocumentedExitCodes) {
    EXPECT_EQ(run("farm submit " + tmp_.file("missing.usda") + " --backend local --output-dir " + farm()).exitCode, 4);
    RunResult r = run("farm submit " + kCornellBox + " --backend local --output-dir " + farm() + " -- -o x.exr");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("-o/--output"), std::string::npos) << r.err;
    EXPECT_EQ(run("farm submit " + kCornellBox + " --backend local -- --spp 0").exitCode, 2) << "render's own check";
    EXPECT_EQ(run("farm submit " + kCornellBox + " --tiles 0 1").exitCode, 2);
    EXPECT_EQ(run("farm submit " + kCornellBox + " --frames 5-1").exitCode, 2);
    EXPECT_EQ(run("farm submit " + kCornellBox + " --backend pbs").exitCode, 2);
    EXPECT_EQ(run("farm frobnicate " + farm()).exitCode, 2);
    r = run("farm status " + tmp_.file("nowhere"));
    EXPECT_EQ(r.exitCode, 4);
    EXPECT_NE(r.err.find("farm.json"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(farm())) << "nothing is created for refused input";

    ASSERT_EQ(
        run("farm submit " + kCornellBox + " --backend local --output-dir " + farm() + " --" + kRenderArgs).exitCode,
        0);
    r = run("farm submit " + kCornellBox + " --backend local --output-dir " + farm() + " --" + kRenderArgs);
    EXPECT_EQ(r.exitCode, 2) << "a second submit into the same folder";
    EXPECT_NE(r.err.find("farm resume"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fluence
