#include "apps/pass_outputs.h"

#include <cstdio>
#include <filesystem>
#include <utility>

#include "apps/snapshot_signal.h"
#include "output/atomic_file.h"

namespace fluence::app {

namespace fs = std::filesystem;

PassOutputs::PassOutputs(const RenderOptions& options, std::string outputPath, CheckpointFingerprint fingerprint,
                         CryptomatteFilm* cryptomatte, WarningLog& warnings, SnapshotWriter writeSnapshot)
    : options_(options),
      cryptomatte_(cryptomatte),
      outputPath_(std::move(outputPath)),
      checkpointPath_(checkpointPath(outputPath_)),
      snapshotPath_(snapshotPath(outputPath_)),
      fingerprint_(std::move(fingerprint)),
      writeSnapshot_(std::move(writeSnapshot)),
      warnings_(warnings),
      lastCheckpoint_(Clock::now()),
      lastSnapshot_(lastCheckpoint_) {}

std::string PassOutputs::snapshotPath(const std::string& outputPath) {
    const fs::path p(outputPath);
    return (p.parent_path() / (p.stem().string() + ".snapshot" + p.extension().string())).string();
}

int PassOutputs::resume(Film& film) {
    if (!options_.resume) return 0;
    std::error_code error;
    if (!fs::exists(checkpointPath_, error)) {
        std::printf("fluence: --resume: no checkpoint at %s; rendering from the start\n", checkpointPath_.c_str());
        return 0;
    }
    const int samplesDone = readCheckpoint(checkpointPath_, fingerprint_, film, cryptomatte_);
    std::printf("fluence: resuming from %s at %d samples per pixel\n", checkpointPath_.c_str(), samplesDone);
    return samplesDone;
}

bool PassOutputs::due(const std::optional<double>& interval, Clock::time_point last) {
    return interval && std::chrono::duration<double>(Clock::now() - last).count() >= *interval;
}

void PassOutputs::onPass(const Film& film, int samplesDone) {
    if (due(options_.checkpointSeconds, lastCheckpoint_)) {
        try {
            writeCheckpoint(checkpointPath_, fingerprint_, samplesDone, film, cryptomatte_);
        } catch (const output::OutputError& e) {
            warnings_(checkpointPath_, std::string("checkpoint not written: ") + e.what());
        }
        lastCheckpoint_ = Clock::now();
    }
    // Both are asked, so that a signal is not left pending for a later pass.
    const bool signalled = SnapshotSignal::take();
    if (signalled || due(options_.snapshotSeconds, lastSnapshot_)) {
        try {
            writeSnapshot_(snapshotPath_, film, samplesDone);
        } catch (const output::OutputError& e) {
            warnings_(snapshotPath_, std::string("snapshot not written: ") + e.what());
        }
        lastSnapshot_ = Clock::now();
    }
}

void PassOutputs::finish() {
    for (const std::string& path : {checkpointPath_, snapshotPath_}) {
        std::error_code error;
        fs::remove(path, error);
        output::removeStaleTemporaries(path);
    }
}

}  // namespace fluence::app
