// The denoiser (denoise/denoiser.h) on images with named channels: what `fluence render --denoise`
// and `fluence denoise` share.
//
// The buffers are read from these channels (core/film.h): half0.R/G/B, half1.R/G/B (the two half
// images), variance.R/G/B, albedo.R/G/B, N.X/Y/Z and Z, and albedoVariance.R/G/B and NVariance.X/Y/Z
// when the image has them; light path layers from NAME.R/G/B.
// Written back: R G B become the denoised beauty and the noisy one is kept as noisy.R/G/B (left as
// it is when the image already has it: denoising a denoised image starts again from the halves);
// a denoised layer NAME.R/G/B likewise keeps its noisy colour as NAME_noisy.R/G/B.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"
#include "denoise/denoiser.h"

namespace fluence::app {

// An image without a channel the denoiser needs; the message names every missing channel.
class DenoiseInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The channels `image` needs for denoise(), with the light path layers `layers`.
std::vector<std::string> denoiseInputChannels(const std::vector<std::string>& layers);

// The light path layers of an image: its NAME.R/G/B layers that are neither the beauty's buffers
// nor their noisy copies nor Cryptomatte's.
std::vector<std::string> lightPathLayersOf(const Image& image);

// Denoises `image` in place, with its light path layers `layers` each on their own. Throws
// DenoiseInputError.
void denoiseImage(Image& image, const std::vector<std::string>& layers, int threads);

// Channels `names` of every pixel of `image` (each present), interleaved.
std::vector<float> gather(const Image& image, const std::vector<std::string>& names);

// `image` with the channels of `extra` (of the same size) after its own.
Image withChannels(const Image& image, const Image& extra);

}  // namespace fluence::app
