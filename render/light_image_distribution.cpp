#include "render/light_image_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/scene_description.h"

namespace fluence::render {

namespace {

// Fills cdf[0..n] with the running sums of w[0..n-1] scaled to end at 1 (even steps when they
// sum to 0) and returns the sum.
double buildCdf(const float* w, int n, float* cdf) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += w[i];
    double running = 0.0;
    cdf[0] = 0.0f;
    for (int i = 0; i < n; ++i) {
        running += sum > 0.0 ? w[i] : 1.0;
        cdf[i + 1] = static_cast<float>(running / (sum > 0.0 ? sum : n));
    }
    cdf[n] = 1.0f;
    return sum;
}

// Fills guide[0..n-1] with the cell that holds k / n (the last i with cdf[i] <= k / n), where
// the search for u in [k / n, (k + 1) / n) can start (Chen & Asau's guide table).
void buildGuide(const float* cdf, int n, int* guide) {
    int i = 0;
    for (int k = 0; k < n; ++k) {
        while (i + 1 < n && cdf[i + 1] <= float(k) / n) ++i;
        guide[k] = i;
    }
}

// The cell whose cdf interval holds u (never an empty one: the last i with cdf[i] <= u), and u's
// position inside it in [0, 1). The guide table starts the search in that cell or a few before
// it (as many as cdf intervals end within u's 1/n of the unit interval: about one on average).
std::pair<int, float> invert(const float* cdf, const int* guide, int n, float u) {
    int i = guide[std::min(static_cast<int>(u * n), n - 1)];
    while (i + 1 < n && cdf[i + 1] <= u) ++i;
    while (i > 0 && cdf[i] > u) --i;  // only if float rounding started it past u
    float width = cdf[i + 1] - cdf[i];
    float within = width > 0.0f ? (u - cdf[i]) / width : 0.5f;
    return {i, std::clamp(within, 0.0f, 0x1.fffffep-1f)};
}

}  // namespace

ImageDistribution::ImageDistribution(int width, int height, std::vector<float> weights)
    : width_(width), height_(height), weights_(std::move(weights)) {
    if (width <= 0 || height <= 0 || weights_.size() != std::size_t(width) * height)
        throw std::invalid_argument("ImageDistribution: expected width * height weights");
    for (float w : weights_)
        if (!(w >= 0.0f) || !std::isfinite(w))
            throw std::invalid_argument("ImageDistribution: weights must be finite and >= 0");
    columnCdf_.resize(std::size_t(height) * (width + 1));
    std::vector<float> rowSums(height);
    double total = 0.0;
    for (int y = 0; y < height; ++y) {
        rowSums[y] = static_cast<float>(
            buildCdf(&weights_[std::size_t(y) * width], width, &columnCdf_[std::size_t(y) * (width + 1)]));
        total += rowSums[y];
    }
    rowCdf_.resize(height + 1);
    buildCdf(rowSums.data(), height, rowCdf_.data());
    rowGuide_.resize(height);
    buildGuide(rowCdf_.data(), height, rowGuide_.data());
    columnGuide_.resize(std::size_t(height) * width);
    for (int y = 0; y < height; ++y)
        buildGuide(&columnCdf_[std::size_t(y) * (width + 1)], width, &columnGuide_[std::size_t(y) * width]);
    if (total == 0.0) std::fill(weights_.begin(), weights_.end(), 1.0f);
    meanWeight_ = total > 0.0 ? static_cast<float>(total / (double(width) * height)) : 1.0f;
}

ImageDistribution::Sample ImageDistribution::sample(Vec2f u) const {
    auto [row, v] = invert(rowCdf_.data(), rowGuide_.data(), height_, u.y);
    const std::size_t r = row;
    auto [column, w] = invert(&columnCdf_[r * (width_ + 1)], &columnGuide_[r * width_], width_, u.x);
    return {{(column + w) / width_, (row + v) / height_}, weights_[r * width_ + column] / meanWeight_};
}

float ImageDistribution::pdf(Vec2f uv) const {
    int column = std::clamp(static_cast<int>(uv.x * width_), 0, width_ - 1);
    int row = std::clamp(static_cast<int>(uv.y * height_), 0, height_ - 1);
    return weights_[std::size_t(row) * width_ + column] / meanWeight_;
}

std::vector<float> luminanceWeights(const RgbImage& image, const RGB& scale) {
    std::vector<float> weights(image.texels.size());
    for (std::size_t i = 0; i < weights.size(); ++i) {
        float w = luminance(vmax(scale * image.texels[i], RGB(0.0f)));
        weights[i] = std::isfinite(w) ? w : 0.0f;
    }
    return weights;
}

}  // namespace fluence::render
