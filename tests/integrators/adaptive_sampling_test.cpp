// Adaptive sampling (RenderSettings::targetError, integrators/renderer.h): pixels that converge
// early stop early and the noisy ones go on; every pixel that stopped before the maximum has reached
// the target; the image is still the same for any thread count; and without a target every pixel
// takes every sample.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr int kSize = 24, kMaxSpp = 256, kMinSpp = 8;
constexpr double kTarget = 0.03;

test_support::RenderedFilm renderAdaptively(double targetError, int threads, SamplerKind sampler = SamplerKind::Sobol) {
    RenderSettings settings;
    settings.sampler = sampler;
    settings.samplesPerPixel = kMaxSpp;
    settings.targetError = targetError;
    settings.minSamples = kMinSpp;
    settings.threads = threads;
    return test_support::renderFilm(PathTracer(IntegratorSettings{}), test::litSphereUnderASky(), kSize, settings);
}

TEST(AdaptiveSampling, EasyPixelsStopEarlyAndEveryStoppedPixelReachedTheTarget) {
    const auto [film, stats] = renderAdaptively(kTarget, 0);
    int atMinimum = 0, atMaximum = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::uint32_t n = film.samples(x, y);
            ASSERT_GE(n, std::uint32_t(kMinSpp));
            ASSERT_LE(n, std::uint32_t(kMaxSpp));
            atMinimum += n == kMinSpp;
            atMaximum += n == kMaxSpp;
            if (n < kMaxSpp) {
                EXPECT_LE(film.relativeError(x, y), kTarget) << x << ", " << y;
            }
        }
    const double mean = double(film.totalSamples()) / (kSize * kSize);
    std::printf("[ measured ] %d pixels stopped at %d spp, %d ran to %d; %.1f spp on average\n", atMinimum, kMinSpp,
                atMaximum, kMaxSpp, mean);
    EXPECT_GT(atMinimum, 0) << "the sky seen directly has no noise";
    EXPECT_GT(mean, 2.0 * kMinSpp) << "the lit sphere needs more";
    EXPECT_LT(mean, kMaxSpp);
    EXPECT_EQ(stats.samples, film.totalSamples());
}

TEST(AdaptiveSampling, IsTheSameForAnyThreadCount) {
    for (SamplerKind sampler : test_support::kSamplers) {
        const Image one = renderAdaptively(kTarget, 1, sampler).film.resolve();
        const Image two = renderAdaptively(kTarget, 2, sampler).film.resolve();
        ASSERT_EQ(one.pixels.size(), two.pixels.size());
        EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)));
    }
}

TEST(AdaptiveSampling, WithoutATargetEveryPixelTakesEverySample) {
    const Film film = renderAdaptively(0.0, 0).film;
    EXPECT_EQ(film.totalSamples(), std::uint64_t(kSize) * kSize * kMaxSpp);
}

}  // namespace
}  // namespace fluence::integrators
