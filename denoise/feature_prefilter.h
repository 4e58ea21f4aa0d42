// The denoiser's noisy features smoothed with their own variance before the fit (denoise/denoiser.h),
// as NFOR (Bitterli et al. 2016, section 4) prefilters its features.
//
// Where a pixel's first hits differ from sample to sample (depth of field, motion blur, hair), its
// albedo and normal are means of a few different surfaces: noisy, and noisy as its colour is, since
// the colour's samples saw the same surfaces. Fitted against those features, the regression
// explains the colour's noise by theirs and gives it back when the model is evaluated at the pixel's
// own features. So each feature group (albedo R G B, normal X Y Z) of a noisy pixel is replaced by
// an NL-means average over the (2 featureRadius + 1)² window: neighbour j weighs
//   w = exp(-max(0, d² - s) / (k² s)),  d² = the mean over the group of (f_i - f_j)²,
//   s = v_i + min(v_i, v_j),
// the colour weights' form (denoise/denoiser.h), with k = featureK and v the group's noise level:
// the mean over its components of the variance of their means, or its 3x3 mean where that is
// larger (a defocused pixel whose few samples all hit one surface reads a variance of 0). Neighbours
// within the noise of each other are averaged, those beyond it are not.
//
// Which pixels are noisy: the film's variance is the samples' variance over their count, which is
// the noise of a mean of independent samples. Where the first hits vary within the pixel in a way
// the sampler stratifies (an edge in focus, a texture finer than the pixel) the mean is far less
// noisy than that, and smoothing it would blur what the features explain exactly. There the
// neighbouring means differ by much more than v: half their squared difference (to the right and
// lower neighbours, averaged over the group) is 6 to 39 times v on the Cornell box, the material
// ball and the creased cubes, and 0.5 to 2.5 times under depth of field, motion blur and hair
// (medians, 16 samples: bench/results/2026-12-05-denoise-features.md); for noise alone around a
// smooth expectation it would be v. So a pixel's group is prefiltered only where that difference,
// averaged over its 5x5 window, is below kNoiseDominated = 4 times v averaged likewise; elsewhere,
// and where v is 0, the features are kept exactly, and the denoiser is as without their variance.
//
// Every pixel reads the input features only, so the result is the same in any order and at any
// thread count.
#pragma once

#include "denoise/denoise_planes.h"

namespace fluence::denoise {

// Replaces planes.features' albedo and normal by their prefiltered values; nothing without the
// buffers' feature variance. Runs on oneTBB (call inside the denoiser's arena).
void prefilterFeatures(const DenoiseBuffers& buffers, const DenoiseSettings& settings, DenoisePlanes& planes);

}  // namespace fluence::denoise
