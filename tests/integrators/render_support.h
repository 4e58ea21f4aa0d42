// Shared by the integrator tests: render a SceneDescription with an integrator into an Image, and
// average a channel over selected pixels with its standard error.
#pragma once

#include <cstdint>
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

// A size x size render of `desc` through its camera, `spp` samples per pixel.
inline Rendered renderWith(const Integrator& integrator, const render::SceneDescription& desc, int size, int spp,
                           int threads = 0, std::uint64_t seed = 0) {
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.threads = threads;
    settings.seed = seed;
    RenderedFilm r = renderFilm(integrator, desc, size, settings);
    return {r.film.resolve(), r.stats};
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
