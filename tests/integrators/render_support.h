// Shared by the integrator tests: render a SceneDescription with an integrator into an Image, and
// average a channel (or the difference of two images) over selected pixels with its standard error.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>

#include "integrators/integrator.h"
#include "integrators/renderer.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "tests/support/statistics.h"

namespace fluence::integrators::test_support {

struct Rendered {
    Image image;
    RenderStats stats;
};

struct RenderedFilm {
    Film film;
    RenderStats stats;
};

// A size x size render of `desc` through its camera with `settings`, as the film itself (for its
// per-pixel statistics).
inline RenderedFilm renderFilm(const Integrator& integrator, const render::SceneDescription& desc, int size,
                               const RenderSettings& settings) {
    render::RenderScene scene(desc);
    render::Camera camera(*desc.camera, size, size);
    Film film(size, size, camera.farClip());
    RenderStats stats = render(scene, camera, integrator, settings, film);
    return {std::move(film), stats};
}

// Over the pixels where `select` holds, the mean of channel c's difference a - b with its standard
// error. Where both images estimate the same values, each difference has mean 0 (pixels differ in
// expected value, their differences do not), so the spread of the differences is their noise.
inline test::MeanEstimate meanDifference(const Image& a, const Image& b, int c,
                                         const std::function<bool(int, int)>& select) {
    test::MeanEstimate e;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (select(x, y)) e.add(double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]));
    return e;
}

// The samplers (core/random.h), for tests that hold for each.
inline constexpr SamplerKind kSamplers[] = {SamplerKind::Sobol, SamplerKind::Independent};

// A size x size render of `desc` through its camera, `spp` samples per pixel.
inline Rendered renderWith(const Integrator& integrator, const render::SceneDescription& desc, int size, int spp,
                           int threads = 0, std::uint64_t seed = 0, SamplerKind sampler = SamplerKind::Sobol) {
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.threads = threads;
    settings.seed = seed;
    settings.sampler = sampler;
    RenderedFilm r = renderFilm(integrator, desc, size, settings);
    return {r.film.resolve(), r.stats};
}

// Under `sampler`, `desc` rendered (size x size, 8 samples per pixel, seed 5) on 1 and 2 threads,
// and the tile at (20, 24) of 24 x 16 pixels rendered alone, agree bit for bit.
inline void expectBitIdenticalAcrossThreadCountsAndTiles(const Integrator& integrator,
                                                         const render::SceneDescription& desc, int size,
                                                         SamplerKind sampler) {
    const Rendered one = renderWith(integrator, desc, size, 8, 1, 5, sampler);
    const Rendered two = renderWith(integrator, desc, size, 8, 2, 5, sampler);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    EXPECT_EQ(0,
              std::memcmp(one.image.pixels.data(), two.image.pixels.data(), one.image.pixels.size() * sizeof(float)));

    const render::RenderScene scene(desc);
    const render::Camera camera(*desc.camera, size, size);
    RenderSettings settings;
    settings.samplesPerPixel = 8;
    settings.seed = 5;
    settings.sampler = sampler;
    settings.windowX = 20;
    settings.windowY = 24;
    settings.imageWidth = size;
    Film film(24, 16, camera.farClip());
    render(scene, camera, integrator, settings, film);
    const Image tile = film.resolve();
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x)
            ASSERT_EQ(
                0, std::memcmp(tile.pixel(x, y), one.image.pixel(x + 20, y + 24), tile.channelCount() * sizeof(float)))
                << x << "," << y;
}

// Per channel, the mean radiance of n samples of `integrator` along `ray`, sample i drawing from the
// stream (seed, 0, i), prepared for the scene without a splat film (so bdpt leaves light tracing out).
inline std::array<test::MeanEstimate, 3> radianceAlong(const Integrator& integrator, const render::RenderScene& scene,
                                                       const render::Ray& ray, int n, std::uint64_t seed) {
    const render::Camera camera(render::CameraDesc{}, 8, 8);  // for the first-hit AOVs only
    const std::unique_ptr<RenderState> state = integrator.prepare(scene, camera, seed, nullptr);
    RenderCounters counters;
    std::array<test::MeanEstimate, 3> e;
    for (int i = 0; i < n; ++i) {
        SampleStream rng(seed, 0, std::uint64_t(i));
        const RGB L = integrator.sample(*state, scene, camera, ray, rng, counters).radiance;
        for (int c = 0; c < 3; ++c) e[c].add(L[c]);
    }
    return e;
}

// The radiance of a sky of radiance 1 seen head-on through a smooth glass slab whose faces reflect
// F at normal incidence and whose interior transmits a = exp(-sigmaA L) across: the ray's chains
// between the two faces sum to
//     R + T = F + (1 - F)^2 F a^2 / (1 - F^2 a^2) + (1 - F)^2 a / (1 - F^2 a^2).
inline double glassSlabSeenHeadOn(double F, double a) {
    const double loop = 1.0 - F * F * a * a;
    return F + (1 - F) * (1 - F) * F * a * a / loop + (1 - F) * (1 - F) * a / loop;
}

// Mean of channel `c` over the pixels where `select` holds, with its standard error (pixels are
// independent estimates).
inline test::MeanEstimate channelMean(const Image& image, int c, const std::function<bool(const float*)>& select) {
    test::MeanEstimate e;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (const float* p = image.pixel(x, y); select(p)) e.add(p[c]);
    return e;
}

}  // namespace fluence::integrators::test_support
