#include "core/splat_film.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fluence {

namespace {

constexpr double kScale = double(std::int64_t(1) << SplatFilm::kFractionBits);
constexpr std::int64_t kMaxSum = std::numeric_limits<std::int64_t>::max();

// old + v, or kMaxSum where that would exceed it (old, v >= 0): min(exact sum, kMaxSum) whatever
// the order of the adds.
void saturatingAdd(std::atomic<std::int64_t>& sum, std::int64_t v) {
    std::int64_t old = sum.load(std::memory_order_relaxed);
    while (!sum.compare_exchange_weak(old, v > kMaxSum - old ? kMaxSum : old + v, std::memory_order_relaxed)) {}
}

}  // namespace

SplatFilm::SplatFilm(int width, int height, int originX, int originY, int layers)
    : width_(width),
      height_(height),
      originX_(originX),
      originY_(originY),
      layers_(layers),
      sums_(static_cast<std::size_t>(width > 0 ? width : 0) * static_cast<std::size_t>(height > 0 ? height : 0) *
            static_cast<std::size_t>(layers >= 0 ? layers + 1 : 0) * 3) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("splat film resolution must be positive");
    if (layers < 0) throw std::invalid_argument("a splat film's layer count must not be negative");
}

bool SplatFilm::addTo(int slot, float x, float y, const RGB& value) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(value[c]) || value[c] < 0.0f) return false;
    const double px = std::floor(double(x)) - originX_, py = std::floor(double(y)) - originY_;
    if (!(px >= 0.0 && px < width_ && py >= 0.0 && py < height_)) return true;
    const std::size_t index = indexOf(slot, static_cast<std::size_t>(px), static_cast<std::size_t>(py));
    for (int c = 0; c < 3; ++c) {
        if (value[c] == 0.0f) continue;
        const double clamped = std::min(double(value[c]), kMaxValue);
        saturatingAdd(sums_[index + std::size_t(c)], std::llround(clamped * kScale));
    }
    return true;
}

std::array<double, 3> SplatFilm::sumOf(int slot, int x, int y) const {
    const std::size_t index = indexOf(slot, static_cast<std::size_t>(x), static_cast<std::size_t>(y));
    std::array<double, 3> s;
    for (std::size_t c = 0; c < 3; ++c) s[c] = double(sums_[index + c].load(std::memory_order_relaxed)) / kScale;
    return s;
}

std::vector<std::int64_t> SplatFilm::fixedSums() const {
    std::vector<std::int64_t> sums(sums_.size());
    for (std::size_t i = 0; i < sums.size(); ++i) sums[i] = sums_[i].load(std::memory_order_relaxed);
    return sums;
}

void SplatFilm::restore(const std::vector<std::int64_t>& sums) {
    if (sums.size() != sums_.size()) throw std::invalid_argument("splat film sums of another size");
    for (std::size_t i = 0; i < sums.size(); ++i) sums_[i].store(sums[i], std::memory_order_relaxed);
}

}  // namespace fluence
