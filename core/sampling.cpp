#include "core/sampling.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace fluence {

namespace {

// sin and cos of a in [-pi/4, pi/4], within about an ulp of float: the minimax polynomials of
// Cephes' sinf/cosf on that interval. A fraction of the cost of std::sin and std::cos, which
// reduce any argument (the concentric disk mapping below showed 6% of the Cornell box's render
// time in sincosf, bench/results/2026-11-27-throughput-s7.md).
struct SinCos {
    float sin, cos;
};
SinCos sinCosQuarterTurn(float a) {
    const float z = a * a;
    const float s = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * a + a;
    const float c =
        ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
    return {s, c};
}

}  // namespace

// Shirley and Chiu's concentric mapping: the square's point at (ox, oy) goes to radius r = the
// larger coordinate and angle theta = pi/4 * (the smaller / the larger) from that coordinate's axis.
// Which coordinate is larger is a coin flip per call, which no branch predictor learns, and a
// mispredicted branch here throws away the next-event estimation the processor runs beside a BSDF
// sample (integrators/path_tracer.cpp). So both cases are one computation on operands picked by
// index, which compiles to no branch (GCC turns `?:` selects back into one; measured in
// bench/results/2026-12-06-cornell-cpu-s20.md).
Vec2f sampleUniformDisk(Vec2f u) {
    const float o[2] = {2.0f * u.x - 1.0f, 2.0f * u.y - 1.0f};
    if (o[0] == 0.0f && o[1] == 0.0f) return {0.0f, 0.0f};
    // larger == 0: theta = pi/4 * oy/ox. larger == 1: theta = pi/2 - a with a = pi/4 * ox/oy, so
    // cos theta = sin a and sin theta = cos a.
    const int larger = std::abs(o[0]) > std::abs(o[1]) ? 0 : 1;
    const float r = o[larger];
    const SinCos t = sinCosQuarterTurn((kPi / 4.0f) * (o[1 - larger] / r));
    const float cosSin[2] = {t.cos, t.sin};
    return {r * cosSin[larger], r * cosSin[1 - larger]};
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
        if (!(w >= 0.0) || !std::isfinite(w))
            throw std::invalid_argument("DiscreteDistribution: weights must be finite and >= 0");
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
