#include "render/ies_profile.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"

namespace fluence::render {

namespace {

constexpr float kDegrees = kPi / 180.0f;

// Appends the mirror image of the horizontal angles (and their columns) about `about` degrees.
void mirror(std::vector<float>& angles, std::vector<std::vector<float>>& columns, float about) {
    for (int i = static_cast<int>(angles.size()) - 2; i >= 0; --i) {
        angles.push_back(2.0f * about - angles[i]);
        columns.push_back(columns[i]);
    }
}

// The interval [i, i+1] of `grid` holding x and where in it x lies; nullopt outside the grid.
struct Bracket {
    std::size_t i;
    float t;
};
Bracket bracket(const std::vector<float>& grid, float x) {
    if (grid.size() == 1) return {0, 0.0f};
    auto upper = std::upper_bound(grid.begin(), grid.end(), x);
    std::size_t i = std::clamp<std::size_t>(std::size_t(upper - grid.begin()), 1, grid.size() - 1) - 1;
    float t = std::clamp((x - grid[i]) / (grid[i + 1] - grid[i]), 0.0f, 1.0f);
    return {i, t};
}

}  // namespace

IesProfile::IesProfile(const texture::IesTable& table, float angleScale, bool normalize)
    : profileScale_(angleScale > -1.0f ? 1.0f + angleScale : 1.0f) {
    std::size_t nv = table.verticalDegrees.size();
    for (float v : table.verticalDegrees) vertical_.push_back(v * kDegrees);
    std::vector<float> angles = table.horizontalDegrees;
    std::vector<std::vector<float>> columns;
    for (std::size_t h = 0; h < angles.size(); ++h)
        columns.emplace_back(table.candela.begin() + h * nv, table.candela.begin() + (h + 1) * nv);
    if (angles.size() == 1) {
        const float only = angles.front();
        angles = {only, 360.0f};
        columns.push_back(columns[0]);
    } else if (angles.back() == 90.0f) {
        mirror(angles, columns, 90.0f);
        mirror(angles, columns, 180.0f);
    } else if (angles.back() == 180.0f) {
        mirror(angles, columns, 180.0f);
    } else if (angles.back() == 270.0f) {
        mirror(angles, columns, 270.0f);
    }
    for (std::size_t h = 0; h < angles.size(); ++h) {
        horizontal_.push_back(angles[h] * kDegrees);
        values_.insert(values_.end(), columns[h].begin(), columns[h].end());
    }

    // The mean intensity by the midpoint rule on a grid finer than any profile's.
    constexpr int kTheta = 360, kPhi = 720;
    double integral = 0.0;
    for (int i = 0; i < kTheta; ++i) {
        float theta = (i + 0.5f) * kPi / kTheta;
        double ring = 0.0;
        for (int j = 0; j < kPhi; ++j) ring += candela(theta, (j + 0.5f) * 2.0f * kPi / kPhi);
        integral += ring * std::sin(theta);
    }
    integral *= (kPi / kTheta) * (2.0 * kPi / kPhi);
    bool hemisphere = vertical_.back() - vertical_.front() <= kPi / 2 + 0.1f;
    mean_ = static_cast<float>(integral / ((hemisphere ? 2.0 : 4.0) * kPi));
    if (normalize) scale_ = mean_ > 0.0f ? 1.0f / mean_ : 0.0f;
}

float IesProfile::candela(float theta, float phi) const {
    if (theta < vertical_.front() || theta > vertical_.back()) return 0.0f;
    float first = horizontal_.front();
    phi = first + std::fmod(std::fmod(phi - first, 2.0f * kPi) + 2.0f * kPi, 2.0f * kPi);
    Bracket v = bracket(vertical_, theta), h = bracket(horizontal_, phi);
    std::size_t nv = vertical_.size();
    auto at = [&](std::size_t hi, std::size_t vi) { return values_[hi * nv + vi]; };
    std::size_t v1 = std::min(v.i + 1, nv - 1), h1 = std::min(h.i + 1, horizontal_.size() - 1);
    float lo = at(h.i, v.i) + v.t * (at(h.i, v1) - at(h.i, v.i));
    float hi = at(h1, v.i) + v.t * (at(h1, v1) - at(h1, v.i));
    return lo + h.t * (hi - lo);
}

float IesProfile::factor(float theta, float phi) const {
    float scaled = std::clamp((theta - kPi) / profileScale_ + kPi, 0.0f, kPi);
    return candela(scaled, phi) * scale_;
}

}  // namespace fluence::render
