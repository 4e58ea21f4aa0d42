// Render checkpoints: the film of a render stopped at a pass boundary, with what it takes to go
// on, in a file beside the output (`fluence render --checkpoint SECS`, `--resume`).
//
// A checkpoint is only resumed by the render that wrote it: its fingerprint is a list of named
// entries (scene and the content of its layer files, camera, resolution, window, frame, seed,
// integrator, samples per pixel, ..., see apps/render_fingerprint.h), and reading compares each with
// the resuming render's, naming every entry that differs.
//
// File layout, in the machine's byte order (core/binary_stream.h):
//   "FLUENCE CHECKPOINT\n"          magic
//   u32 kCheckpointVersion, u32 kByteOrderMark
//   u32 N, then N x (string name, string value)   the fingerprint
//   u32 samplesDone                 samples per pixel the film holds (pass boundary)
//   film state                      core/film_state.h
//   u8 hasCryptomatte, then its state when 1 (core/cryptomatte_film.h)
// Written to a temporary file and renamed into place (output/atomic_file.h), so a render killed
// at any moment leaves the previous checkpoint or the new one, never a partial one.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/cryptomatte_film.h"
#include "core/film.h"

namespace fluence::app {

inline constexpr std::uint32_t kCheckpointVersion = 2;

// Named entries that must all be equal for a checkpoint to be resumed, in a fixed order.
using CheckpointFingerprint = std::vector<std::pair<std::string, std::string>>;

// The file is not a checkpoint, is damaged, or is of another version or byte order.
class CheckpointError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The checkpoint was written by another render; the message names every entry that differs,
// "seed: 1 in the checkpoint, 2 now".
class CheckpointMismatch : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The checkpoint of the output `outputPath`: "<outputPath>.checkpoint".
std::string checkpointPath(const std::string& outputPath);

// Writes the checkpoint atomically, with the Cryptomatte coverage counts when `cryptomatte` is not
// null. Throws output::OutputError.
void writeCheckpoint(const std::string& path, const CheckpointFingerprint& fingerprint, int samplesDone,
                     const Film& film, const CryptomatteFilm* cryptomatte = nullptr);

// Reads the checkpoint at `path` into `film` and `cryptomatte` (fresh, of the render's shape and
// layers; null when the render has no Cryptomatte layers) and returns its samplesDone. Throws
// CheckpointMismatch when its fingerprint differs from `fingerprint`, CheckpointError when it
// cannot be read or its Cryptomatte layers are not the render's; the films are then unspecified.
int readCheckpoint(const std::string& path, const CheckpointFingerprint& fingerprint, Film& film,
                   CryptomatteFilm* cryptomatte = nullptr);

}  // namespace fluence::app
