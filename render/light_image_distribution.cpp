#include "render/light_image_distribution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

// The cell whose cdf interval holds u (never an empty one), and u's position inside it in [0, 1).
std::pair<int, float> invert(const float* cdf, int n, float u) {
    int i = static_cast<int>(std::upper_bound(cdf, cdf + n + 1, u) - cdf) - 1;
    i = std::clamp(i, 0, n - 1);
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
        if (!(w >= 0.0f) || !std::isfinite(w)) throw std::invalid_argument("ImageDistribution: weights must be finite and >= 0");
    columnCdf_.resize(std::size_t(height) * (width + 1));
    std::vector<float> rowSums(height);
    double total = 0.0;
    for (int y = 0; y < height; ++y) {
        rowSums[y] = static_cast<float>(buildCdf(&weights_[std::size_t(y) * width], width, &columnCdf_[std::size_t(y) * (width + 1)]));
        total += rowSums[y];
    }
    rowCdf_.resize(height + 1);
    buildCdf(rowSums.data(), height, rowCdf_.data());
    if (total == 0.0) std::fill(weights_.begin(), weights_.end(), 1.0f);
    meanWeight_ = total > 0.0 ? static_cast<float>(total / (double(width) * height)) : 1.0f;
}

ImageDistribution::Sample ImageDistribution::sample(Vec2f u) const {
    auto [row, v] = invert(rowCdf_.data(), height_, u.y);
    auto [column, w] = invert(&columnCdf_[std::size_t(row) * (width_ + 1)], width_, u.x);
    return {{(column + w) / width_, (row + v) / height_}, weights_[std::size_t(row) * width_ + column] / meanWeight_};
}

float ImageDistribution::pdf(Vec2f uv) const {
    int column = std::clamp(static_cast<int>(uv.x * width_), 0, width_ - 1);
    int row = std::clamp(static_cast<int>(uv.y * height_), 0, height_ - 1);
    return weights_[std::size_t(row) * width_ + column] / meanWeight_;
}

}  // namespace fluence::render
