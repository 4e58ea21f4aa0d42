// The denoiser's input rearranged for its inner loops: one plane (row-major float array) per
// channel, and the guides the weights compare, computed once (denoise/denoiser.h).
#pragma once

#include <array>
#include <vector>

#include "denoise/denoiser.h"

namespace fluence::denoise {

struct DenoisePlanes {
    int width = 0, height = 0;
    // The 3x3 box-filtered half images (R G B), which the weights compare, and the variance of
    // such a mean (a half's mean has twice the beauty's variance; the box divides it by 9).
    std::array<std::vector<float>, 3> guide[2];
    std::array<std::vector<float>, 3> guideVariance;
    // The variance of the beauty's mean, R G B: per pixel, and its 3x3 mean.
    std::array<std::vector<float>, 3> variance, smoothVariance;
    // The mean over R G B of the pixel's variance, and of that over the fit window around it
    // (what a pixel's variance is compared with to tell a firefly).
    std::vector<float> pixelVariance, windowVariance;
    // albedo R G B, normal X Y Z, depth: the regression's features (albedo and normal prefiltered
    // where they are noisy: denoise/feature_prefilter.h).
    std::array<std::vector<float>, 7> features;
    // The values fitted, per half: the half's R G B, then each layer's R G B (the layers' planes
    // are shared by both halves).
    std::vector<std::vector<float>> storage;
    std::vector<const float*> values[2];
    // The noisy beauty (the mean of the halves) and layers, R G B each, as `values`.
    std::vector<const float*> noisy;

    int outputs() const { return int(values[0].size()); }
};

// The mean of `image` (a plane of width x height) over the (2 radius + 1)² box around each pixel
// (at the borders, over the pixels inside the image).
std::vector<float> boxMean(const std::vector<float>& image, int width, int height, int radius);

DenoisePlanes makePlanes(const DenoiseBuffers& buffers, int windowRadius);

}  // namespace fluence::denoise
