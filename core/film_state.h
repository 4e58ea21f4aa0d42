// The complete state of a Film as bytes, so a render stopped at a pass boundary can go on later
// (render checkpoints, apps/render_checkpoint.h) and finish bit-identical to one never stopped.
//
// Everything the Film keeps is written: its shape (width, height, far depth) and light path
// layer names, then per pixel every running sum (radiance, luminance and its square, albedo,
// normal, coverage, cost (version 4 on)), the nearest depth and whether anything was hit, the sample count, the
// light path layer sums, the splat film's fixed-point sums when there is one (light
// tracing), and the denoiser's buffer sums when the film keeps them (version 3 on; version 5 on, the
// sums of the power-of-two prefixes that split the halves, core/film.h, and the features' squares:
// version 4's were even-indexed samples' and squared sums, which this build refuses). Doubles are
// written as they are, so sums continue exactly. The bytes are in the
// machine's byte order (core/binary_stream.h): the container records and checks it.
//
// Whoever adds a field to Film or Film::Pixel must write and read it here and bump
// kFilmStateVersion: static_asserts on their sizes in film_state.cpp fail to compile until then.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <stdexcept>

#include "core/film.h"

namespace fluence {

inline constexpr std::uint32_t kFilmStateVersion = 5;

// The state read does not fit the film (another shape or other layers: the message says which),
// or the data is damaged or ends early.
class FilmStateError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

void writeFilmState(const Film& film, std::ostream& out);
// Replaces every sum of `film`, which must have the shape and light path layers of the film that
// was written. Throws FilmStateError (leaving `film` unspecified).
void readFilmState(std::istream& in, Film& film);

}  // namespace fluence
