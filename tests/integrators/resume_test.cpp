// Resuming a render (RenderSettings::firstSample, onPass; integrators/renderer.h): a render stopped
// after a pass, its film saved (core/film_state.h) and read back into a new film, then rendered on
// from that pass, ends bit-identical to the render never stopped: with every pixel taking every
// sample, with adaptive sampling (pixels stopped at different counts), and with a method that keeps
// per-sample-index state between passes (sppm's photon maps and shrinking radii), and with light
// tracing's splats into other pixels (bdpt).
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <sstream>

#include "core/film_state.h"
#include "integrators/adaptive_sampling.h"
#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "integrators/sppm.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr int kSize = 20;

// Renders uninterrupted, then again stopping after the pass that reaches `stopAt` samples per pixel
// (saving the film there, as a checkpoint does), then resumed from the saved film; expects the
// resumed image to equal the uninterrupted one bit for bit.
void expectResumedEqualsUninterruptedWith(const Integrator& integrator, RenderSettings settings, int stopAt) {
    const render::SceneDescription desc = test::litSphereUnderASky();
    const test_support::RenderedFilm whole = test_support::renderFilm(integrator, desc, kSize, settings);

    std::atomic<bool> stop{false};
    std::stringstream saved;
    int savedAt = -1;
    RenderSettings first = settings;
    first.stop = &stop;
    first.onPass = [&](int samplesDone) {
        ASSERT_FALSE(stop.load()) << "onPass after the stop";
        if (samplesDone < stopAt) return;
        savedAt = samplesDone;
        stop = true;  // the next pass never starts, as if the process were killed here
    };
    const test_support::RenderedFilm stopped = test_support::renderFilm(integrator, desc, kSize, first);
    ASSERT_EQ(savedAt, stopAt) << "pass boundaries are 1, 3, 7, 15, 31, ... (adaptive: minSamples among them)";
    EXPECT_TRUE(stopped.stats.interrupted);
    writeFilmState(stopped.film, saved);

    render::RenderScene renderScene(desc);
    render::Camera camera(*desc.camera, kSize, kSize);
    Film film(kSize, kSize, camera.farClip());
    if (AdaptiveSampling::enabled(settings)) film.enableDenoiseBuffers();  // what adaptive sampling reads
    readFilmState(saved, film);
    RenderSettings resumed = settings;
    resumed.firstSample = savedAt;
    const RenderStats stats = render(renderScene, camera, integrator, resumed, film);
    EXPECT_FALSE(stats.interrupted);

    const Image a = whole.film.resolve(), b = film.resolve();
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
    EXPECT_EQ(whole.film.totalSamples(), film.totalSamples());
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            ASSERT_EQ(whole.film.cost(x, y), film.cost(x, y)) << "the costs adaptive sampling's budget reads";
}

// The same, under each sampler.
void expectResumedEqualsUninterrupted(const Integrator& integrator, RenderSettings settings, int stopAt) {
    for (SamplerKind sampler : test_support::kSamplers) {
        SCOPED_TRACE(sampler == SamplerKind::Sobol ? "sobol" : "independent");
        settings.sampler = sampler;
        expectResumedEqualsUninterruptedWith(integrator, settings, stopAt);
    }
}

TEST(Resume, EveryPixelEverySample) {
    RenderSettings settings;
    settings.samplesPerPixel = 40;
    expectResumedEqualsUninterrupted(PathTracer(IntegratorSettings{}), settings, 15);
}

TEST(Resume, AdaptiveSamplingGoesOnFromEachPixelsOwnCount) {
    RenderSettings settings;
    settings.samplesPerPixel = 200;
    settings.targetError = 0.05;
    settings.minSamples = 8;
    const test_support::RenderedFilm whole =
        test_support::renderFilm(PathTracer(IntegratorSettings{}), test::litSphereUnderASky(), kSize, settings);
    std::uint32_t least = 1000, most = 0;  // the test means something only if pixels stopped apart
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            least = std::min(least, whole.film.samples(x, y));
            most = std::max(most, whole.film.samples(x, y));
        }
    ASSERT_LT(least, 31u);
    ASSERT_GT(most, 63u);
    expectResumedEqualsUninterrupted(PathTracer(IntegratorSettings{}), settings, 35);
}

TEST(Resume, AdaptiveSamplingToABudgetToo) {
    RenderSettings settings;
    settings.samplesPerPixel = 200;
    settings.meanSamplesPerPixel = 40;
    settings.minSamples = 8;
    expectResumedEqualsUninterrupted(PathTracer(IntegratorSettings{}), settings, 35);
}

TEST(Resume, PhotonMappingKeepsItsPerSampleState) {
    SppmSettings sppm;
    sppm.photonPathsPerMap = 2000;
    RenderSettings settings;
    settings.samplesPerPixel = 12;
    expectResumedEqualsUninterrupted(Sppm(IntegratorSettings{}, sppm), settings, 7);
}

TEST(Resume, LightTracingSplatsGoOnToo) {
    IntegratorSettings integratorSettings;
    integratorSettings.maxDepth = 3;
    RenderSettings settings;
    settings.samplesPerPixel = 10;
    expectResumedEqualsUninterrupted(Bdpt(integratorSettings), settings, 3);
}

}  // namespace
}  // namespace fluence::integrators
