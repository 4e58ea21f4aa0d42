// What `fluence render` writes at pass boundaries besides the final image, one set per output
// (frame, tile):
//
//   checkpoints  --checkpoint SECS: at the first pass boundary at least SECS after the render
//                started or the last checkpoint (0: after every pass), the film's whole state as
//                "<output>.checkpoint" (apps/render_checkpoint.h). --resume goes on from it: the
//                image then comes out bit-identical to an uninterrupted render's, and a render
//                killed at any moment loses at most the work since the last checkpoint. The
//                checkpoint is removed once the final image is written, and kept when the render
//                is interrupted or fails.
//   snapshots    --snapshot SECS (0: every pass), and on SIGUSR1 (apps/snapshot_signal.h): the
//                image so far, as "<stem>.snapshot<ext>" beside the output ("beauty.0001.exr" ->
//                "beauty.0001.snapshot.exr"), with its sample count in "fluence/samplesPerPixel"
//                and "fluence/snapshot" = 1. The final path never holds a partial image. Like the
//                checkpoint, it is removed once the final image is written (the image supersedes
//                it) and kept otherwise (the best image there is).
//
// Both are written atomically (output/atomic_file.h); a write that fails is a warning and the
// render goes on. Temporary files that a killed render left beside them are removed at the end.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "apps/cli_options.h"
#include "apps/render_checkpoint.h"
#include "apps/warning_log.h"
#include "core/film.h"

namespace fluence::app {

class PassOutputs {
public:
    // Writes the image of `film` (holding `samplesDone` samples per pixel) to `path`, as the
    // render command writes its output. Throws output::OutputError.
    using SnapshotWriter = std::function<void(const std::string& path, const Film& film, int samplesDone)>;

    // `cryptomatte`: the render's Cryptomatte coverage (null without Cryptomatte layers), saved in
    // checkpoints and restored on resume with the film.
    PassOutputs(const RenderOptions& options, std::string outputPath, CheckpointFingerprint fingerprint,
                CryptomatteFilm* cryptomatte, WarningLog& warnings, SnapshotWriter writeSnapshot);

    // With --resume, reads the checkpoint into `film` (fresh) and the Cryptomatte coverage, and returns the samples per pixel it
    // holds; without a checkpoint, says so on stdout and returns 0. Throws CheckpointMismatch and
    // CheckpointError.
    int resume(Film& film);

    // The render's RenderSettings::onPass: writes what is due.
    void onPass(const Film& film, int samplesDone);

    // After the final image is written: removes the checkpoint, the snapshot and stale temporary files.
    void finish();

    static std::string snapshotPath(const std::string& outputPath);

private:
    using Clock = std::chrono::steady_clock;
    static bool due(const std::optional<double>& interval, Clock::time_point last);

    const RenderOptions& options_;
    CryptomatteFilm* cryptomatte_;
    std::string outputPath_, checkpointPath_, snapshotPath_;
    CheckpointFingerprint fingerprint_;
    SnapshotWriter writeSnapshot_;
    WarningLog& warnings_;
    Clock::time_point lastCheckpoint_, lastSnapshot_;
};

}  // namespace fluence::app
