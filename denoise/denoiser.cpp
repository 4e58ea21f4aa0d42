#include "denoise/denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "denoise/denoise_planes.h"
#include "denoise/feature_prefilter.h"
#include "denoise/local_fit.h"

namespace fluence::denoise {

namespace {

constexpr int kBandCentreRows = 16;  // centre rows whose pixels one task reconstructs

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
    if (!in.albedoVariance.empty() || !in.normalVariance.empty()) {
        checkSize(in.albedoVariance, 3 * pixels, "albedo variance");
        checkSize(in.normalVariance, 3 * pixels, "normal variance");
    }
    for (const std::vector<float>& layer : in.layers) checkSize(layer, 3 * pixels, "layer");
    if (3 * (in.layers.size() + 1) > std::size_t(kMaxOutputs))
        throw DenoiseError("denoise: at most " + std::to_string(kMaxOutputs / 3 - 1) + " layers");
    if (settings.radius < 0 || settings.radius > kMaxRadius || settings.fitStride < 1 || !(settings.k > 0.0f) ||
        !(settings.ridge >= 0.0f) || !(settings.fireflyRatio > 0.0f) || !(settings.minSupport >= 0.0f) ||
        !(settings.keepThreshold >= 0.0f) || settings.featureRadius < 0 || settings.featureRadius > kMaxRadius ||
        !(settings.featureK > 0.0f))
        throw DenoiseError("denoise: settings out of range");
}

// The centres' fits for the pixel rows [rowBegin, rowEnd): the centre rows within fitStride of
// them, every centre column; coefficients per centre, per half, outputs x kFeatures.
class BandFits {
public:
    BandFits(const DenoisePlanes& planes, const DenoiseSettings& settings, int rowBegin, int rowEnd)
        : stride_(settings.fitStride),
          columns_((planes.width - 1) / stride_ + 1),
          perHalf_(std::size_t(planes.outputs()) * kFeatures) {
        const int lastRow = (planes.height - 1) / stride_;
        first_ = std::max(0, (rowBegin - stride_ + stride_ - 1) / stride_);
        const int last = std::min(lastRow, (rowEnd - 1 + stride_) / stride_);
        coefficients_.resize(std::size_t(last - first_ + 1) * std::size_t(columns_) * 2 * perHalf_);
        for (int row = first_; row <= last; ++row)
            for (int column = 0; column < columns_; ++column) {
                float* halves[2] = {coefficients_.data() + offset(column, row, 0),
                                    coefficients_.data() + offset(column, row, 1)};
                fitCentre(planes, settings, column * stride_, row * stride_, halves);
            }
    }

    // Centre (column, row)'s coefficients for half h.
    const float* at(int column, int row, int h) const { return coefficients_.data() + offset(column, row, h); }

private:
    std::size_t offset(int column, int row, int h) const {
        return ((std::size_t(row - first_) * std::size_t(columns_) + std::size_t(column)) * 2 + std::size_t(h)) *
               perHalf_;
    }

    int stride_, columns_, first_ = 0;
    std::size_t perHalf_;
    std::vector<float> coefficients_;
};

float tent(int distance, int stride) { return 1.0f - float(std::abs(distance)) / float(stride + 1); }

// Pixel (x, y) of both halves, every output, from the centres' models (see denoiser.h): the mean
// of the two halves into `out`.
void reconstruct(const DenoisePlanes& planes, const DenoiseSettings& settings, const BandFits& fits, int x, int y,
                 float* out) {
    const int stride = settings.fitStride, outputs = planes.outputs();
    const std::size_t p = std::size_t(y) * planes.width + x;
    const float k2 = settings.k * settings.k;
    float sums[2][kMaxOutputs] = {}, weightSums[2] = {0.0f, 0.0f}, tentSum = 0.0f;
    const int columns = (planes.width - 1) / stride + 1, rows = (planes.height - 1) / stride + 1;
    for (int row = std::max(0, (y - 1) / stride); row <= std::min(rows - 1, (y + stride) / stride); ++row)
        for (int column = std::max(0, (x - 1) / stride); column <= std::min(columns - 1, (x + stride) / stride);
             ++column) {
            const int cx = column * stride, cy = row * stride;
            if (std::abs(cx - x) > stride || std::abs(cy - y) > stride) continue;
            const std::size_t c = std::size_t(cy) * planes.width + cx;
            const float t =
                tent(cx - x, stride) * tent(cy - y, stride) * fireflyWeight(planes, p, c, settings.fireflyRatio);
            float f[kFeatures];
            centredFeatures(planes, c, p, f);
            tentSum += t;
            for (int h = 0; h < 2; ++h) {
                const float w = t * colourWeight(planes, 1 - h, c, p, k2);
                const float* coefficients = fits.at(column, row, h);
                for (int o = 0; o < outputs; ++o) {
                    float value = 0.0f;
                    for (int q = 0; q < kFeatures; ++q) value += coefficients[o * kFeatures + q] * f[q];
                    sums[h][o] += w * value;
                }
                weightSums[h] += w;
            }
        }
    float own[2][kMaxOutputs * kFeatures];
    const bool alone = weightSums[0] < settings.minSupport * tentSum || weightSums[1] < settings.minSupport * tentSum;
    if (alone) {
        float* halves[2] = {own[0], own[1]};
        fitCentre(planes, settings, x, y, halves);
    }
    for (int o = 0; o < outputs; ++o) {
        float value = 0.0f;
        for (int h = 0; h < 2; ++h) value += 0.5f * (alone ? own[h][o * kFeatures] : sums[h][o] / weightSums[h]);
        out[o] = std::isfinite(value) ? std::max(0.0f, value) : 0.0f;
    }
}

// The selection step (see denoiser.h): pixel p's denoised outputs `out` drawn towards the noisy
// ones where their difference shows a bias.
void keepWhatTheFitLost(const DenoisePlanes& planes, const DenoiseSettings& settings, std::size_t p, float* out) {
    float blend[3];
    for (std::size_t c = 0; c < 3; ++c) {
        const float variance = std::max(planes.variance[c][p], planes.smoothVariance[c][p]);
        const float d = out[c] - planes.noisy[c][p];
        const float bias = std::max(0.0f, d * d - settings.keepThreshold * variance);
        blend[c] = bias > 0.0f ? bias / (bias + variance) : 0.0f;
    }
    for (int o = 0; o < planes.outputs(); ++o) out[o] += blend[o % 3] * (planes.noisy[std::size_t(o)][p] - out[o]);
}

}  // namespace

Denoised denoise(const DenoiseBuffers& in, const DenoiseSettings& settings) {
    checkInput(in, settings);
    DenoisePlanes planes = makePlanes(in, settings.radius);
    const std::size_t pixels = std::size_t(in.width) * std::size_t(in.height);
    const int outputs = planes.outputs(), bandRows = kBandCentreRows * settings.fitStride;
    std::vector<float> result(pixels * std::size_t(outputs));
    tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        prefilterFeatures(in, settings, planes);
        const int bands = (in.height + bandRows - 1) / bandRows;
        tbb::parallel_for(tbb::blocked_range<int>(0, bands, 1), [&](const tbb::blocked_range<int>& range) {
            for (int band = range.begin(); band < range.end(); ++band) {
                const int rowBegin = band * bandRows, rowEnd = std::min(in.height, rowBegin + bandRows);
                const BandFits fits(planes, settings, rowBegin, rowEnd);
                for (int y = rowBegin; y < rowEnd; ++y)
                    for (int x = 0; x < in.width; ++x) {
                        const std::size_t p = std::size_t(y) * in.width + x;
                        float* out = result.data() + p * std::size_t(outputs);
                        reconstruct(planes, settings, fits, x, y, out);
                        keepWhatTheFitLost(planes, settings, p, out);
                    }
            }
        });
    });

    Denoised out;
    out.beauty.resize(3 * pixels);
    out.layers.assign(in.layers.size(), std::vector<float>(3 * pixels));
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 3; ++c) {
            out.beauty[3 * p + std::size_t(c)] = result[p * std::size_t(outputs) + std::size_t(c)];
            for (std::size_t l = 0; l < in.layers.size(); ++l)
                out.layers[l][3 * p + std::size_t(c)] = result[p * std::size_t(outputs) + 3 + 3 * l + std::size_t(c)];
        }
    return out;
}

}  // namespace fluence::denoise
