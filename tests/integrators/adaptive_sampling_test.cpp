// Adaptive sampling (RenderSettings::targetError and meanSamplesPerPixel, integrators/renderer.h,
// integrators/adaptive_sampling.h) on a rendered scene: pixels that converge early stop early and
// the noisy ones go on; a budget is spent as asked; the image is the same for any thread count and
// for windows whose edges fall on block edges (tiles); its mean agrees with uniform sampling's
// (stopping on an error estimate must not bias it visibly); without a rule every pixel takes every
// sample.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "integrators/adaptive_sampling.h"
#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"
#include "tests/support/statistics.h"

namespace fluence::integrators {
namespace {

constexpr int kSize = 24, kMaxSpp = 256, kMinSpp = 8;
constexpr double kTarget = 0.03;

RenderSettings adaptiveSettings(double targetError, double meanSpp, int threads, SamplerKind sampler) {
    RenderSettings settings;
    settings.sampler = sampler;
    settings.samplesPerPixel = kMaxSpp;
    settings.targetError = targetError;
    settings.meanSamplesPerPixel = meanSpp;
    settings.minSamples = kMinSpp;
    settings.threads = threads;
    return settings;
}

test_support::RenderedFilm renderAdaptively(double targetError, int threads, SamplerKind sampler = SamplerKind::Sobol,
                                            double meanSpp = 0.0) {
    return test_support::renderFilm(PathTracer(IntegratorSettings{}), test::litSphereUnderASky(), kSize,
                                    adaptiveSettings(targetError, meanSpp, threads, sampler));
}

TEST(AdaptiveSampling, EasyPixelsStopEarlyAndNoisyOnesGoOn) {
    const auto [film, stats] = renderAdaptively(kTarget, 0);
    int atMinimum = 0, atMaximum = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::uint32_t n = film.samples(x, y);
            ASSERT_GE(n, std::uint32_t(kMinSpp));
            ASSERT_LE(n, std::uint32_t(kMaxSpp));
            atMinimum += n == kMinSpp;
            atMaximum += n == kMaxSpp;
        }
    const double mean = double(film.totalSamples()) / (kSize * kSize);
    std::printf("[ measured ] %d pixels stopped at %d spp, %d ran to %d; %.1f spp on average\n", atMinimum, kMinSpp,
                atMaximum, kMaxSpp, mean);
    EXPECT_GT(atMinimum, 0) << "the sky seen directly has no noise";
    EXPECT_GT(mean, 2.0 * kMinSpp) << "the lit sphere needs more";
    EXPECT_LT(mean, kMaxSpp);
    EXPECT_EQ(stats.samples, film.totalSamples());
}

TEST(AdaptiveSampling, ABudgetIsSpentAsAsked) {
    for (double meanSpp : {24.0, 64.0}) {
        const Film film = renderAdaptively(0.0, 0, SamplerKind::Independent, meanSpp).film;
        std::uint32_t least = kMaxSpp, most = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                least = std::min(least, film.samples(x, y));
                most = std::max(most, film.samples(x, y));
            }
        const double mean = double(film.totalSamples()) / (kSize * kSize);
        std::printf("[ measured ] budget %g: %.2f spp on average, %u to %u\n", meanSpp, mean, least, most);
        EXPECT_NEAR(mean, meanSpp, 0.03 * meanSpp);
        EXPECT_EQ(least, std::uint32_t(kMinSpp)) << "the sky";
        EXPECT_GT(most, 2 * meanSpp) << "the sphere's edge";
    }
}

TEST(AdaptiveSampling, IsTheSameForAnyThreadCount) {
    for (SamplerKind sampler : test_support::kSamplers)
        for (double meanSpp : {0.0, 48.0}) {
            const double target = meanSpp > 0.0 ? 0.0 : kTarget;
            const Image one = renderAdaptively(target, 1, sampler, meanSpp).film.resolve();
            const Image two = renderAdaptively(target, 2, sampler, meanSpp).film.resolve();
            ASSERT_EQ(one.pixels.size(), two.pixels.size());
            EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)))
                << "mean spp " << meanSpp;
        }
}

TEST(AdaptiveSampling, WindowsOnBlockEdgesAssembleIntoTheWholeImage) {
    static_assert(kSize % AdaptiveSampling::kBlockSize == 0);
    const render::SceneDescription desc = test::litSphereUnderASky();
    const RenderSettings settings = adaptiveSettings(kTarget, 0.0, 2, SamplerKind::Sobol);
    const Image whole =
        test_support::renderFilm(PathTracer(IntegratorSettings{}), desc, kSize, settings).film.resolve();
    render::RenderScene scene(desc);
    const render::Camera camera(*desc.camera, kSize, kSize);
    const int edge = AdaptiveSampling::kBlockSize;  // windows: [0, 8) and [8, 24) on each axis
    for (int wy : {0, edge})
        for (int wx : {0, edge}) {
            const int w = wx == 0 ? edge : kSize - edge, h = wy == 0 ? edge : kSize - edge;
            RenderSettings window = settings;
            window.windowX = wx;
            window.windowY = wy;
            window.imageWidth = kSize;
            Film film(w, h, camera.farClip());
            render(scene, camera, PathTracer(IntegratorSettings{}), window, film);
            const Image part = film.resolve();
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (std::size_t c = 0; c < part.channelCount(); ++c)
                        ASSERT_EQ(part.pixel(x, y)[c], whole.pixel(wx + x, wy + y)[c])
                            << "pixel " << wx + x << ", " << wy + y << " channel " << c;
        }
}

// The image's mean over seeds, adaptive against uniform at about the same samples: within Welch's
// band at significance 1e-3. The scene's edge pixels are where stopping could bias most.
TEST(AdaptiveSampling, TheImageMeanAgreesWithUniformSampling) {
    constexpr int kSeeds = 24;
    auto imageMean = [](const RenderSettings& settings) {
        const Image image =
            test_support::renderFilm(PathTracer(IntegratorSettings{}), test::litSphereUnderASky(), 16, settings)
                .film.resolve();
        double sum = 0.0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                for (int c = 0; c < 3; ++c) sum += image.pixel(x, y)[c];
        return sum / (16 * 16 * 3);
    };
    for (double meanSpp : {0.0, 32.0}) {
        test::MeanEstimate adaptive, uniform;
        for (int seed = 0; seed < kSeeds; ++seed) {
            RenderSettings a = adaptiveSettings(meanSpp > 0.0 ? 0.0 : 0.1, meanSpp, 0, SamplerKind::Independent);
            a.seed = std::uint64_t(seed);
            adaptive.add(imageMean(a));
            RenderSettings u;
            u.samplesPerPixel = 32;
            u.seed = std::uint64_t(1000 + seed);
            uniform.add(imageMean(u));
        }
        const double band = test::welchBand(adaptive, uniform, 1e-3);
        std::printf("[ measured ] %s: adaptive %.5f +- %.5f, uniform %.5f +- %.5f, band %.5f\n",
                    meanSpp > 0.0 ? "budget" : "target", adaptive.mean(), adaptive.unbiasedStandardError(),
                    uniform.mean(), uniform.unbiasedStandardError(), band);
        EXPECT_GT(band, 0.0);
        EXPECT_NEAR(adaptive.mean(), uniform.mean(), band);
    }
}

TEST(AdaptiveSampling, WithoutATargetEveryPixelTakesEverySample) {
    const Film film = renderAdaptively(0.0, 0).film;
    EXPECT_EQ(film.totalSamples(), std::uint64_t(kSize) * kSize * kMaxSpp);
}

}  // namespace
}  // namespace fluence::integrators
