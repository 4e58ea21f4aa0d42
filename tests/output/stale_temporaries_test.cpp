// output::removeStaleTemporaries: the temporary files of a target left by a process that no longer
// runs (killed mid-write) are removed; those of a live process, and other files, are kept.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "output/atomic_file.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// The id of a process that has ended (and been reaped).
pid_t deadProcess() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    ::waitpid(pid, nullptr, 0);
    return pid;
}

TEST(StaleTemporaries, RemovesThoseOfEndedProcessesOnly) {
    test::TempDir dir("fluence_stale_temporaries");
    const std::string dead = ".out.exr.checkpoint.tmp-" + std::to_string(deadProcess()) + "-3";
    const std::string live = ".out.exr.checkpoint.tmp-" + std::to_string(::getpid()) + "-0";
    const std::string otherTarget = ".out.exr.tmp-" + std::to_string(deadProcess()) + "-0";
    for (const std::string& name : {dead, live, otherTarget, std::string("out.exr.checkpoint")})
        std::ofstream(dir.file(name)) << "x";

    output::removeStaleTemporaries(dir.file("out.exr.checkpoint"));
    const std::vector<std::string> left = dir.list();
    EXPECT_EQ(left, (std::vector<std::string>{live, otherTarget, "out.exr.checkpoint"}));
}

}  // namespace
}  // namespace fluence
