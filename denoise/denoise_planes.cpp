#include "denoise/denoise_planes.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace fluence::denoise {

namespace {

// Channel `channel` of an interleaved image of `stride` floats per pixel, times `scale`.
std::vector<float> plane(const std::vector<float>& image, int stride, int channel, float scale = 1.0f) {
    std::vector<float> out(image.size() / std::size_t(stride));
    for (std::size_t p = 0; p < out.size(); ++p) out[p] = scale * image[p * std::size_t(stride) + std::size_t(channel)];
    return out;
}

}  // namespace

// The mean of `image` over the (2 radius + 1)² box around each pixel (at the borders, over the
// pixels inside the image), by a horizontal then a vertical pass.
std::vector<float> boxMean(const std::vector<float>& image, int width, int height, int radius) {
    std::vector<float> rows(image.size()), out(image.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float sum = 0.0f;
            const int x0 = std::max(0, x - radius), x1 = std::min(width - 1, x + radius);
            for (int xx = x0; xx <= x1; ++xx) sum += image[std::size_t(y) * width + xx];
            rows[std::size_t(y) * width + x] = sum / float(x1 - x0 + 1);
        }
    for (int y = 0; y < height; ++y) {
        const int y0 = std::max(0, y - radius), y1 = std::min(height - 1, y + radius);
        for (int x = 0; x < width; ++x) {
            float sum = 0.0f;
            for (int yy = y0; yy <= y1; ++yy) sum += rows[std::size_t(yy) * width + x];
            out[std::size_t(y) * width + x] = sum / float(y1 - y0 + 1);
        }
    }
    return out;
}

DenoisePlanes makePlanes(const DenoiseBuffers& in, int windowRadius) {
    DenoisePlanes planes;
    planes.width = in.width;
    planes.height = in.height;
    const std::size_t pixels = std::size_t(in.width) * std::size_t(in.height);
    planes.pixelVariance.assign(pixels, 0.0f);
    for (int c = 0; c < 3; ++c) {
        for (int h = 0; h < 2; ++h)
            planes.guide[h][std::size_t(c)] = boxMean(plane(in.halves[h], 3, c), in.width, in.height, 1);
        planes.variance[std::size_t(c)] = plane(in.variance, 3, c);
        planes.smoothVariance[std::size_t(c)] = boxMean(planes.variance[std::size_t(c)], in.width, in.height, 1);
        planes.guideVariance[std::size_t(c)] = planes.smoothVariance[std::size_t(c)];
        for (float& v : planes.guideVariance[std::size_t(c)]) v *= 2.0f / 9.0f;
        for (std::size_t p = 0; p < pixels; ++p) planes.pixelVariance[p] += planes.variance[std::size_t(c)][p] / 3.0f;
        planes.features[std::size_t(c)] = plane(in.albedo, 3, c);
        planes.features[std::size_t(3 + c)] = plane(in.normal, 3, c);
    }
    planes.features[6] = in.depth;
    // The window's variance level, robust to a firefly: the mean over the window of the pixels'
    // variances, each clamped to that mean first (a firefly of variance F raises the first mean by
    // F / n, and the second by F / n² only).
    const std::vector<float> level = boxMean(planes.pixelVariance, in.width, in.height, windowRadius);
    std::vector<float> clamped(pixels);
    for (std::size_t p = 0; p < pixels; ++p) clamped[p] = std::min(planes.pixelVariance[p], level[p]);
    planes.windowVariance = boxMean(clamped, in.width, in.height, windowRadius);

    // Planes kept in `storage`: the halves' colours, the noisy beauty, then the layers.
    for (int h = 0; h < 2; ++h)
        for (int c = 0; c < 3; ++c) planes.storage.push_back(plane(in.halves[h], 3, c));
    for (int c = 0; c < 3; ++c) {
        std::vector<float> mean(pixels);
        for (std::size_t p = 0; p < pixels; ++p)
            mean[p] = 0.5f * (in.halves[0][3 * p + std::size_t(c)] + in.halves[1][3 * p + std::size_t(c)]);
        planes.storage.push_back(std::move(mean));
    }
    for (const std::vector<float>& layer : in.layers)
        for (int c = 0; c < 3; ++c) planes.storage.push_back(plane(layer, 3, c));
    for (int h = 0; h < 2; ++h)
        for (int c = 0; c < 3; ++c) planes.values[h].push_back(planes.storage[std::size_t(3 * h + c)].data());
    for (int c = 0; c < 3; ++c) planes.noisy.push_back(planes.storage[std::size_t(6 + c)].data());
    for (std::size_t l = 9; l < planes.storage.size(); ++l) {
        for (int h = 0; h < 2; ++h) planes.values[h].push_back(planes.storage[l].data());
        planes.noisy.push_back(planes.storage[l].data());
    }
    return planes;
}

}  // namespace fluence::denoise
