// End-to-end: SIGTERM and SIGINT stop a render cleanly (apps/stop_signals.h): exit code 7 and
// nothing at the output path, neither the image nor a temporary file beside it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

class InterruptCli : public ::testing::TestWithParam<const char*> {
protected:
    test::TempDir tmp_{"fluence_interrupt_cli"};

    // Starts a render that would take minutes, sends `signal` after two seconds, and returns the
    // exit code the shell saw.
    int renderAndSignal(const std::string& signal) {
        const std::string scene = tmp_.file("furnace.usda");
        std::ofstream(scene) << test::furnaceUsda(0.5);
        const std::string script = std::string(FLUENCE_BINARY) + " render " + scene + " -r 64 64 --spp 1000000 -o " +
                                   tmp_.file("out.exr") + " > " + tmp_.file("log.txt") +
                                   " 2>&1 & pid=$!; sleep 2; kill -" + signal + " $pid; wait $pid; echo $? > " +
                                   tmp_.file("code.txt");
        std::system(("sh -c '" + script + "'").c_str());
        return std::stoi(test::slurp(tmp_.file("code.txt")));
    }
};

TEST_P(InterruptCli, StopsCleanlyWritingNothing) {
    EXPECT_EQ(renderAndSignal(GetParam()), 7) << test::slurp(tmp_.file("log.txt"));
    EXPECT_NE(test::slurp(tmp_.file("log.txt")).find("interrupted by a signal"), std::string::npos);
    for (const auto& entry : fs::directory_iterator(tmp_.path()))
        EXPECT_EQ(entry.path().string().find("out"), std::string::npos) << entry.path() << " was written";
}

INSTANTIATE_TEST_SUITE_P(Signals, InterruptCli, testing::Values("TERM", "INT"));

}  // namespace
}  // namespace fluence
