// Adaptive sampling's decisions on synthetic films (integrators/adaptive_sampling.h): samples added
// by hand, flat (every sample the same) or noisy (two values in a hashed order), then the plan of
// the next pass read. A flat region stops and a noisy one goes on; a pixel whose own halves agree
// by luck amid noisy neighbours goes on; the neighbours of a lone noisy pixel in a flat area go on
// (it is judged by them, not by its own samples), up to the edge of its block; the budget rule gives the
// noisier region more, and of two regions alike but for their cost per sample, the cheaper one
// more, as sqrt(1 / cost).
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "core/film.h"
#include "integrators/adaptive_sampling.h"
#include "integrators/renderer.h"

namespace fluence::integrators {
namespace {

constexpr int kWidth = 16, kHeight = 8, kDone = 16, kCount = 16;  // a pass doubles the samples

// A value of pixel (x, y)'s sample i: `level`, plus or minus `spread` in a hashed order.
float sampleValue(int x, int y, int i, float level, float spread) {
    std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(i) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return level + ((h & 1u) ? spread : -spread);
}

// A film of kDone samples per pixel, pixel (x, y) spreading its samples by spread(x, y) about 0.5,
// each sample costing cost(x, y); the values of pixel (x, y) are those of pixel (x % valuesRepeat, y).
Film syntheticFilm(const std::function<float(int, int)>& spread, const std::function<double(int, int)>& cost = {},
                   int valuesRepeat = kWidth) {
    Film film(kWidth, kHeight, 100.0f);
    film.enableDenoiseBuffers();
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int i = 0; i < kDone; ++i) {
                FilmSample s{};
                s.radiance = RGB(sampleValue(x % valuesRepeat, y, i, 0.5f, spread(x, y)));
                film.add(x, y, s, cost ? cost(x, y) : 1.0);
            }
    return film;
}

RenderSettings targetSettings() {
    RenderSettings settings;
    settings.samplesPerPixel = 1024;
    settings.targetError = 0.05;
    settings.minSamples = kDone;
    return settings;
}

std::uint32_t planned(const std::vector<std::uint32_t>& plan, int x, int y) {
    return plan[std::size_t(y) * kWidth + x];
}

TEST(AdaptiveStoppingRule, AFlatRegionStopsAndANoisyOneGoesOn) {
    const Film film = syntheticFilm([](int x, int) { return x < 8 ? 0.0f : 0.4f; });
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, targetSettings(), kDone, kCount);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            EXPECT_EQ(planned(plan, x, y), x < 8 ? 0u : std::uint32_t(kCount)) << x << ", " << y;
}

TEST(AdaptiveStoppingRule, BeforeMinSamplesEveryPixelGoesOn) {
    const Film film = syntheticFilm([](int, int) { return 0.0f; });
    RenderSettings settings = targetSettings();
    settings.minSamples = 32;
    for (std::uint32_t n : AdaptiveSampling::planPass(film, settings, kDone, kCount))
        EXPECT_EQ(n, std::uint32_t(kCount));
}

TEST(AdaptiveStoppingRule, APixelWhoseHalvesAgreeByLuckAmidNoiseGoesOn) {
    const Film film = syntheticFilm([](int x, int y) { return x == 11 && y == 3 ? 0.0f : 0.4f; });
    EXPECT_EQ(AdaptiveSampling::neighbourhoodVariances(film, 0, 0).size(), std::size_t(kWidth * kHeight));
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, targetSettings(), kDone, kCount);
    EXPECT_EQ(planned(plan, 11, 3), std::uint32_t(kCount));
}

TEST(AdaptiveStoppingRule, ALoneNoisyPixelKeepsItsNeighbourhoodGoingWithinItsBlock) {
    // Pixel (3, 3) noisy in a flat image, and (7, 5) at its block's right edge.
    const Film film =
        syntheticFilm([](int x, int y) { return (x == 3 && y == 3) || (x == 7 && y == 5) ? 0.4f : 0.0f; });
    // Their halves' sums of signs are -2 and 0 (3, 3) and 2 and 0 (7, 5): the halves differ by 0.1,
    // their own a is 0.19 and 0.13 (see adaptive_sampling.h). A neighbour averages that with 7 flat
    // pixels: a = 0.024 or 0.016, a relative error of 0.038 or 0.032 at 16 samples, which the
    // target must be below for the neighbours to go on.
    RenderSettings settings = targetSettings();
    settings.targetError = 0.02;
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, settings, kDone, kCount);
    for (int y = 2; y <= 4; ++y)
        for (int x = 2; x <= 4; ++x)
            if (x != 3 || y != 3) {
                EXPECT_EQ(planned(plan, x, y), std::uint32_t(kCount)) << x << ", " << y;
            }
    EXPECT_EQ(planned(plan, 3, 3), 0u) << "its own decision reads its neighbours only (no bias from its own mean)";
    EXPECT_EQ(planned(plan, 0, 0), 0u) << "away from it, the flat image stops";
    EXPECT_EQ(planned(plan, 6, 5), std::uint32_t(kCount));
    EXPECT_EQ(planned(plan, 8, 5), 0u) << "the next block decides on its own pixels";
    // Seen as a window of the image starting 1 pixel further right, the blocks move: (7, 5) is then
    // image pixel 8, the first of its block, and (6, 5) is in the block before it.
    RenderSettings window = settings;
    window.windowX = 1;
    window.imageWidth = kWidth + 1;
    const std::vector<std::uint32_t> moved = AdaptiveSampling::planPass(film, window, kDone, kCount);
    EXPECT_EQ(planned(moved, 6, 5), 0u);
    EXPECT_EQ(planned(moved, 8, 5), std::uint32_t(kCount));
}

bool isPowerOfTwo(std::uint32_t n) { return n > 0 && (n & (n - 1)) == 0; }

TEST(AdaptiveStoppingRule, ABudgetGoesToTheNoisierPixelsAndStopsTheFlatOnes) {
    // Left flat, middle a little noisy, right very noisy; a budget between what the pixels have
    // and every pixel going on.
    const Film film = syntheticFilm([](int x, int) { return x < 6 ? 0.0f : x < 11 ? 0.05f : 0.4f; });
    RenderSettings settings = targetSettings();
    settings.targetError = 0.0;
    settings.meanSamplesPerPixel = 24.0;
    const std::vector<std::uint32_t> counts = AdaptiveSampling::budgetCounts(film, settings, kDone);
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, settings, kDone, kCount);
    std::uint64_t total = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::uint32_t n = counts[std::size_t(y) * kWidth + x];
            total += n;
            EXPECT_TRUE(isPowerOfTwo(n)) << x << ", " << y << ": " << n;
            EXPECT_EQ(planned(plan, x, y), n > kDone ? std::uint32_t(kCount) : 0u) << "the pass doubles them";
            if (x < 5) {
                EXPECT_EQ(n, std::uint32_t(kDone)) << x << ", " << y;
            }
            if (x >= 12) {
                EXPECT_LE(counts[std::size_t(y) * kWidth + 8], n) << x << ", " << y;
            }
        }
    EXPECT_GT(counts[4 * kWidth + 13], counts[4 * kWidth + 8]);
    // The steps taken cost at most the budget, and the cheapest left out (16 samples of a pixel)
    // did not fit in what was left.
    const double budget = settings.meanSamplesPerPixel * kWidth * kHeight;
    EXPECT_LE(double(total), budget);
    EXPECT_GT(double(total), budget - kDone);
    settings.meanSamplesPerPixel = kDone;
    for (std::uint32_t n : AdaptiveSampling::planPass(film, settings, kDone, kCount)) EXPECT_EQ(n, 0u) << "spent";
}

TEST(AdaptiveStoppingRule, ABudgetWeighsEachPixelByItsCostPerSample) {
    // The right block's pixels have the left block's values (so the same variance estimates) but
    // cost 4 per sample against 1: a step from n to 2n gains a / (2 c n^2), so a right pixel at n
    // gains what its left twin gains at 2n, and the left ends with twice the right's count (the
    // continuous optimum, sqrt(a / c), says the same). At the budget's margin the left pixel's next
    // step ties with its twin's, and the lower index goes first: there the left has 4x. The budget is what kDone + 24 uniform
    // samples would cost, so that few counts reach a bound.
    const Film film = syntheticFilm([](int, int) { return 0.4f; }, [](int x, int) { return x < 8 ? 1.0 : 4.0; }, 8);
    const std::vector<double> costs = AdaptiveSampling::neighbourhoodCosts(film, 0, 0);
    EXPECT_EQ(costs[3], 1.0);
    EXPECT_EQ(costs[11], 4.0);
    RenderSettings settings = targetSettings();
    settings.targetError = 0.0;
    settings.meanSamplesPerPixel = kDone + 24;
    settings.samplesPerPixel = 1024;
    const std::vector<std::uint32_t> counts = AdaptiveSampling::budgetCounts(film, settings, kDone);
    double spent = 0.0, budget = 0.0;
    int pairs = 0, twice = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double perSample = x < 8 ? 1.0 : 4.0;
            const std::uint32_t n = counts[std::size_t(y) * kWidth + x];
            EXPECT_TRUE(isPowerOfTwo(n)) << x << ", " << y << ": " << n;
            spent += perSample * n;
            budget += perSample * settings.meanSamplesPerPixel;
            if (x >= 8) continue;
            const std::uint32_t right = counts[std::size_t(y) * kWidth + x + 8];
            if (right > std::uint32_t(kDone)) {  // not at the bound (where the halves agree by luck, a
                ++pairs;                         // pixel stops at once)
                twice += n == 2 * right;
                EXPECT_TRUE(n == 2 * right || n == 4 * right) << x << ", " << y << ": " << n << " and " << right;
            }
        }
    EXPECT_GE(pairs, kWidth * kHeight / 4) << "at least half the pairs are compared";
    EXPECT_GE(twice, pairs / 2) << "the margin's ties are few";
    EXPECT_LE(spent, budget);
    EXPECT_GT(spent, 0.9 * budget);
}

}  // namespace
}  // namespace fluence::integrators
