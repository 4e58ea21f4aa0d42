// What a surface-only scene would pay for the machinery of volumes and subsurface scattering if the
// path tracer did not leave it out (issue #10, "model no more than a scene needs").
//
// PathTracer::sample() runs trace<false>, compiled without free flights, ratio-tracked shadow
// rays, the medium stack, spectral MIS and diffusion probes, on a scene without media, and
// trace<true> on one with media. This bench renders the surface-only samples (the Cornell box, the
// material ball) with both, interleaved over several rounds so the shared machine's load falls on
// both alike, checks that the images are bit-identical, and prints the samples/s of each and their
// ratio (median over the rounds). Results: bench/results/2026-11-27-media-overhead.md.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/film.h"
#include "delegate/scene_delegate.h"
#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "render/render_scene.h"
#include "scene/stage.h"

namespace {

using namespace fluence;

// The path tracer with or without the media machinery, whatever the scene.
template <bool kMedia>
class TracerVariant final : public integrators::Integrator {
public:
    FilmSample sample(const integrators::RenderState&, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, integrators::RenderCounters& counters) const override {
        // Surface-only scenes: no medium for the equiangular strategy to sample.
        return tracer_.trace<kMedia>(integrators::LightEvents(), integrators::EquiangularLights(), scene, camera, ray,
                                     rng, counters);
    }

private:
    integrators::PathTracer tracer_{integrators::IntegratorSettings{}};
};

render::SceneDescription load(const std::string& file, std::pair<int, int> resolution) {
    auto stage = usd::Stage::open(file);
    delegate::DelegateOptions o;
    o.resolution = resolution;
    o.convertColor = [](const RGB& c, const std::string&) { return c; };
    o.warn = [](const std::string&, const std::string&) {};
    delegate::SceneDelegate delegate(*stage, o);
    delegate.sync();
    return delegate.sceneDescription();
}

struct Timed {
    double samplesPerSecond;
    Image image;
};

Timed renderWith(const integrators::Integrator& integrator, const render::RenderScene& scene,
                 const render::Camera& camera, std::pair<int, int> res, int spp) {
    integrators::RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.seed = 3;
    Film film(res.first, res.second, camera.farClip());
    const integrators::RenderStats stats = integrators::render(scene, camera, integrator, settings, film);
    return {double(stats.samples) / stats.seconds, film.resolve()};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main() {
    constexpr int kRounds = 7;
    const std::pair<int, int> res{320, 240};
    std::printf("%-28s %6s %16s %16s %8s %10s\n", "scene", "spp", "without Msmp/s", "with Msmp/s", "ratio",
                "identical");
    for (const auto& [file, spp] : std::vector<std::pair<std::string, int>>{
             {"usd_samples/cornell_box.usda", 16}, {"usd_samples/material_ball/material_ball.usda", 8}}) {
        const render::SceneDescription desc = load(std::string(FLUENCE_SOURCE_DIR) + "/" + file, res);
        const render::RenderScene scene(desc);
        const render::Camera camera(*desc.camera, res.first, res.second);
        if (scene.hasMedia()) std::printf("%s has media: not a surface-only scene\n", file.c_str());
        const TracerVariant<false> without;
        const TracerVariant<true> with;
        std::vector<double> a, b, ratio;
        bool identical = true;
        for (int round = 0; round < kRounds; ++round) {
            const Timed x = renderWith(without, scene, camera, res, spp), y = renderWith(with, scene, camera, res, spp);
            a.push_back(x.samplesPerSecond * 1e-6);
            b.push_back(y.samplesPerSecond * 1e-6);
            ratio.push_back(x.samplesPerSecond / y.samplesPerSecond);
            identical =
                identical && x.image.pixels.size() == y.image.pixels.size() &&
                std::memcmp(x.image.pixels.data(), y.image.pixels.data(), x.image.pixels.size() * sizeof(float)) == 0;
        }
        std::printf("%-28s %6d %16.3f %16.3f %8.3f %10s\n", file.substr(file.find_last_of('/') + 1).c_str(), spp,
                    median(a), median(b), median(ratio), identical ? "yes" : "NO");
    }
    std::printf("\nratio = samples/s without the media machinery / with it (median of %d interleaved rounds)\n",
                kRounds);
}
