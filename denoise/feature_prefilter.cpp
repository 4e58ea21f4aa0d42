#include "denoise/feature_prefilter.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace fluence::denoise {

namespace {

constexpr float kNoiseDominated = 4.0f;  // neighbours' difference below this times v: noise (see the header)
constexpr int kNoiseWindowRadius = 2;    // the 5x5 window that comparison is averaged over

// Per pixel, half the squared difference of the group's means `feature` to its right and lower
// neighbours, averaged over the group and those neighbours (0 for a 1x1 image).
std::vector<float> neighbourDifference(const std::vector<float>* feature, int width, int height) {
    std::vector<float> out(std::size_t(width) * std::size_t(height), 0.0f);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t p = std::size_t(y) * width + x;
            float sum = 0.0f;
            int count = 0;
            auto add = [&](std::size_t q) {
                for (int c = 0; c < 3; ++c) sum += (feature[c][p] - feature[c][q]) * (feature[c][p] - feature[c][q]);
                ++count;
            };
            if (x + 1 < width) add(p + 1);
            if (y + 1 < height) add(p + std::size_t(width));
            out[p] = count > 0 ? sum / float(2 * 3 * count) : 0.0f;
        }
    return out;
}

// The group's noise level v per pixel (see the header), 0 where its features are not noisy.
std::vector<float> noiseLevel(const std::vector<float>& variance, const std::vector<float>* feature, int width,
                              int height) {
    std::vector<float> own(variance.size() / 3);
    for (std::size_t p = 0; p < own.size(); ++p)
        own[p] = (variance[3 * p] + variance[3 * p + 1] + variance[3 * p + 2]) / 3.0f;
    std::vector<float> level = boxMean(own, width, height, 1);
    const std::vector<float> difference =
        boxMean(neighbourDifference(feature, width, height), width, height, kNoiseWindowRadius);
    const std::vector<float> windowVariance = boxMean(own, width, height, kNoiseWindowRadius);
    for (std::size_t p = 0; p < own.size(); ++p)
        level[p] = difference[p] < kNoiseDominated * windowVariance[p] ? std::max(level[p], own[p]) : 0.0f;
    return level;
}

// One feature group's planes `in` filtered into `out` (planes of their size; a pixel of noise
// level 0 keeps its features), for the rows [rowBegin, rowEnd).
struct GroupFilter {
    const std::vector<float>* in;
    const std::vector<float>& level;
    std::vector<float>* out;
    int width, height, radius;
    float k2;

    void operator()(int rowBegin, int rowEnd) const {
        for (int y = rowBegin; y < rowEnd; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * width + x;
                const float vi = level[i];
                if (!(vi > 0.0f)) {
                    for (int c = 0; c < 3; ++c) out[c][i] = in[c][i];
                    continue;
                }
                float sums[3] = {0.0f, 0.0f, 0.0f}, weightSum = 0.0f;
                for (int yy = std::max(0, y - radius); yy <= std::min(height - 1, y + radius); ++yy)
                    for (int xx = std::max(0, x - radius); xx <= std::min(width - 1, x + radius); ++xx) {
                        const std::size_t j = std::size_t(yy) * width + xx;
                        float distance = 0.0f;
                        for (int c = 0; c < 3; ++c) distance += (in[c][i] - in[c][j]) * (in[c][i] - in[c][j]);
                        const float shared = vi + std::min(vi, level[j]);
                        const float w = std::exp(-std::max(0.0f, distance / 3.0f - shared) / (k2 * shared));
                        for (int c = 0; c < 3; ++c) sums[c] += w * in[c][j];
                        weightSum += w;
                    }
                for (int c = 0; c < 3; ++c) out[c][i] = sums[c] / weightSum;  // weightSum >= 1: j = i weighs 1
            }
    }
};

}  // namespace

void prefilterFeatures(const DenoiseBuffers& buffers, const DenoiseSettings& settings, DenoisePlanes& planes) {
    if (buffers.albedoVariance.empty()) return;
    const std::vector<float>* groups[2] = {&buffers.albedoVariance, &buffers.normalVariance};
    for (std::size_t g = 0; g < 2; ++g) {
        std::vector<float>* group = &planes.features[3 * g];  // read while the filter writes `out`
        const std::vector<float> level = noiseLevel(*groups[g], group, planes.width, planes.height);
        if (std::none_of(level.begin(), level.end(), [](float v) { return v > 0.0f; })) continue;
        std::vector<float> out[3];
        for (std::vector<float>& plane : out) plane.resize(level.size());
        const GroupFilter filter{group,
                                 level,
                                 out,
                                 planes.width,
                                 planes.height,
                                 settings.featureRadius,
                                 settings.featureK * settings.featureK};
        tbb::parallel_for(tbb::blocked_range<int>(0, planes.height),
                          [&](const tbb::blocked_range<int>& rows) { filter(rows.begin(), rows.end()); });
        for (int c = 0; c < 3; ++c) group[c] = std::move(out[c]);
    }
}

}  // namespace fluence::denoise
