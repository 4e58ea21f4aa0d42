// Rendering a frame, the denoiser's part of the write step (`fluence render --denoise`,
// `--denoise-layers`, `--denoise-buffers`): the film's half images and variance added to the
// first product's EXR, with the first-hit features (albedo, N, Z) its vars do not write, and, with
// --denoise, its beauty denoised (apps/denoise_image.h). A channel the denoiser adds is written as
// 32-bit float, but a noisy copy takes the type of the channel it copies (so noisy.R/G/B is the
// beauty a render without --denoise writes, bit for bit).
//
// A tile (--tile-count) is not denoised, only given the buffers: the denoiser looks at neighbours
// across the tile's edges, so tiles are denoised once assembled (`fluence denoise`), without seams.
#pragma once

#include <string>

#include "apps/cli_options.h"
#include "apps/warning_log.h"
#include "core/film.h"
#include "core/image.h"
#include "output/exr_writer.h"

namespace fluence::app {

// Whether the render keeps the denoiser's buffers (Film::enableDenoiseBuffers).
bool keepsDenoiseBuffers(const RenderOptions& opt);

// Adds the buffers of `film` to `image` (the first product, over the film's whole window), and the
// features it lacks from `resolved` (the film resolved), and denoises it as the options say;
// warnings to `warnings` under `path`.
void addDenoiseOutputs(const RenderOptions& opt, const Film& film, const Image& resolved, Image& image,
                       output::ExrHeader& header, WarningLog& warnings, const std::string& path);

}  // namespace fluence::app
