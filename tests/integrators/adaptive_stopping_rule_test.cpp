// Adaptive sampling's decisions on synthetic films (integrators/adaptive_sampling.h): samples added
// by hand, flat (every sample the same) or noisy (two values in a hashed order), then the plan of
// the next pass read. A flat region stops and a noisy one goes on; a pixel whose own halves agree
// by luck amid noisy neighbours goes on; the pixels within 2 of a lone noisy pixel in a flat area
// go on (it is judged by them, not by its own samples), up to the edge of its block; the budget rule gives the
// noisier region more, and of two regions alike but for their cost per sample, the cheaper one
// more, as sqrt(1 / cost); the budget rule floors a pixel's estimate by its block's mean.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "core/film.h"
#include "integrators/adaptive_sampling.h"
#include "integrators/renderer.h"

namespace fluence::integrators {
namespace {

constexpr int kWidth = 16, kHeight = 8, kDone = 16, kCount = 17;

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
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, targetSettings(), kDone, kCount).samples;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            EXPECT_EQ(planned(plan, x, y), x < 8 ? 0u : std::uint32_t(kCount)) << x << ", " << y;
}

TEST(AdaptiveStoppingRule, BeforeMinSamplesEveryPixelGoesOn) {
    const Film film = syntheticFilm([](int, int) { return 0.0f; });
    RenderSettings settings = targetSettings();
    settings.minSamples = 32;
    for (std::uint32_t n : AdaptiveSampling::planPass(film, settings, kDone, kCount).samples)
        EXPECT_EQ(n, std::uint32_t(kCount));
}

TEST(AdaptiveStoppingRule, APixelWhoseHalvesAgreeByLuckAmidNoiseGoesOn) {
    const Film film = syntheticFilm([](int x, int y) { return x == 11 && y == 3 ? 0.0f : 0.4f; });
    EXPECT_EQ(AdaptiveSampling::neighbourhoodVariances(film, 0, 0).size(), std::size_t(kWidth * kHeight));
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, targetSettings(), kDone, kCount).samples;
    EXPECT_EQ(planned(plan, 11, 3), std::uint32_t(kCount));
}

TEST(AdaptiveStoppingRule, ALoneNoisyPixelKeepsItsNeighbourhoodGoingWithinItsBlock) {
    // Pixel (3, 3) noisy in a flat image, and (7, 5) at its block's right edge.
    const Film film =
        syntheticFilm([](int x, int y) { return (x == 3 && y == 3) || (x == 7 && y == 5) ? 0.4f : 0.0f; });
    // Their halves' sums of signs are -2 and 0 (3, 3) and 2 and 0 (7, 5): the halves differ by 0.1,
    // their own a is 0.19 and 0.13 (see adaptive_sampling.h). A pixel within 2 of them averages that
    // with at most 23 flat pixels (fewer at the block's edges): a >= 0.19 / 24 = 0.0079 or
    // 0.13 / 19 = 0.0068, a relative error of at least 0.022 or 0.021 at 16 samples, which the
    // target must be below for the neighbours to go on. With the 3x3 neighbourhood the pixels 2
    // away from them stopped.
    RenderSettings settings = targetSettings();
    settings.targetError = 0.02;
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, settings, kDone, kCount).samples;
    for (int y = 1; y <= 5; ++y)
        for (int x = 1; x <= 5; ++x)
            if (x != 3 || y != 3) {
                EXPECT_EQ(planned(plan, x, y), std::uint32_t(kCount)) << x << ", " << y;
            }
    EXPECT_EQ(planned(plan, 3, 3), 0u) << "its own decision reads its neighbours only (no bias from its own mean)";
    EXPECT_EQ(planned(plan, 0, 0), 0u) << "away from it, the flat image stops";
    EXPECT_EQ(planned(plan, 6, 5), std::uint32_t(kCount));
    EXPECT_EQ(planned(plan, 5, 7), std::uint32_t(kCount));
    EXPECT_EQ(planned(plan, 8, 5), 0u) << "the next block decides on its own pixels";
    // Seen as a window of the image starting 1 pixel further right, the blocks move: (7, 5) is then
    // image pixel 8, the first of its block, and (6, 5) is in the block before it.
    RenderSettings window = settings;
    window.windowX = 1;
    window.imageWidth = kWidth + 1;
    const std::vector<std::uint32_t> moved = AdaptiveSampling::planPass(film, window, kDone, kCount).samples;
    EXPECT_EQ(planned(moved, 6, 5), 0u);
    EXPECT_EQ(planned(moved, 8, 5), std::uint32_t(kCount));
}

// Heavy tails: a rare bright sample seen in one pixel of a block is a sign of the block's error,
// but the 5x5 neighbourhood of a pixel 3 or more away does not hold it. The budget rule floors a
// pixel's a by its block's mean (the pixel itself left out): a lone noisy pixel at (1, 1) gives
// (6, 6), beyond its 5x5 neighbourhood, 1/63 of its a, which its 24 neighbours within 2 average
// as 1/24; the pixel itself reads its flat neighbours and stops; the next block is flat and stops.
TEST(AdaptiveStoppingRule, ABudgetFloorsAPixelsVarianceByItsBlocksMean) {
    const Film film = syntheticFilm([](int x, int y) { return x == 1 && y == 1 ? 0.4f : 0.0f; });
    const std::vector<double> local = AdaptiveSampling::neighbourhoodVariances(film, 0, 0);
    const std::vector<double> floored = AdaptiveSampling::budgetVariances(film, 0, 0);
    const std::size_t far = 6 * kWidth + 6, near = 2 * kWidth + 2;
    ASSERT_GT(local[near], 0.0);
    EXPECT_EQ(local[far], 0.0);
    EXPECT_NEAR(floored[far], local[near] * 24.0 / 63.0, 1e-12 * local[near]);
    EXPECT_EQ(floored[near], local[near]) << "the larger of the two";
    RenderSettings settings = targetSettings();
    settings.targetError = 0.0;
    settings.meanSamplesPerPixel = 24.0;
    settings.samplesPerPixel = kDone + kCount;
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, settings, kDone, kCount).samples;
    EXPECT_GT(planned(plan, 6, 6), 0u);
    EXPECT_EQ(planned(plan, 1, 1), 0u) << "its own decision reads its neighbours only";
    EXPECT_EQ(planned(plan, 12, 4), 0u) << "the next block";
}

TEST(AdaptiveStoppingRule, ABudgetGoesToTheNoisierPixelsAndStopsTheFlatOnes) {
    // Left flat, middle a little noisy, right very noisy; a budget between what the pixels have
    // and every pixel going on.
    const Film film = syntheticFilm([](int x, int) { return x < 6 ? 0.0f : x < 11 ? 0.05f : 0.4f; });
    RenderSettings settings = targetSettings();
    settings.targetError = 0.0;
    settings.meanSamplesPerPixel = 24.0;
    settings.samplesPerPixel = kDone + kCount;  // so that this pass can spend the whole budget
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, settings, kDone, kCount).samples;
    std::uint64_t total = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            total += kDone + planned(plan, x, y);
            if (x < 5) {
                EXPECT_EQ(planned(plan, x, y), 0u) << x << ", " << y;
            }
            if (x == 8 || x >= 12) {
                EXPECT_LE(planned(plan, 8, y), planned(plan, x, y)) << x << ", " << y;
            }
        }
    EXPECT_GT(planned(plan, 13, 4), planned(plan, 8, 4));
    const double mean = double(total) / (kWidth * kHeight);
    EXPECT_NEAR(mean, settings.meanSamplesPerPixel, 1.0) << "the budget is spent, per pixel rounded";
    settings.meanSamplesPerPixel = kDone;
    for (std::uint32_t n : AdaptiveSampling::planPass(film, settings, kDone, kCount).samples)
        EXPECT_EQ(n, 0u) << "spent";
}

TEST(AdaptiveStoppingRule, ABudgetWeighsEachPixelByItsCostPerSample) {
    // The right block's pixels have the left block's values (so the same variance estimates) but
    // cost 4 per sample against 1: the best counts for the cost go as sqrt(a / c), half as many on
    // the right. The budget is what kDone + 24 uniform samples would cost: about 66 samples on the
    // left and 33 on the right, so that few counts reach a bound.
    const Film film = syntheticFilm([](int, int) { return 0.4f; }, [](int x, int) { return x < 8 ? 1.0 : 4.0; }, 8);
    const std::vector<double> costs = AdaptiveSampling::neighbourhoodCosts(film, 0, 0);
    EXPECT_EQ(costs[3], 1.0);
    EXPECT_EQ(costs[11], 4.0);
    RenderSettings settings = targetSettings();
    settings.targetError = 0.0;
    settings.meanSamplesPerPixel = kDone + 24;
    settings.samplesPerPixel = kDone + 128;
    const std::vector<std::uint32_t> plan = AdaptiveSampling::planPass(film, settings, kDone, 128).samples;
    double spent = 0.0, budget = 0.0;
    int pairs = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double perSample = x < 8 ? 1.0 : 4.0;
            spent += perSample * (kDone + planned(plan, x, y));
            budget += perSample * settings.meanSamplesPerPixel;
            if (x >= 8) continue;
            const double left = kDone + planned(plan, x, y), right = kDone + planned(plan, x + 8, y);
            if (right > kDone && left < kDone + 128) {  // neither at a bound (where the halves agree by
                ++pairs;                                // luck, a pixel stops at once)
                EXPECT_NEAR(left, 2.0 * right, 1.0) << x << ", " << y << ": each rounded to a whole sample";
            }
        }
    EXPECT_GE(pairs, kWidth * kHeight / 4) << "at least half the pairs are compared";
    // Each pixel's count is rounded: at most half a sample of its cost either way.
    EXPECT_NEAR(spent, budget, 0.5 * 8 * (1.0 + 4.0) * kHeight);
}

}  // namespace
}  // namespace fluence::integrators
