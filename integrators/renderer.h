// The render loop: drives an integrator over the film, in passes of tiles on oneTBB.
//
// The image is rendered in passes of 1, 2, 4, ... (at most 64) samples per pixel; within a pass
// 32x32 tiles are shaded in parallel. Sample n of pixel (x, y) always draws from the stream
// (seed, y*width+x, n), and each pixel adds its samples in index order, so the image is
// bit-identical for any thread count and any pass division. A time limit is honoured between
// passes (the last pass is shrunk to fit the time left), so every pixel has the same sample
// count. A sample whose radiance (or a light path layer) is not finite is counted and replaced by zero, so one bad
// sample cannot poison a pixel.
//
// Adaptive sampling (RenderSettings::targetError or meanSamplesPerPixel,
// integrators/adaptive_sampling.h): before each pass, from the film's half buffers, each pixel is
// told how many of the pass's samples it takes; one that takes fewer has stopped, for good, and is
// skipped by later passes; the render ends when every pixel has. Every sample's cost (rays and medium
// lookups counted, integrators/sample_cost.h) is added to its pixel in the film, for the budget
// rule. The decisions read the film between
// passes only, so they too are the same for any thread count. Stopping on an estimate of the error
// biases a pixel slightly (the estimate and the mean are correlated), as in every adaptive sampler;
// the neighbourhood filter and minSamples keep it small. Since a pixel's samples depend only on
// (seed, pixel, sample index), a render resumed from a pass boundary's film
// (RenderSettings::firstSample) finishes bit-identical to one never stopped. The integrator's prepare() runs before the first pass and its
// beginSamples() before each (integrators/integrator.h), within the render's thread limit (their
// own parallel loops use its arena); the time they take counts towards the time limit.
//
// Light tracing (bdpt's t = 1): an integrator that asks for splats (Integrator::usesSplats) gets
// the film's splat film when the film is the whole image, and none for a tile (a window), which
// then renders without those strategies: a tile's light paths start in its own pixels only, so
// it would miss the light that other tiles' light paths send into it. (Tiles of such a method
// therefore assemble into the one-piece render without light tracing, not into the default one.)
// Splats add in fixed point (core/splat_film.h), so
// the image stays bit-identical at any thread count and pass division; with adaptive sampling,
// they are divided by the light paths traced per pixel of the whole image (core/film.h).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "core/cryptomatte_film.h"
#include "core/film.h"
#include "integrators/integrator.h"

namespace fluence::integrators {

struct RenderSettings {
    int samplesPerPixel = 64;  // the most any pixel takes
    // Adaptive sampling (integrators/adaptive_sampling.h), one rule or neither (0: samplesPerPixel
    // everywhere). targetError > 0: each pixel stops once it has minSamples and the relative
    // standard error of its mean is at most targetError. meanSamplesPerPixel > 0: the image takes
    // samples that cost (integrators/sample_cost.h) what that many uniform samples per pixel would,
    // each pixel's count chosen to lower the image's relative MSE most for the cost. The film then keeps the half buffers (Film::enableDenoiseBuffers; render()
    // enables them on an empty film, a film to resume needs them before readFilmState).
    double targetError = 0.0;
    double meanSamplesPerPixel = 0.0;
    int minSamples = 16;
    std::uint64_t seed = 0;
    // The camera samples' random numbers (core/random.h): Sobol stratifies each pixel's samples,
    // Independent hashes every value apart.
    SamplerKind sampler = SamplerKind::Sobol;
    int threads = 0;                // 0: every core
    double timeLimitSeconds = 0.0;  // 0: none
    // Set (from another thread or a signal handler) to stop: no tile starts after it is seen, and
    // render() returns with RenderStats::interrupted (the film is then incomplete: pixels hold
    // different sample counts). Null: the render cannot be stopped.
    const std::atomic<bool>* stop = nullptr;
    // The film is the window of the camera's image at (windowX, windowY), the image imageWidth
    // pixels wide (0: the film is the whole image). Sample n of image pixel (x, y) draws from the
    // same stream whatever the window, so tiles rendered apart assemble into the whole render, bit
    // for bit.
    int windowX = 0, windowY = 0, imageWidth = 0;
    // Resuming (apps/render_checkpoint.h): the film already holds samples 0 to firstSample - 1 of
    // every pixel (fewer where adaptive sampling stopped it), and the render goes on from there.
    int firstSample = 0;
    // Called after every pass that completed (never after an interrupted one), between passes,
    // with the samples per pixel done so far: the film then holds samples 0 to samplesDone - 1 of
    // every pixel that adaptive sampling has not stopped (for checkpoints and snapshots).
    std::function<void(int samplesDone)> onPass;
    // Cryptomatte layers (core/cryptomatte_film.h), the film's size: every sample the film takes is
    // added to it too. Null: none (nothing is kept).
    CryptomatteFilm* cryptomatte = nullptr;
};

// Read by a progress reporter on another thread while render() runs.
struct RenderProgress {
    std::atomic<std::uint64_t> pixelSamplesDone{0};
    std::atomic<std::uint64_t> pixelSamplesPlanned{0};
};

struct RenderStats {
    double seconds = 0.0;
    // The process's CPU time (user + system, every thread) over the same span as `seconds`: the
    // render's own cost when it is the process's only work, as in `fluence render`; unlike the
    // wall time, it does not grow when other processes share the cores.
    double cpuSeconds = 0.0;
    int samplesPerPixel = 0;    // the most taken in any pixel (in every pixel without adaptive sampling)
    std::uint64_t samples = 0;  // taken over the whole image
    int passes = 0;
    bool interrupted = false;  // RenderSettings::stop was set before the render finished
    RenderCounters counters;
    std::string methodSummary;  // the integrator's per-render state's summary() ("" for nothing)
};

// The camera ray of one sample of image pixel (x, y): the stream's first two dimensions place it
// in the pixel (a box filter), its own lens values (SampleStream::lens) the point of the aperture,
// and its own shutter dimension (SampleStream::shutterTime) its time, so that depth of field and
// motion blur change no other random number of the sample. A still pinhole camera reads no lens
// values, so none are drawn for it; and where neither the camera nor the scene moves
// (RenderScene::moves), no ray's time changes anything, so none is drawn and the time is 0
// (drawing either changes nothing else).
inline render::Ray cameraSampleRay(const render::RenderScene& scene, const render::Camera& camera, SampleStream& rng,
                                   int imageX, int imageY) {
    const Vec2f jitter = rng.next2D();
    const float time = camera.moves() || scene.moves() ? rng.shutterTime() : 0.0f;
    const Vec2f lens = camera.moves() || !camera.lens().isPinhole() ? rng.lens() : Vec2f(0.5f);
    render::Ray ray = camera.generateRay(float(imageX) + jitter.x, float(imageY) + jitter.y, lens, time);
    ray.time = time;
    return ray;
}

RenderStats render(const render::RenderScene& scene, const render::Camera& camera, const Integrator& integrator,
                   const RenderSettings& settings, Film& film, RenderProgress* progress = nullptr);

}  // namespace fluence::integrators
