#include "core/sampling.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace fluence {

Vec2f sampleUniformDisk(Vec2f u) {
    float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
    if (ox == 0.0f && oy == 0.0f) return {0.0f, 0.0f};
    float r, theta;
    if (std::abs(ox) > std::abs(oy)) {
        r = ox;
        theta = (kPi / 4.0f) * (oy / ox);
    } else {
        r = oy;
        theta = kPi / 2.0f - (kPi / 4.0f) * (ox / oy);
    }
    return {r * std::cos(theta), r * std::sin(theta)};
}

Vec3f sampleCosineHemisphere(Vec2f u) {
    Vec2f d = sampleUniformDisk(u);
    float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}

Vec3f sampleUniformSphere(Vec2f u) {
    float z = 1.0f - 2.0f * u.x;
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3f sampleUniformCone(Vec2f u, float cosThetaMax) {
    float cosTheta = (1.0f - u.x) + u.x * cosThetaMax;
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

Vec2f sampleUniformTriangle(Vec2f u) {
    // Heitz 2019, "A Low-Distortion Map Between Triangle and Square".
    float b0, b1;
    if (u.x < u.y) {
        b0 = u.x / 2.0f;
        b1 = u.y - b0;
    } else {
        b1 = u.y / 2.0f;
        b0 = u.x - b1;
    }
    return {b0, b1};
}

DiscreteDistribution::DiscreteDistribution(const std::vector<double>& weights) {
    double total = 0.0;
    for (double w : weights) {
        if (!(w >= 0.0) || !std::isfinite(w)) throw std::invalid_argument("DiscreteDistribution: weights must be finite and >= 0");
        total += w;
    }
    if (weights.empty()) return;
    pmf_.resize(weights.size());
    cdf_.resize(weights.size());
    double running = 0.0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        double p = total > 0.0 ? weights[i] / total : 1.0 / static_cast<double>(weights.size());
        pmf_[i] = static_cast<float>(p);
        running += p;
        cdf_[i] = running;
    }
    cdf_.back() = 1.0;
}

std::size_t DiscreteDistribution::sample(float u) const {
    auto it = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
    std::size_t i = static_cast<std::size_t>(it - cdf_.begin());
    i = std::min(i, cdf_.size() - 1);
    while (pmf_[i] == 0.0f && i > 0) --i;  // never return a zero-probability item
    return i;
}

}  // namespace fluence
