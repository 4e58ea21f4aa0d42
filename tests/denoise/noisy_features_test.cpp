// The denoiser where its features are noisy (denoise/feature_prefilter.h): a defocused edge between
// two albedos, where each sample's first hit lands on one side or the other, so the pixel's albedo
// is a mean of a few random surfaces and its colour's noise follows its albedo's. Every pixel's
// samples are drawn from fixed seeds; the margins come from the spread over those seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "denoise/denoiser.h"
#include "tests/denoise/flat_floor_buffers.h"

namespace fluence::denoise {
namespace {

constexpr int kSize = 64;
constexpr int kSamples = 16;
constexpr float kDark = 0.2f, kLight = 0.8f;
constexpr float kShadingNoise = 0.1f;  // the samples' noise beyond which surface they hit

// The share of a pixel's lens samples that land on the light side: a ramp over the 40 middle
// columns (the edge blurred by the lens), 0 and 1 beyond.
float lightShare(int x) { return std::clamp(float(x - 12) / 40.0f, 0.0f, 1.0f); }

// The expected colour: radiance = albedo (a white light), mixed over the lens.
float truth(int x) { return kDark + (kLight - kDark) * lightShare(x); }

// kSamples samples per pixel: each hits the light side with probability lightShare(x) and then has
// albedo kLight, else kDark, and a colour of its albedo plus Gaussian noise; the buffers as the
// film keeps them (halves, the variance of the mean, the features' means and their variance).
DenoiseBuffers defocusedEdge(unsigned seed) {
    DenoiseBuffers b = flatFloorBuffers(kSize);
    const std::size_t n = std::size_t(kSize) * kSize;
    b.albedoVariance.resize(3 * n);
    b.normalVariance.assign(3 * n, 0.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::normal_distribution<float> shading(0.0f, kShadingNoise);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::size_t p = std::size_t(y) * kSize + x;
            double sums[2] = {0, 0}, all = 0, squares = 0, albedo = 0, albedoSquares = 0;
            for (int s = 0; s < kSamples; ++s) {
                const double a = uniform(rng) < lightShare(x) ? kLight : kDark;
                const double v = a + shading(rng);
                sums[s % 2] += v;
                all += v;
                squares += v * v;
                albedo += a;
                albedoSquares += a * a;
            }
            const double mean = all / kSamples, albedoMean = albedo / kSamples;
            for (int c = 0; c < 3; ++c) {
                b.halves[0][3 * p + c] = float(sums[0] / (kSamples / 2));
                b.halves[1][3 * p + c] = float(sums[1] / (kSamples / 2));
                b.variance[3 * p + c] = float((squares - kSamples * mean * mean) / (kSamples - 1) / kSamples);
                b.albedo[3 * p + c] = float(albedoMean);
                b.albedoVariance[3 * p + c] =
                    float((albedoSquares - kSamples * albedoMean * albedoMean) / (kSamples - 1) / kSamples);
            }
        }
    return b;
}

// relMSE against truth(), as bench/denoise_quality measures it, over the blurred columns.
double relMse(const std::vector<float>& image) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 13; x < 52; ++x) {
            const double t = truth(x), d = image[3 * (std::size_t(y) * kSize + x)] - t;
            sum += d * d / (t * t + 0.01);
            ++count;
        }
    return sum / count;
}

DenoiseBuffers withoutFeatureVariance(DenoiseBuffers b) {
    b.albedoVariance.clear();
    b.normalVariance.clear();
    return b;
}

TEST(NoisyFeatures, DefocusedEdgeDenoisesBetterWithTheFeaturesVariance) {
    // Eight fixed seeds; on each, the relMSE of the denoised edge without the features' variance
    // (the regression fitted to the noisy albedo, which gives back the colour noise it shares) and
    // with it (the albedo prefiltered). The improvement d = without - with must be positive beyond
    // its spread: its mean above 3 standard errors (the seeds' standard deviation of d over
    // sqrt(8)), a one-sided t-test at p < 0.01 with 7 degrees of freedom.
    constexpr int kSeeds = 8;
    double sum = 0, squares = 0, ratioSum = 0;
    for (unsigned seed = 1; seed <= kSeeds; ++seed) {
        const DenoiseBuffers b = defocusedEdge(seed);
        const double with = relMse(denoise(b).beauty), without = relMse(denoise(withoutFeatureVariance(b)).beauty);
        sum += without - with;
        squares += (without - with) * (without - with);
        ratioSum += without / with;
    }
    const double mean = sum / kSeeds, spread = std::sqrt((squares - kSeeds * mean * mean) / (kSeeds - 1));
    EXPECT_GT(mean, 3.0 * spread / std::sqrt(double(kSeeds)))
        << "mean gain " << mean << ", spread " << spread << ", mean ratio " << ratioSum / kSeeds;
}

TEST(NoisyFeatures, ZeroFeatureVarianceChangesNothing) {
    // Clean features (variance 0 everywhere) are not prefiltered: the result is bit for bit the
    // denoiser's without the features' variance.
    DenoiseBuffers b = defocusedEdge(9);
    std::fill(b.albedoVariance.begin(), b.albedoVariance.end(), 0.0f);
    EXPECT_EQ(denoise(b).beauty, denoise(withoutFeatureVariance(b)).beauty);
}

TEST(NoisyFeatures, BitIdenticalAtAnyThreadCount) {
    const DenoiseBuffers b = defocusedEdge(10);
    DenoiseSettings settings;
    settings.threads = 1;
    const std::vector<float> one = denoise(b, settings).beauty;
    for (int threads : {2, 3, 8}) {
        settings.threads = threads;
        EXPECT_EQ(one, denoise(b, settings).beauty) << threads << " threads";
    }
}

TEST(NoisyFeatures, RefusesAFeatureVarianceOfTheWrongSize) {
    DenoiseBuffers b = defocusedEdge(11);
    b.normalVariance.pop_back();
    EXPECT_THROW(denoise(b), DenoiseError);
    b.normalVariance.clear();  // the albedo's variance without the normal's
    EXPECT_THROW(denoise(b), DenoiseError);
}

}  // namespace
}  // namespace fluence::denoise
