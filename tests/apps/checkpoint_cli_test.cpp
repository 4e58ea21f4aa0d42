// End-to-end: checkpoints and snapshots of `fluence render` (apps/pass_outputs.h).
//
// A render checkpointing every pass is killed with SIGKILL once its first checkpoint exists;
// resuming it with another seed or resolution is refused (exit 2, naming what differs), and
// resuming it as it was finishes bit-identical to a render never stopped, leaving no checkpoint or
// temporary file; so does a render with --denoise, its denoised image included. SIGUSR1 writes a
// snapshot beside an output that does not exist yet. Nothing here depends on timing but generous
// timeouts: the test waits for files, never for durations.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

const std::string kScene = std::string(FLUENCE_SOURCE_DIR) + "/usd_samples/cornell_box.usda";
// Small, but a few seconds of rendering on one thread, so the render is still going when its first
// checkpoint appears.
const std::string kRender = "render " + kScene + " -r 40 40 --spp 1024 --max-depth 4 --seed 3";

// `fluence ARGS` running in the background (its output in DIR/child.txt).
class Child {
public:
    Child(const std::string& args, const fs::path& dir) {
        const std::string command = "exec " + std::string(FLUENCE_BINARY) + " " + args + " > " +
                                    (dir / "child.txt").string() + " 2>&1 < /dev/null";
        pid_ = ::fork();
        if (pid_ == 0) {
            ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
    }
    ~Child() {
        if (pid_ > 0 && !exited_) {
            ::kill(pid_, SIGKILL);
            wait();
        }
    }
    // Waits (up to two minutes) until `ready` holds; false if the process ended first or time ran out.
    bool waitFor(const std::function<bool()>& ready) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
        while (std::chrono::steady_clock::now() < deadline) {
            if (ready()) return true;
            int status = 0;
            if (::waitpid(pid_, &status, WNOHANG) == pid_) {
                exited_ = true;
                return ready();
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return false;
    }
    void signal(int sig) { ::kill(pid_, sig); }
    // The exit code, or -signal when a signal ended it.
    int wait() {
        int status = 0;
        ::waitpid(pid_, &status, 0);
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
    }

private:
    pid_t pid_ = -1;
    bool exited_ = false;
};

bool samePixels(const fs::path& a, const fs::path& b) {
    const test::ExrImage x = test::readExr(a), y = test::readExr(b);
    return x.channels == y.channels && x.pixels.size() == y.pixels.size() &&
           std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)) == 0;
}

class CheckpointCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_checkpoint_cli"};
    bool exists(const std::string& name) const { return fs::exists(tmp_.path() / name); }
    // Runs `fluence ARGS` (which writes out.exr with checkpoints) and kills it once its first
    // checkpoint exists.
    void killAtFirstCheckpoint(const std::string& args) {
        Child child(args, tmp_.path());
        ASSERT_TRUE(child.waitFor([&] { return exists("out.exr.checkpoint"); })) << test::slurp(tmp_.file("child.txt"));
        child.signal(SIGKILL);
        ASSERT_EQ(child.wait(), -SIGKILL) << "the render finished before it was killed; make it longer";
    }
    std::string entries() const {
        std::string list;
        for (const std::string& name : tmp_.list()) list += name + " ";
        return list;
    }
};

TEST_F(CheckpointCli, KilledRenderResumesBitIdenticalAndRefusesAnotherRendersCheckpoint) {
    const std::string out = tmp_.file("out.exr");
    ASSERT_NO_FATAL_FAILURE(killAtFirstCheckpoint(kRender + " -j 1 --checkpoint 0 -o " + out));
    ASSERT_FALSE(exists("out.exr"));

    // Another render's checkpoint is refused, and kept.
    test::RunResult r = test::runFluence(kRender + " --seed 4 --resume -o " + out, tmp_.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("seed: 3 in the checkpoint, 4 now"), std::string::npos) << r.err;
    r = test::runFluence("render " + kScene + " -r 40 30 --spp 1024 --max-depth 4 --seed 3 --resume -o " + out,
                         tmp_.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("resolution: 40x40 in the checkpoint, 40x30 now"), std::string::npos) << r.err;
    r = test::runFluence(kRender + " --sampler independent --resume -o " + out, tmp_.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("sampler: sobol in the checkpoint, independent now"), std::string::npos) << r.err;
    EXPECT_TRUE(exists("out.exr.checkpoint"));
    EXPECT_FALSE(exists("out.exr"));

    // Resumed as it was (on every core, where the killed render had one), it goes on from there.
    r = test::runFluence(kRender + " --resume --checkpoint 0 -o " + out, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("resuming from " + out + ".checkpoint at "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("at 0 samples"), std::string::npos) << r.out;

    r = test::runFluence(kRender + " -o " + tmp_.file("reference.exr"), tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(samePixels(tmp_.file("reference.exr"), out));
    for (const std::string& name : tmp_.list())
        EXPECT_TRUE(name == "out.exr" || name == "reference.exr" || name.ends_with(".txt"))
            << name << " was left behind";
}

TEST_F(CheckpointCli, CryptomatteCoverageResumesBitIdenticalToo) {
    const std::string out = tmp_.file("out.exr"), crypto = " --cryptomatte object,material";
    ASSERT_NO_FATAL_FAILURE(killAtFirstCheckpoint(kRender + crypto + " -j 1 --checkpoint 0 -o " + out));
    test::RunResult r = test::runFluence(kRender + " --resume -o " + out, tmp_.path());
    EXPECT_EQ(r.exitCode, 2) << "a render without the layers refuses the checkpoint: " << r.err;
    EXPECT_NE(r.err.find("cryptomatte: object material in the checkpoint,  now"), std::string::npos) << r.err;
    r = test::runFluence(kRender + crypto + " --resume -o " + out, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("at 0 samples"), std::string::npos) << r.out;
    r = test::runFluence(kRender + crypto + " -o " + tmp_.file("reference.exr"), tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage resumed = test::readExr(out);
    ASSERT_NE(resumed.channel("CryptoObject00.R"), -1);
    EXPECT_TRUE(samePixels(tmp_.file("reference.exr"), out));
}

TEST_F(CheckpointCli, DenoisedRenderResumesBitIdenticalToo) {
    // The half images and variance are in the checkpoint, so the denoised beauty (RGB), the noisy one
    // and the buffers of a resumed render are those of a render never stopped.
    const std::string out = tmp_.file("out.exr"), denoise = " --denoise";
    ASSERT_NO_FATAL_FAILURE(killAtFirstCheckpoint(kRender + denoise + " -j 1 --checkpoint 0 -o " + out));
    test::RunResult r = test::runFluence(kRender + denoise + " --resume -o " + out, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("at 0 samples"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("denoised"), std::string::npos) << r.out;
    r = test::runFluence(kRender + denoise + " -o " + tmp_.file("reference.exr"), tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage resumed = test::readExr(out);
    ASSERT_NE(resumed.channel("noisy.R"), -1);
    ASSERT_NE(resumed.channel("half0.R"), -1);
    EXPECT_TRUE(samePixels(tmp_.file("reference.exr"), out));
}

TEST_F(CheckpointCli, ResumeWithoutACheckpointRendersFromTheStart) {
    const test::RunResult r =
        test::runFluence("render " + kScene + " -r 16 16 --spp 4 --resume -o " + tmp_.file("out.exr"), tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("no checkpoint at"), std::string::npos) << r.out;
    EXPECT_TRUE(exists("out.exr"));
}

// A resumed sequence skips the frames this same render already wrote (their headers carry its
// fingerprint and no checkpoint is left), renders those missing, and renders again a frame written
// by another render (here another seed).
TEST_F(CheckpointCli, ResumeSkipsTheFramesThisRenderAlreadyWrote) {
    const std::string pattern = "'" + tmp_.file("out.$F4.exr") + "'";
    const std::string render = "render " + kScene + " -r 16 16 --spp 4 -f 1 -n 3 --resume -o " + pattern;
    test::RunResult r = test::runFluence(render, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("skipped"), std::string::npos) << r.out;
    const test::ExrImage first = test::readExr(tmp_.file("out.0001.exr"));
    EXPECT_EQ(first.spec.get_string_attribute("fluence/fingerprint").size(), 16u);

    fs::remove(tmp_.file("out.0002.exr"));
    const auto written = fs::last_write_time(tmp_.file("out.0001.exr"));
    r = test::runFluence(render, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("out.0001.exr is already rendered"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("out.0003.exr is already rendered"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("out.0002.exr is already rendered"), std::string::npos) << r.out;
    EXPECT_TRUE(exists("out.0002.exr"));
    EXPECT_EQ(fs::last_write_time(tmp_.file("out.0001.exr")), written) << "a skipped frame is not written again";

    r = test::runFluence(render + " --seed 8", tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("already rendered"), std::string::npos) << "another seed renders every frame again:\n"
                                                                 << r.out;
}

// The fingerprint covers the asset files a scene reads (by path, size and modification time): an
// output rendered before its texture was replaced is not "already rendered".
TEST_F(CheckpointCli, ResumeRendersAgainAfterATextureChanged) {
    auto writeTexture = [&](int seed) {
        const test::RunResult r = test::runFluence(
            "render " + kScene + " -r 8 8 --spp 1 --seed " + std::to_string(seed) + " -o " + tmp_.file("texture.exr"),
            tmp_.path());
        ASSERT_EQ(r.exitCode, 0) << r.err;
    };
    writeTexture(1);
    const std::string scene = tmp_.file("textured.usda");
    std::ofstream(scene) << test::texturedQuadUsda("./texture.exr");
    const std::string render = "render " + scene + " -r 8 8 --spp 2 --resume -o " + tmp_.file("out.exr");
    test::RunResult r = test::runFluence(render, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = test::runFluence(render, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("already rendered"), std::string::npos) << r.out;

    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a modification time of its own
    writeTexture(2);
    r = test::runFluence(render, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("already rendered"), std::string::npos) << "the texture changed:\n" << r.out;
}

TEST_F(CheckpointCli, Sigusr1WritesASnapshotBeforeTheOutputExists) {
    Child child("render " + kScene + " -r 32 32 --spp 1000000 --checkpoint 0 -o " + tmp_.file("out.exr"), tmp_.path());
    // The checkpoint shows the render is under way (the handler is installed before the scene loads).
    ASSERT_TRUE(child.waitFor([&] { return exists("out.exr.checkpoint"); })) << test::slurp(tmp_.file("child.txt"));
    ASSERT_FALSE(exists("out.snapshot.exr"));
    child.signal(SIGUSR1);
    ASSERT_TRUE(child.waitFor([&] { return exists("out.snapshot.exr"); })) << test::slurp(tmp_.file("child.txt"));
    EXPECT_FALSE(exists("out.exr"));
    const test::ExrImage snapshot = test::readExr(tmp_.file("out.snapshot.exr"));
    EXPECT_EQ(snapshot.width, 32);
    EXPECT_GE(snapshot.at(5, 5, "sampleCount"), 1.0f);
    EXPECT_EQ(snapshot.spec.get_float_attribute("fluence/snapshot"), 1.0f);
    EXPECT_GE(snapshot.spec.get_float_attribute("fluence/samplesPerPixel"), 1.0f);

    child.signal(SIGTERM);
    EXPECT_EQ(child.wait(), 7);
    // Interrupted: the snapshot and the checkpoint stay (the best image there is; --resume), the
    // output is not written.
    EXPECT_TRUE(exists("out.snapshot.exr")) << entries();
    EXPECT_TRUE(exists("out.exr.checkpoint")) << entries();
    EXPECT_FALSE(exists("out.exr"));
}

TEST_F(CheckpointCli, ASuccessfulRenderLeavesNoSnapshotOrCheckpointPerFrame) {
    const test::RunResult r =
        test::runFluence("render " + kScene + " -r 16 16 --spp 8 -f 1 -n 2 --checkpoint 0 --snapshot 0 -o '" +
                             tmp_.file("out.$F4.exr") + "'",
                         tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& name : tmp_.list())
        EXPECT_TRUE(name == "out.0001.exr" || name == "out.0002.exr" || name.ends_with(".txt"))
            << name << " was left behind";
}

TEST_F(CheckpointCli, BadIntervalsAreUsageErrors) {
    for (const char* flag : {"--checkpoint", "--snapshot"}) {
        const test::RunResult r = test::runFluence("render " + kScene + " " + flag + " -1", tmp_.path());
        EXPECT_EQ(r.exitCode, 2) << flag;
        EXPECT_NE(r.err.find(std::string(flag) + " must be >= 0 seconds"), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace fluence
