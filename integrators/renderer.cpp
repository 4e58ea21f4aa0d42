#include "integrators/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "integrators/adaptive_sampling.h"
#include "integrators/sample_cost.h"

namespace fluence::integrators {

namespace {

// Tiles of adaptive sampling are smaller: late passes have few pixels left, and small tiles spread
// them over the threads.
constexpr int kTileSize = 32, kAdaptiveTileSize = 8;
constexpr int kMaxPassSamples = 64;

struct PassRange {
    int first, count;
};

bool stopped(const RenderSettings& settings) { return settings.stop && settings.stop->load(std::memory_order_relaxed); }

// Whether a sample's radiance, and the light path layers the film keeps, are all finite.
bool finite(const FilmSample& sample, std::size_t layers) {
    bool all = isFinite(sample.radiance);
    for (std::size_t l = 0; l < layers; ++l) all = all && isFinite(sample.lightPath(l));
    return all;
}

void renderPass(const render::RenderScene& scene, const render::Camera& camera, const Integrator& integrator,
                const RenderState& state, const RenderSettings& settings, Film& film, PassRange pass,
                const std::vector<std::uint32_t>& plan, tbb::combinable<RenderCounters>& counters,
                RenderProgress* progress) {
    const int width = film.width(), height = film.height();
    const int size = AdaptiveSampling::enabled(settings) ? kAdaptiveTileSize : kTileSize;
    const int tilesX = (width + size - 1) / size, tilesY = (height + size - 1) / size;
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tilesX * tilesY, 1),
        [&](const tbb::blocked_range<int>& tiles) {
            RenderCounters& local = counters.local();
            for (int tile = tiles.begin(); tile != tiles.end(); ++tile) {
                if (stopped(settings)) return;
                int x0 = (tile % tilesX) * size, y0 = (tile / tilesX) * size;
                int x1 = std::min(x0 + size, width), y1 = std::min(y0 + size, height);
                std::uint64_t taken = 0;
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) {
                        const int imageX = x + settings.windowX, imageY = y + settings.windowY;
                        const std::uint64_t pixelIndex =
                            std::uint64_t(imageY) *
                                std::uint64_t(settings.imageWidth > 0 ? settings.imageWidth : width) +
                            std::uint64_t(imageX);
                        const int last = pass.first + int(plan[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
                        PixelSlotScrambles scrambles(settings.seed, pixelIndex);  // the pixel's samples share them
                        for (int s = pass.first; s < last; ++s) {
                            ++taken;
                            SampleStream rng(scrambles, std::uint64_t(s), settings.sampler);
                            const render::Ray ray = cameraSampleRay(scene, camera, rng, imageX, imageY);
                            const RenderCounters before = local;
                            FilmSample sample = integrator.sample(state, scene, camera, ray, rng, local);
                            if (!finite(sample, film.lightPathLayers().size())) {
                                sample.radiance = RGB(0.0f);
                                sample.clearLightPaths(film.lightPathLayers().size());
                                ++local.nonFiniteSamples;
                            }
                            film.add(x, y, sample, sampleCost(before, local, sample.hit));
                            if (settings.cryptomatte) settings.cryptomatte->add(x, y, sample);
                        }
                    }
                if (progress) progress->pixelSamplesDone.fetch_add(taken, std::memory_order_relaxed);
            }
        },
        tbb::simple_partitioner());
}

}  // namespace

RenderStats render(const render::RenderScene& scene, const render::Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film, RenderProgress* progress) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();  // the process's CPU time, every thread
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    if (progress) progress->pixelSamplesDone = film.totalSamples();  // resumed: those already in the film

    int concurrency = settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
    tbb::task_arena arena(concurrency);
    tbb::combinable<RenderCounters> counters;
    RenderStats stats;

    // Light tracing (integrators/integrator.h): splats only into a film that is the whole image.
    const bool wholeImage = film.width() == camera.imageWidth() && film.height() == camera.imageHeight();
    SplatFilm* splats = integrator.usesSplats() && wholeImage ? &film.enableSplats() : nullptr;
    std::unique_ptr<RenderState> state;  // the integrator's per-render state (integrators/integrator.h)
    arena.execute(
        [&] { state = integrator.prepare(scene, camera, settings.seed, splats); });  // within the thread limit
    const bool adaptive = AdaptiveSampling::enabled(settings);
    if (adaptive && !film.hasDenoiseBuffers()) {  // its error estimate reads the half buffers
        if (film.totalSamples() > 0)
            throw std::logic_error("render: adaptive sampling resumed on a film without the half buffers");
        film.enableDenoiseBuffers();
    }
    // Each pass doubles the samples of the pixels still going (1, 2, 4, ...; at most
    // kMaxPassSamples), so a resumed render's passes go on as the uninterrupted render's would have.
    // Adaptive sampling ends a pass at minSamples, where its rules start.
    int done = settings.firstSample;
    double secondsPerSample = 0.0;  // per sample per pixel over the whole image, measured
    while (done < settings.samplesPerPixel && !stopped(settings)) {
        int count = std::min(std::clamp(done + 1, 1, kMaxPassSamples), settings.samplesPerPixel - done);
        if (adaptive && done < settings.minSamples) count = std::min(count, settings.minSamples - done);
        if (settings.timeLimitSeconds > 0.0 && stats.passes > 0) {
            double left = settings.timeLimitSeconds - elapsed();
            int fits = secondsPerSample > 0.0 ? static_cast<int>(left / secondsPerSample) : count;
            count = std::min(count, fits);
            if (count <= 0) break;
        }
        double passStart = elapsed();
        const AdaptiveSampling::PassPlan plan = AdaptiveSampling::planPass(film, settings, done, count);
        if (progress) progress->pixelSamplesPlanned = plan.expectedTotal;
        if (std::all_of(plan.samples.begin(), plan.samples.end(), [](std::uint32_t n) { return n == 0; })) break;
        arena.execute([&] {
            integrator.beginSamples(*state, scene, camera, settings.seed, done, count);
            renderPass(scene, camera, integrator, *state, settings, film, {done, count}, plan.samples, counters,
                       progress);
        });
        secondsPerSample = (elapsed() - passStart) / count;
        done += count;
        ++stats.passes;
        if (settings.onPass && !stopped(settings)) settings.onPass(done);
    }
    stats.interrupted = stopped(settings);
    stats.samples = film.totalSamples();
    if (progress) progress->pixelSamplesPlanned = stats.samples;

    stats.seconds = elapsed();
    stats.cpuSeconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    stats.samplesPerPixel = 0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            stats.samplesPerPixel = std::max<int>(stats.samplesPerPixel, film.samples(x, y));
    counters.combine_each([&](const RenderCounters& c) { stats.counters += c; });
    stats.methodSummary = state->summary();
    return stats;
}

}  // namespace fluence::integrators
