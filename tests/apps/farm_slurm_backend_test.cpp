// The Slurm backend's command lines, against stand-in `sbatch`, `squeue` and `scancel` scripts
// put first in PATH: what it asks Slurm (arrays, throttle, CPUs, logs, afterok/afterany and
// --kill-on-invalid-dep), that its --wrap text gives the task the exact arguments when /bin/sh
// runs it, how squeue's answer is read, and that Slurm's refusals become SchedulerError.
// (tests/farm/slurm_farm_test.sh runs the real thing on a one-node cluster.)
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "apps/farm_process.h"
#include "apps/farm_slurm_backend.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence::app {
namespace {

class FarmSlurmBackend : public ::testing::Test {
protected:
    void SetUp() override {
        const char* path = std::getenv("PATH");
        oldPath_ = path ? path : "";
        ::setenv("PATH", (tmp_.path().string() + ":" + oldPath_).c_str(), 1);
    }
    void TearDown() override { ::setenv("PATH", oldPath_.c_str(), 1); }

    // A stand-in for Slurm's `name`: records its arguments, one per line, in name.args, then runs `body`.
    void fake(const std::string& name, const std::string& body) {
        const std::string file = tmp_.file(name);
        std::ofstream(file) << "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done > '" +
                                   tmp_.file(name + ".args") + "'\n" + body + "\n";
        ::chmod(file.c_str(), 0755);
    }
    std::vector<std::string> argsOf(const std::string& name) {
        std::vector<std::string> lines;
        std::ifstream in(tmp_.file(name + ".args"));
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        return lines;
    }
    static bool has(const std::vector<std::string>& args, const std::string& arg) {
        return std::find(args.begin(), args.end(), arg) != args.end();
    }

    test::TempDir tmp_{"fluence_farm_slurm"};
    std::string oldPath_;
    SlurmFarmBackend slurm_;
};

TEST_F(FarmSlurmBackend, ArraysAndDependentJobsAreAskedForAsSlurmExpects) {
    fake("sbatch", "echo '4242;cluster'");
    ArrayJob array;
    array.name = "fluence-shot";
    array.command = {"printf", "[%s]", "/farm dir/it's", "$HOME"};
    array.indices = {2, 5};
    array.maxParallel = 3;
    array.cpusPerTask = 4;
    array.logPattern = "/farm dir/logs/task_%a.log";
    array.workDir = "/farm dir";
    EXPECT_EQ(slurm_.submitArray(array), "4242");
    const std::vector<std::string> args = argsOf("sbatch");
    for (const char* expected : {"--parsable", "--array=2,5%3", "--cpus-per-task=4", "--job-name=fluence-shot",
                                 "--output=/farm dir/logs/task_%a.log", "--open-mode=append", "--chdir=/farm dir"})
        EXPECT_TRUE(has(args, expected)) << expected;
    ASSERT_TRUE(args.back().starts_with("--wrap="));
    // What Slurm's /bin/sh makes of the wrap text: the exact arguments, then the task index.
    ::setenv("SLURM_ARRAY_TASK_ID", "5", 1);
    const CommandOutput task = runCommand({"sh", "-c", args.back().substr(7)});
    ::unsetenv("SLURM_ARRAY_TASK_ID");
    EXPECT_EQ(task.out, "[/farm dir/it's][$HOME][5]");

    SingleJob merge;
    merge.name = "fluence-shot-merge";
    merge.command = {"fluence", "farm", "merge", "/farm dir"};
    merge.logPath = "/farm dir/logs/merge.log";
    merge.workDir = "/farm dir";
    EXPECT_EQ(slurm_.submitDependent(merge, {{"4242"}, {"17", "18"}}), "4242");
    const std::vector<std::string> mergeArgs = argsOf("sbatch");
    EXPECT_TRUE(has(mergeArgs, "--dependency=afterok:4242,afterany:17:18"));
    EXPECT_TRUE(has(mergeArgs, "--kill-on-invalid-dep=yes"));
    EXPECT_EQ(mergeArgs.back(), "--wrap='fluence' 'farm' 'merge' '/farm dir'");

    array.indices = {9, 0, 1, 2, 3, 5, 10};
    array.maxParallel = 0;
    slurm_.submitArray(array);
    EXPECT_TRUE(has(argsOf("sbatch"), "--array=0-3,5,9-10")) << "consecutive tasks as ranges";

    slurm_.submitDependent(merge, {});
    EXPECT_FALSE(has(argsOf("sbatch"), "--kill-on-invalid-dep=yes")) << "no dependency, no dependency options";
}

TEST_F(FarmSlurmBackend, PollReadsSqueueAndForgottenJobsAreNotQueued) {
    fake("squeue", "printf '4242 2 RUNNING\\n4242 5 PENDING\\n4243 N/A PENDING\\n'");
    const std::vector<QueuedTask> queued = slurm_.poll({"4242", "4243"});
    EXPECT_EQ(argsOf("squeue"), std::vector<std::string>({"-h", "-r", "-j", "4242,4243", "-o", "%F %K %T"}));
    ASSERT_EQ(queued.size(), 3u);
    EXPECT_EQ(queued[0].jobId, "4242");
    EXPECT_EQ(queued[0].index, 2);
    EXPECT_EQ(queued[0].state, QueueState::Running);
    EXPECT_EQ(queued[1].state, QueueState::Pending);
    EXPECT_EQ(queued[2].jobId, "4243");
    EXPECT_EQ(queued[2].index, -1);

    fake("squeue", "echo 'slurm_load_jobs error: Invalid job id specified' >&2; exit 1");
    EXPECT_TRUE(slurm_.poll({"4242"}).empty());
    fake("squeue", "echo 'Unable to contact slurm controller' >&2; exit 1");
    EXPECT_THROW(slurm_.poll({"4242"}), SchedulerError);
}

TEST_F(FarmSlurmBackend, RefusalsAreSchedulerErrorsWithSlurmsMessage) {
    fake("sbatch", "echo 'sbatch: error: Batch job submission failed: Invalid job array specification' >&2; exit 1");
    ArrayJob array;
    array.command = {"true"};
    array.indices = {0};
    try {
        slurm_.submitArray(array);
        ADD_FAILURE() << "no error";
    } catch (const SchedulerError& e) {
        EXPECT_NE(std::string(e.what()).find("Invalid job array specification"), std::string::npos) << e.what();
    }
    fake("sbatch", "echo 'not a job id'");
    EXPECT_THROW(slurm_.submitArray(array), SchedulerError);
    fake("scancel", "exit 0");
    slurm_.cancel({"7", "8"});
    EXPECT_EQ(argsOf("scancel"), std::vector<std::string>({"7", "8"}));
}

}  // namespace
}  // namespace fluence::app
