#include "denoise/denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace fluence::denoise {

namespace {

constexpr int kFeatures = 8;         // the constant, albedo R G B, normal X Y Z, relative depth
constexpr int kMaxOutputs = 3 * 17;  // the beauty and up to 16 layers, R G B each
constexpr float kEpsilon = 1e-10f;   // keeps the NL-means distance finite where the variance is 0
constexpr float kNegligibleWeight = 1e-4f;

// The 3x3 box filter of an interleaved R G B image, times `scale` (at the borders, over the
// pixels inside the image).
std::vector<float> boxFilter(const std::vector<float>& image, int width, int height, float scale) {
    std::vector<float> out(image.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float sum[3] = {0, 0, 0};
            int count = 0;
            for (int yy = std::max(0, y - 1); yy <= std::min(height - 1, y + 1); ++yy)
                for (int xx = std::max(0, x - 1); xx <= std::min(width - 1, x + 1); ++xx, ++count)
                    for (int c = 0; c < 3; ++c) sum[c] += image[(std::size_t(yy) * width + xx) * 3 + c];
            for (int c = 0; c < 3; ++c) out[(std::size_t(y) * width + x) * 3 + c] = sum[c] * scale / float(count);
        }
    return out;
}

// The colour the weights compare, and its variance.
struct Guide {
    std::vector<float> colour, variance;
};

void checkSize(const std::vector<float>& v, std::size_t expected, const char* what) {
    if (v.size() != expected)
        throw DenoiseError(std::string("denoise: the ") + what + " buffer holds " + std::to_string(v.size()) +
                           " values, not " + std::to_string(expected));
}

void checkInput(const DenoiseBuffers& in, const DenoiseSettings& settings) {
    if (in.width <= 0 || in.height <= 0) throw DenoiseError("denoise: empty image");
    const std::size_t pixels = std::size_t(in.width) * std::size_t(in.height);
    checkSize(in.halves[0], 3 * pixels, "half0");
    checkSize(in.halves[1], 3 * pixels, "half1");
    checkSize(in.variance, 3 * pixels, "variance");
    checkSize(in.albedo, 3 * pixels, "albedo");
    checkSize(in.normal, 3 * pixels, "normal");
    checkSize(in.depth, pixels, "depth");
    for (const std::vector<float>& layer : in.layers) checkSize(layer, 3 * pixels, "layer");
    if (3 * (in.layers.size() + 1) > std::size_t(kMaxOutputs))
        throw DenoiseError("denoise: at most " + std::to_string(kMaxOutputs / 3 - 1) + " layers");
    if (settings.radius < 0 || settings.stride < 1 || !(settings.k > 0.0f) || !(settings.ridge >= 0.0f))
        throw DenoiseError("denoise: settings out of range");
}

// The fit's features of pixel j, centred on pixel i's.
[[gnu::always_inline]] inline void features(const DenoiseBuffers& in, std::size_t i, std::size_t j,
                                            float x[kFeatures]) {
    x[0] = 1.0f;
    for (int c = 0; c < 3; ++c) {
        x[1 + c] = in.albedo[3 * j + c] - in.albedo[3 * i + c];
        x[4 + c] = in.normal[3 * j + c] - in.normal[3 * i + c];
    }
    const float depth = std::max(in.depth[i], 1e-6f);
    x[7] = std::clamp((in.depth[j] - depth) / depth, -1.0f, 1.0f);
}

// The NL-means weight of pixel j for pixel i (see denoiser.h).
[[gnu::always_inline]] inline float colourWeight(const Guide& guide, std::size_t i, std::size_t j, float k2) {
    float distance = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float ui = guide.colour[3 * i + c], uj = guide.colour[3 * j + c];
        const float vi = guide.variance[3 * i + c], vj = guide.variance[3 * j + c];
        const float shared = vi + std::min(vi, vj);
        distance += ((ui - uj) * (ui - uj) - shared) / (kEpsilon + k2 * shared);
    }
    return std::exp(-std::max(0.0f, distance / 3.0f));
}

// Solves a x = b for `outputs` right-hand sides (a symmetric positive definite, by Cholesky) and
// writes each solution's constant term. False when a is not positive definite.
template <int Columns>
bool constantTerms(const float a[kFeatures][kFeatures], const float b[kFeatures][Columns], int outputs, float* out) {
    double l[kFeatures][kFeatures] = {};
    for (int r = 0; r < kFeatures; ++r) {
        for (int c = 0; c <= r; ++c) {
            double s = a[c][r];
            for (int p = 0; p < c; ++p) s -= l[r][p] * l[c][p];
            if (r == c) {
                if (!(s > 0.0)) return false;
                l[r][r] = std::sqrt(s);
            } else {
                l[r][c] = s / l[c][c];
            }
        }
    }
    for (int o = 0; o < outputs; ++o) {
        double y[kFeatures], x[kFeatures];
        for (int r = 0; r < kFeatures; ++r) {
            double s = b[r][o];
            for (int p = 0; p < r; ++p) s -= l[r][p] * y[p];
            y[r] = s / l[r][r];
        }
        for (int r = kFeatures - 1; r >= 0; --r) {
            double s = y[r];
            for (int p = r + 1; p < kFeatures; ++p) s -= l[p][r] * x[p];
            x[r] = s / l[r][r];
        }
        out[o] = static_cast<float>(x[0]);
    }
    return true;
}

// Pixel (x, y) of half `half` and of every layer, fitted with the weights of `guide`: the
// constant terms, added to `sums` (R G B of the half, then of each layer). `Outputs` is their
// count when known at compile time (the beauty alone), else 0.
template <int Outputs>
void fitPixel(const DenoiseBuffers& in, const DenoiseSettings& settings, const Guide& guide, int half, int x, int y,
              float* sums) {
    const int outputs = Outputs > 0 ? Outputs : 3 * int(in.layers.size() + 1);
    const std::size_t i = std::size_t(y) * in.width + x;
    const float k2 = settings.k * settings.k;
    constexpr int kColumns = Outputs > 0 ? Outputs : kMaxOutputs;
    float a[kFeatures][kFeatures] = {}, b[kFeatures][kColumns] = {};
    float weightSum = 0.0f;
    const int r = settings.radius / settings.stride * settings.stride;
    for (int yy = std::max(y - r, y % settings.stride); yy <= std::min(y + r, in.height - 1); yy += settings.stride)
        for (int xx = std::max(x - r, x % settings.stride); xx <= std::min(x + r, in.width - 1);
             xx += settings.stride) {
            const std::size_t j = std::size_t(yy) * in.width + xx;
            const float w = colourWeight(guide, i, j, k2);
            if (w < kNegligibleWeight) continue;
            float f[kFeatures], values[kColumns];
            features(in, i, j, f);
            for (int c = 0; c < 3; ++c) values[c] = in.halves[half][3 * j + c];
            for (int l = 0; 3 + 3 * l < outputs; ++l)
                for (int c = 0; c < 3; ++c) values[3 + 3 * l + c] = in.layers[std::size_t(l)][3 * j + c];
            weightSum += w;
            for (int p = 0; p < kFeatures; ++p) {
                const float wp = w * f[p];
                for (int q = p; q < kFeatures; ++q) a[p][q] += wp * f[q];
                for (int o = 0; o < outputs; ++o) b[p][o] += wp * values[o];
            }
        }
    for (int p = 1; p < kFeatures; ++p) a[p][p] += settings.ridge * weightSum;
    float fitted[kColumns];
    if (!constantTerms<kColumns>(a, b, outputs, fitted))  // not met with the ridge; the weighted mean then
        for (int o = 0; o < outputs; ++o) fitted[o] = b[0][o] / a[0][0];
    for (int o = 0; o < outputs; ++o) sums[o] += std::isfinite(fitted[o]) ? std::max(0.0f, fitted[o]) : 0.0f;
}

}  // namespace

Denoised denoise(const DenoiseBuffers& in, const DenoiseSettings& settings) {
    checkInput(in, settings);
    // The guides: a half's mean has twice the variance of the beauty's, and the box filter divides
    // the variance of independent pixels by 9.
    Guide guides[2];
    const std::vector<float> variance = boxFilter(in.variance, in.width, in.height, 2.0f / 9.0f);
    for (int h = 0; h < 2; ++h) guides[h] = {boxFilter(in.halves[h], in.width, in.height, 1.0f), variance};

    const std::size_t pixels = std::size_t(in.width) * std::size_t(in.height);
    const int outputs = 3 * int(in.layers.size() + 1);
    std::vector<float> sums(pixels * std::size_t(outputs), 0.0f);
    const auto fit = in.layers.empty() ? fitPixel<3> : fitPixel<0>;
    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, in.height), [&](const tbb::blocked_range<int>& rows) {
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = 0; x < in.width; ++x) {
                    float* pixelSums = sums.data() + (std::size_t(y) * in.width + x) * std::size_t(outputs);
                    fit(in, settings, guides[1], 0, x, y, pixelSums);  // half 0 with half 1's weights
                    fit(in, settings, guides[0], 1, x, y, pixelSums);  // and the other way round
                }
        });
    });

    Denoised out;
    out.beauty.resize(3 * pixels);
    out.layers.assign(in.layers.size(), std::vector<float>(3 * pixels));
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c) {
            out.beauty[3 * p + c] = 0.5f * sums[p * outputs + c];
            for (std::size_t l = 0; l < in.layers.size(); ++l)
                out.layers[l][3 * p + c] = 0.5f * sums[p * outputs + 3 + 3 * l + c];
        }
    return out;
}

}  // namespace fluence::denoise
