// The pieces of `fluence farm` below the command line: --frames parsing, the plan's tasks and
// images and its file round trip, the render arguments of a task, the JSON reader, shell quoting
// (read back by a real /bin/sh), and the local backend's job semantics (array, afterok, logs).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "apps/cli_options.h"
#include "apps/farm_local_backend.h"
#include "apps/farm_plan.h"
#include "apps/farm_process.h"
#include "apps/json.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence::app {
namespace {

TEST(FarmFrames, RangesWithStepsAndNegativeFrames) {
    EXPECT_EQ(parseFrameRange("7"), std::vector<double>({7}));
    EXPECT_EQ(parseFrameRange("1-5x2"), std::vector<double>({1, 3, 5}));
    EXPECT_EQ(parseFrameRange("1-6x2"), std::vector<double>({1, 3, 5}));
    EXPECT_EQ(parseFrameRange("-3--1"), std::vector<double>({-3, -2, -1}));
    for (const char* bad : {"", "a", "5-1", "1-3x0", "1x2", "1-", "1-3x"})
        EXPECT_THROW(parseFrameRange(bad), UsageError) << bad;
}

FarmPlan twoFramesTwoTiles(const std::string& folder) {
    FarmPlan plan;
    plan.folder = folder;
    plan.scene = "/scenes/shot.usda";
    plan.renderArgs = {"--spp", "16", "--variant", "/World:look=it's \"quoted\""};
    plan.tileColumns = 2;
    plan.backend = "local";
    planTasks(plan, {1, 2});
    return plan;
}

TEST(FarmPlan, OneTaskPerFrameAndTileNamedAfterTheScene) {
    const FarmPlan plan = twoFramesTwoTiles("/farm");
    ASSERT_EQ(plan.tasks.size(), 4u);
    EXPECT_EQ(plan.tasks[3].index, 3);
    EXPECT_EQ(plan.tasks[3].frame, 2.0);
    EXPECT_EQ(plan.tasks[3].tile, 1);
    EXPECT_EQ(plan.tasks[3].output, "tiles/shot.0002_tile1.exr");
    ASSERT_EQ(plan.images.size(), 2u);
    EXPECT_EQ(plan.images[1].output, "shot.0002.exr");
    EXPECT_EQ(plan.images[1].tasks, std::vector<int>({2, 3}));
    EXPECT_EQ(plan.path("shot.0002.exr"), "/farm/shot.0002.exr");

    FarmPlan whole;
    whole.scene = "/scenes/shot.usda";
    planTasks(whole, {});
    ASSERT_EQ(whole.tasks.size(), 1u);
    EXPECT_FALSE(whole.tasks[0].frame);
    EXPECT_EQ(whole.tasks[0].output, "shot.exr") << "an unsplit task writes the image itself";
}

TEST(FarmPlan, TaskArgumentsAreARenderOfExactlyThatTileAndFrame) {
    const FarmPlan plan = twoFramesTwoTiles("/farm");
    const std::vector<std::string> args = taskRenderArgs(plan, plan.tasks[3], 3);
    const RenderOptions o = parseRenderOptions(args);
    EXPECT_EQ(o.scene, "/scenes/shot.usda");
    EXPECT_EQ(o.output, "/farm/tiles/shot.0002_tile1.exr");
    EXPECT_EQ(o.tileSuffix, "") << "so the output is the path the plan names";
    EXPECT_EQ(o.frame, 2.0);
    EXPECT_EQ(o.threads, 3);
    ASSERT_TRUE(o.tileCount);
    EXPECT_EQ(*o.tileCount, std::make_pair(2, 1));
    EXPECT_EQ(o.tileIndex, 1);
    EXPECT_EQ(o.spp, 16);
    ASSERT_EQ(o.variants.size(), 1u);
    EXPECT_EQ(o.variants[0].selection, "it's \"quoted\"");
}

TEST(FarmPlan, FileRoundTripAndErrorsNameTheFile) {
    test::TempDir tmp("fluence_farm_plan");
    FarmPlan plan = twoFramesTwoTiles(tmp.path().string());
    plan.threadsPerTask = 2;
    plan.maxParallel = 3;
    plan.submissions.push_back({"slurm", {0, 2}, "41", "42"});
    writeFarmPlan(plan);
    const FarmPlan back = readFarmPlan(tmp.path().string());
    EXPECT_EQ(back.scene, plan.scene);
    EXPECT_EQ(back.renderArgs, plan.renderArgs);
    EXPECT_EQ(back.tileColumns, 2);
    EXPECT_EQ(back.tileRows, 1);
    EXPECT_EQ(back.threadsPerTask, 2);
    EXPECT_EQ(back.maxParallel, 3);
    ASSERT_EQ(back.tasks.size(), 4u);
    EXPECT_EQ(back.tasks[2].frame, 2.0);
    EXPECT_EQ(back.tasks[2].output, plan.tasks[2].output);
    EXPECT_EQ(back.images[0].tasks, plan.images[0].tasks);
    ASSERT_EQ(back.submissions.size(), 1u);
    EXPECT_EQ(back.submissions[0].tasks, std::vector<int>({0, 2}));
    EXPECT_EQ(back.submissions[0].mergeJob, "42");

    std::ofstream(tmp.file("farm.json")) << "{\"fluenceFarmPlan\": 1, \"scene\": 3}";
    try {
        readFarmPlan(tmp.path().string());
        ADD_FAILURE() << "a broken plan was read";
    } catch (const FarmPlanError& e) {
        EXPECT_NE(std::string(e.what()).find(tmp.file("farm.json") + ": scene must be a string"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(readFarmPlan(tmp.file("nowhere")), FarmPlanError);
}

TEST(FarmJson, ReadsWhatItsWritersWrite) {
    const JsonValue v = parseJson(R"( {"a": [1, -2.5e3, true, null], "s": "q\"\\\n\u00e9\ud83d\ude00", "o": {}} )");
    EXPECT_EQ(v.at("a", "doc").asArray("a")[1].asNumber("a[1]"), -2500.0);
    EXPECT_TRUE(v.at("a", "doc").asArray("a")[2].asBool("a[2]"));
    EXPECT_TRUE(v.at("a", "doc").asArray("a")[3].isNull());
    EXPECT_EQ(v.at("s", "doc").asString("s"), "q\"\\\n\xc3\xa9\xf0\x9f\x98\x80");
    EXPECT_TRUE(v.at("o", "doc").isObject());
    EXPECT_EQ(v.find("missing"), nullptr);
    const std::string weird = "tab\there \"quote\" back\\slash \x01";
    EXPECT_EQ(parseJson(jsonQuoted(weird)).asString("s"), weird);
    EXPECT_EQ(jsonNumber(0.1), "0.1");
    for (const char* bad : {"", "{", "[1,]", "{\"a\" 1}", "01x", "\"unterminated", "[1] 2", "\"\\x\""})
        EXPECT_THROW(parseJson(bad), JsonError) << bad;
    EXPECT_THROW(parseJson("1.5").asInt("n"), JsonError);
}

TEST(FarmProcess, ShellQuotingReadsBackAsTheSameWord) {
    for (const std::string word : {"plain", "it's", "$HOME `id` \"q\" \\ ;|&", "", "new\nline", "*"}) {
        const CommandOutput r = runCommand({"sh", "-c", "printf '%s' " + shellQuoted(word)});
        EXPECT_EQ(r.exitCode, 0);
        EXPECT_EQ(r.out, word);
    }
    EXPECT_EQ(runCommand({"sh", "-c", "echo oops >&2; exit 3"}).exitCode, 3);
    EXPECT_EQ(runCommand({"sh", "-c", "echo oops >&2; exit 3"}).err, "oops\n");
    EXPECT_THROW(runCommand({"/no/such/program"}), SpawnError);
}

TEST(FarmLocalBackend, RunsEveryTaskAndTheDependentJobOnlyAfterSuccess) {
    test::TempDir tmp("fluence_farm_local");
    LocalFarmBackend backend(2);
    ArrayJob array;
    array.name = "t";
    array.command = {"sh", "-c", "echo task $0 > out_$0.txt; test $0 != 1"};  // the index is $0; task 1 fails
    array.indices = {0, 1, 2};
    array.logPattern = tmp.file("task_%a.log");
    array.workDir = tmp.path().string();
    SingleJob merge;
    merge.name = "merge";
    merge.command = {"sh", "-c", "cat out_*.txt > merged.txt"};
    merge.logPath = tmp.file("merge.log");
    merge.workDir = tmp.path().string();

    const std::string failed = backend.submitArray(array);
    for (int i : {0, 1, 2})
        EXPECT_EQ(test::slurp(tmp.file("out_" + std::to_string(i) + ".txt")), "task " + std::to_string(i) + "\n");
    backend.submitDependent(merge, {{failed}, {}});
    EXPECT_FALSE(fs::exists(tmp.file("merged.txt"))) << "afterok on a failed array must not run";
    EXPECT_TRUE(backend.poll({failed}).empty());

    array.indices = {0, 2};
    const std::string ok = backend.submitArray(array);
    backend.submitDependent(merge, {{ok}, {failed}});
    EXPECT_EQ(test::slurp(tmp.file("merged.txt")), "task 0\ntask 1\ntask 2\n");

    array.command = {"sh", "-c", "echo attempt >&2"};
    array.indices = {0};
    backend.submitArray(array);
    EXPECT_EQ(test::slurp(tmp.file("task_0.log")), "attempt\n") << "standard error goes to the task's log";
}

}  // namespace
}  // namespace fluence::app
