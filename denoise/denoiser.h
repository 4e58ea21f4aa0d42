// The denoiser: feature-guided, weighted first-order regression in the style of NFOR (Bitterli et
// al. 2016, "Nonlinearly Weighted First-order Regression for Denoising Monte Carlo Renderings"),
// with the NL-means colour weights of Rousselle et al. 2013.
//
// Input: the render's two half images (the means of its even- and odd-indexed samples: two
// independent estimates of the beauty), the variance of the beauty's mean, and the first-hit
// features: albedo, shading normal and depth (core/film.h).
//
// Each pixel i is estimated by a weighted least-squares fit, over a window of neighbours j, of the
// colour as a linear function of the features centred on i's: x_j = (1, albedo_j - albedo_i,
// normal_j - normal_i, (depth_j - depth_i) / depth_i); the fit's constant term is the estimate.
// The features explain what changes with the geometry and the textures (so an edge between
// albedos stays sharp), the weights keep out what they do not explain (a caustic, a shadow edge).
// The weight of j is an NL-means weight on colour: with u the 3x3 box-filtered colour and v its
// variance, d² = mean over R G B of ((u_i - u_j)² - s) / (ε + k² s), s = v_i + min(v_i, v_j),
// w = exp(-max(0, d²)). (Rousselle et al. divide by v_i + v_j: the minimum keeps a firefly, whose
// own variance is large, from excusing its distance to the dark pixels around it.)
//
// Cross-filtering: half 0 is fitted with the weights of half 1's colour and half 1 with half 0's,
// so the noise of the weights is independent of the noise they average; the result is the mean of
// the two fits. Extra layers (light path expression AOVs) are fitted with the same weights, each
// on its own colour, in both passes.
//
// Speed: the window is (2 radius / stride + 1)² neighbours, `stride` pixels apart, and the fit's
// 8x8 normal equations are solved by Cholesky with a ridge on the feature terms. Rows run on
// oneTBB; every pixel is computed alone by the same operations, so the output is bit-identical at
// any thread count.
#pragma once

#include <stdexcept>
#include <vector>

namespace fluence::denoise {

// Per-pixel buffers, row-major, row 0 at the top; colours and vectors interleaved (3 floats).
struct DenoiseBuffers {
    int width = 0, height = 0;
    std::vector<float> halves[2];            // R G B: the even and the odd samples' means
    std::vector<float> variance;             // R G B: the variance of the beauty's mean
    std::vector<float> albedo;               // R G B
    std::vector<float> normal;               // X Y Z
    std::vector<float> depth;                // one per pixel (camera-space, > 0)
    std::vector<std::vector<float>> layers;  // R G B each: extra images fitted with the beauty's weights
};

struct DenoiseSettings {
    int radius = 8;       // the window spans (2 radius + 1)² pixels
    int stride = 2;       // every stride-th pixel of it is a neighbour
    float k = 0.6f;       // NL-means colour sensitivity: larger blurs more
    float ridge = 1e-3f;  // ridge on the feature coefficients, relative to the weights' sum
    int threads = 0;      // 0: oneTBB's default
};

struct Denoised {
    std::vector<float> beauty;               // R G B
    std::vector<std::vector<float>> layers;  // R G B each, as DenoiseBuffers::layers
};

// Buffers of the wrong size, or settings out of range.
class DenoiseError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

Denoised denoise(const DenoiseBuffers& buffers, const DenoiseSettings& settings = {});

}  // namespace fluence::denoise
