// The denoiser: feature-guided, weighted first-order regression in the style of NFOR (Bitterli et
// al. 2016, "Nonlinearly Weighted First-order Regression for Denoising Monte Carlo Renderings"),
// with the NL-means colour weights of Rousselle et al. 2013.
//
// Input: the render's two half images (the means of the first and second halves of its samples:
// two estimates of the beauty), the variance of the beauty's mean (from their difference), and the first-hit
// features: albedo, shading normal and depth (core/film.h).
//
// The fit (denoise/local_fit.h): around a centre pixel i, over the (2 radius + 1)² window of
// neighbours j, a weighted least-squares fit of the colour as a linear function of the features
// centred on i's: x_j = (1, albedo_j - albedo_i, normal_j - normal_i, (depth_j - depth_i) / depth_i).
// The features explain what changes with the geometry and the textures (so an edge between
// albedos stays sharp), the weights keep out what they do not explain (a caustic, a shadow edge).
// The weight of j is an NL-means weight on colour: with u the 3x3 box-filtered colour and v its
// variance, d² = mean over R G B of ((u_i - u_j)² - s) / (ε + k² s), s = v_i + min(v_i, v_j),
// w = exp(-max(0, d²)) (Rousselle et al. divide by v_i + v_j: the minimum keeps a firefly, whose
// own variance is large, from excusing its distance to the dark pixels around it); times, for a
// neighbour whose variance is more than `fireflyRatio` times the mean over i's window, that ratio
// over its own, squared (so a firefly is not spread over its neighbours; its own pixel keeps it).
// The window's variance level is the mean of its pixels' variances each clamped to their mean
// (so one firefly hardly raises it).
//
// Noisy features (depth of field, motion blur, hair) are first smoothed with their own variance,
// when the buffers have it (denoise/feature_prefilter.h), so the fit does not give back the noise
// it shares with the colour.
//
// Cross-filtering: half 0 is fitted with the weights of half 1's colour and half 1 with half 0's,
// so the noise of the weights is independent of the noise they average; the result is the mean of
// the two. Extra layers (light path expression AOVs) are fitted with the same weights, each on its
// own colour.
//
// Reconstruction: the fits are made at every `fitStride`-th pixel in x and y (the centres), and
// each pixel p is the mean of the fitted models of the centres within fitStride of it, evaluated
// at p's features, weighted by a tent (1 - |dx| / (fitStride + 1)) (1 - |dy| / ...) times the
// colour weight of p in that centre's fit (so a model is not carried across a colour edge the
// features do not explain) and the firefly weight of the centre for p (so a firefly's own model
// is not carried to its neighbours). Where those weights are below `minSupport` of the tent's (a pixel
// unlike every centre near it: a small highlight), p is fitted as a centre of its own.
//
// Selection: the denoised value d is then compared with the noisy one n, which is unbiased: where
// (d - n)² exceeds `keepThreshold` times n's variance V (the larger of the pixel's and its 3x3
// mean), the excess B² estimates d's squared bias, and the pixel becomes d + B² / (B² + V) (n - d),
// the blend of the two that minimises the expected error for that bias (a highlight the fit
// darkened comes back; noise alone rarely reaches the threshold). Layers take the beauty's blend.
//
// Speed: the fits' sums run four neighbours at a time (SSE) and are solved by Cholesky with a
// ridge on the feature terms; image rows are cut into bands on oneTBB. Every pixel is computed by
// the same operations whatever the band or thread, so the output is bit-identical at any thread
// count.
#pragma once

#include <stdexcept>
#include <vector>

namespace fluence::denoise {

// Per-pixel buffers, row-major, row 0 at the top; colours and vectors interleaved (3 floats).
struct DenoiseBuffers {
    int width = 0, height = 0;
    std::vector<float> halves[2];  // R G B: the first and second halves' means
    std::vector<float> variance;   // R G B: the variance of the beauty's mean
    std::vector<float> albedo;     // R G B
    std::vector<float> normal;     // X Y Z
    std::vector<float> depth;      // one per pixel (camera-space, > 0)
    // The variance of the albedo's and the normal's means, R G B and X Y Z (core/film.h); both
    // empty: the features are taken as noise-free (not prefiltered, denoise/feature_prefilter.h).
    std::vector<float> albedoVariance, normalVariance;
    std::vector<std::vector<float>> layers;  // R G B each: extra images fitted with the beauty's weights
};

struct DenoiseSettings {
    int radius = 4;               // the fit's window spans (2 radius + 1)² pixels (at most 8)
    int fitStride = 3;            // fits at every fitStride-th pixel in x and y
    float k = 0.6f;               // NL-means colour sensitivity: larger blurs more
    float ridge = 1e-3f;          // ridge on the feature coefficients, relative to the weights' sum
    float fireflyRatio = 8.0f;    // a neighbour's variance above this times its window's is cut
    float minSupport = 0.25f;     // below this share of the tent's weight, a pixel is fitted alone
    float keepThreshold = 16.0f;  // (denoised - noisy)² above this times the variance is bias
    int featureRadius = 4;        // the feature prefilter's window spans (2 featureRadius + 1)² (at most 8)
    float featureK = 2.0f;        // its NL-means sensitivity (denoise/feature_prefilter.h): larger blurs more
    int threads = 0;              // 0: oneTBB's default
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
