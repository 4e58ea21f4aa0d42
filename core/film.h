// The film: per-pixel sums of every output the integrators produce.
//
// Each pixel is owned by exactly one task at a time and accumulates its samples in index order,
// so the sums (and the resolved image) do not depend on the thread count. Sums are kept in double
// so thousands of samples add without visible rounding drift.
//
// Resolved channels (Nuke-style layer names, colour channels in the rendering space):
//   R G B        beauty radiance, box-filtered over the pixel (the mean of its samples, plus the
//                splats of light tracing when there are any: enableSplats() below)
//   A            coverage: the fraction of camera samples that hit geometry or a light
//   albedo.R/G/B diffuse reflectance at the first surface hit (data for denoisers)
//   N.X/Y/Z      world-space shading normal at the first hit, averaged (not renormalised)
//   Z            camera-space depth of the nearest first hit in the pixel (a "min" filter, as
//                compositors expect); pixels that hit nothing read the camera's far clip
//   sampleCount  number of samples taken in the pixel
// Not resolved: each pixel's cost, the sum of its samples' costs as the render loop counts them
// (integrators/sample_cost.h: rays, medium lookups and guided walk steps, deterministic), which adaptive sampling's
// budget rule weighs the pixels by (integrators/adaptive_sampling.h).
//   NAME.R/G/B   one layer per light path expression AOV (integrators/light_path_tracker.h), in the
//                order given to the constructor: the part of the beauty whose paths it matches
//
// The denoiser's buffers (denoise/), kept once enableDenoiseBuffers() is called and resolved apart
// by resolveDenoiseBuffers():
//   half0.R/G/B     the mean of the first half of the pixel's samples, half1.R/G/B of the second:
//                   two estimates of the beauty whose difference measures the error the Sobol
//                   sampler actually makes (below)
//   variance.R/G/B  the variance of the beauty's mean, from the halves: (half0 - half1)² n0 n1 / n²
//                   for halves of n0 and n1 of the n samples (unbiased when the samples are
//                   independent: E (half0 - half1)² = sigma² (1/n0 + 1/n1)); one degree of freedom
//                   per pixel, which the denoiser and adaptive sampling average over neighbours
//   albedoVariance.R/G/B, NVariance.X/Y/Z
//                   the variance of the albedo's and the normal's means, from the samples' squares
//                   (a sample that hits nothing counts as 0, as in albedo and N): large where the
//                   first hits differ from sample to sample (depth of field, motion blur, hair)
// The halves are split by sample index (a sample's index is the count of samples before it in its
// pixel), so the split is the same at any thread count, tile division or checkpoint. Under the
// Owen-scrambled Sobol sampler (core/owen_sobol.h) every aligned block of 2^m indices is a
// (0,m,2)-net, so for n = 2^m the halves are samples [0, 2^(m-1)) and [2^(m-1), 2^m): each a net,
// and their difference measures the error of nets. Splitting a net by even and odd index (as
// before) makes two random halves of one net whose errors cancel in the whole: their difference
// measured the error of independent samples, up to thousands of times the net's on a smooth
// integrand (tests/core/film_half_buffers_test.cpp). For n = 2^M + k (1 <= k <= 2^M), the first
// half is [0, 2^M) when k >= 2^(M-1) and [0, 2^(M-1)) otherwise, so the halves' counts are
// within a factor of 2 of each other at any n (a one-sample pixel: both halves read its sample).
// The film keeps the sums of the samples [0, 2^M) and [0, 2^(M-1)) for that, updated when the
// index reaches a power of two.
// Light tracing's splats (enableSplats) are added to both halves alike and not to the variance.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iosfwd>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "core/image.h"
#include "core/name_table.h"
#include "core/rgb.h"
#include "core/splat_film.h"

namespace fluence {

// The most light path expression AOVs one render can write.
inline constexpr int kMaxLightPathLayers = 16;

// What one camera sample contributes.
struct FilmSample {
    RGB radiance;
    bool hit = false;  // the camera ray hit something
    RGB albedo;
    Vec3f normal;
    float depth = 0.0f;  // camera-space depth of the first hit (valid when hit)
    // The first hit's names for the Cryptomatte layers (core/cryptomatte_film.h): indices into the
    // render scene's object and material name tables, kNoName where there is none.
    std::uint32_t objectName = kNoName, materialName = kNoName;
    // The radiance of the paths each light path expression matches, R G B per layer: only the first
    // Film::lightPathLayers() are read, and an integrator that writes them clears those first.
    // Deliberately left uninitialised: most renders have no layers, and zeroing 192 bytes per
    // sample cost the path tracer 2% on the Cornell box (bench/results/2026-11-27-throughput.md).
    float lightPaths[3 * kMaxLightPathLayers];

    void clearLightPaths(std::size_t layers) { std::fill_n(lightPaths, 3 * layers, 0.0f); }
    // A copy with only the first `layers` light path layers (the others left uninitialised, as
    // they are unread): a path tracer's sample copies 48 bytes, not 240, when there are none.
    FilmSample withLightPaths(std::size_t layers) const;
    RGB lightPath(std::size_t layer) const {
        return RGB(lightPaths[3 * layer], lightPaths[3 * layer + 1], lightPaths[3 * layer + 2]);
    }
    void addLightPath(std::size_t layer, const RGB& v) {
        for (int c = 0; c < 3; ++c) lightPaths[3 * layer + std::size_t(c)] += v[c];
    }
};

static_assert(std::is_standard_layout_v<FilmSample> &&
              offsetof(FilmSample, lightPaths) + sizeof(FilmSample::lightPaths) == sizeof(FilmSample));
inline FilmSample FilmSample::withLightPaths(std::size_t layers) const {
    FilmSample s;
    std::memcpy(static_cast<void*>(&s), this, offsetof(FilmSample, lightPaths));
    std::copy_n(lightPaths, 3 * layers, s.lightPaths);
    return s;
}

class Film {
public:
    // `lightPathLayers`: the names of the light path expression AOVs (at most kMaxLightPathLayers).
    Film(int width, int height, float farDepth, std::vector<std::string> lightPathLayers = {});

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds a sample of pixel (x, y) that cost `cost` (integrators/sample_cost.h; 0: not counted).
    void add(int x, int y, const FilmSample& s, double cost = 0.0);

    // The channel names resolve() produces, in order.
    std::vector<std::string> channelNames() const;
    const std::vector<std::string>& lightPathLayers() const { return lightPathLayers_; }
    // Channels that are data rather than colour (for EXR headers).
    static std::vector<std::string> dataChannelNames();
    Image resolve() const;

    // Statistics over the whole film (for summaries and tests).
    std::uint64_t totalSamples() const;

    // Light tracing: the splat film (core/splat_film.h) into which integrators that add light to
    // other pixels than their sample's write (bdpt's t = 1), made by enableSplats() (the render
    // loop's, for an integrator that asks for it and a film that is the whole image); null until
    // then; it has one layer per light path layer. resolve() adds its sums to the beauty (and its
    // layers' to the light path layers) divided by the light paths traced per pixel,
    // totalSamples() / (width height): one per camera sample, wherever it was taken.
    SplatFilm& enableSplats();
    const SplatFilm* splats() const { return splats_.get(); }

    // The denoiser's buffers (see the top of this file): from the next sample on; call before any.
    void enableDenoiseBuffers();
    bool hasDenoiseBuffers() const { return !denoiseSums_.empty(); }
    static std::vector<std::string> denoiseBufferChannelNames();
    // The half images and variance, in denoiseBufferChannelNames() order. Requires the buffers.
    Image resolveDenoiseBuffers() const;
    // The means of pixel (x, y)'s first and second halves of samples (see the top of this file),
    // R G B, without light tracing's splats, and how many samples each holds (a one-sample pixel:
    // both read its sample, counts 1 and 0; no sample: 0). Requires the buffers. Adaptive
    // sampling's error estimate (integrators/adaptive_sampling.h).
    struct HalfMeans {
        std::array<double, 3> first, second;
        std::uint32_t firstCount = 0, secondCount = 0;
        // The halves' estimate of the variance of the pixel's mean in channel c (0 below 2 samples).
        double meanVariance(std::size_t c) const;
    };
    HalfMeans halfMeans(int x, int y) const;

    // The samples taken in pixel (x, y) so far.
    std::uint32_t samples(int x, int y) const { return pixel(x, y).samples; }
    // The sum of the costs of pixel (x, y)'s samples so far (see the top of this file).
    double cost(int x, int y) const { return pixel(x, y).cost; }
    // The relative standard error of the pixel's mean luminance: sqrt(variance / n) / (mean +
    // kRelativeErrorFloor), from its samples' luminance sums (infinite below two samples). The floor
    // keeps dark pixels, whose relative error means little, from sampling forever; it is in the
    // units of radiance (a black pixel converges once its absolute error is below target x 0.01).
    static constexpr double kRelativeErrorFloor = 0.01;
    double relativeError(int x, int y) const;

private:
    // Checkpoints save and restore everything below (core/film_state.h): a new field must be added
    // there too (a static_assert there says so).
    friend void writeFilmState(const Film& film, std::ostream& out);
    friend void readFilmState(std::istream& in, Film& film);

    struct Pixel {
        double radiance[3] = {0, 0, 0};
        double luminance = 0, luminanceSquared = 0;  // sums over the samples (adaptive sampling)
        double albedo[3] = {0, 0, 0};
        double normal[3] = {0, 0, 0};
        double coverage = 0;
        double cost = 0;  // the samples' costs, summed
        float minDepth = 0;
        bool anyHit = false;
        std::uint32_t samples = 0;
    };
    const Pixel& pixel(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }

    int width_, height_;
    float farDepth_;
    std::vector<Pixel> pixels_;
    std::vector<std::string> lightPathLayers_;
    std::vector<double> lightPathSums_;  // per pixel, per layer, R G B
    // With the denoiser's buffers, per pixel: the radiance sums R G B of the samples [0, 2^(M-1)),
    // then of [0, 2^M), 2^M the largest power of two below the pixel's count (see the top of this
    // file), then the squared albedo R G B and normal X Y Z sums; empty without them.
    std::vector<double> denoiseSums_;
    std::unique_ptr<SplatFilm> splats_;
};

}  // namespace fluence
