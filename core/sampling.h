// Sampling routines: warps from [0,1)^2 to common domains, with their densities.
//
// Every routine here has a chi-square goodness-of-fit test against its pdf in
// tests/core/sampling_test.cpp. Densities are with respect to solid angle for directions and
// area for points.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "core/vec.h"

namespace fluence {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;

// Concentric mapping of the square to the unit disk (Shirley & Chiu 1997).
Vec2f sampleUniformDisk(Vec2f u);

// Cosine-weighted direction about +z; pdf = cos(theta) / pi.
Vec3f sampleCosineHemisphere(Vec2f u);
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

// Uniform direction on the unit sphere; pdf = 1 / (4 pi).
Vec3f sampleUniformSphere(Vec2f u);
inline constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPi);

// Uniform direction in the cone about +z with cos(half-angle) = cosThetaMax;
// pdf = 1 / (2 pi (1 - cosThetaMax)).
Vec3f sampleUniformCone(Vec2f u, float cosThetaMax);
inline float uniformConePdf(float cosThetaMax) { return 1.0f / (2.0f * kPi * (1.0f - cosThetaMax)); }

// Uniform barycentrics (b0, b1) on a triangle (b2 = 1 - b0 - b1); pdf = 1 / area.
Vec2f sampleUniformTriangle(Vec2f u);

// Veach's power heuristic with beta = 2, for one sample from each of two strategies:
// a^2 / (a^2 + b^2), computed through the ratio of the densities so that huge densities (grazing
// area-light samples reach 1e20 and more) do not overflow to inf / inf.
inline float powerHeuristic(float pdfA, float pdfB) {
    if (std::isinf(pdfA)) return std::isinf(pdfB) ? 0.5f : 1.0f;
    if (pdfA >= pdfB) {
        if (pdfA == 0.0f) return 0.0f;
        float r = pdfB / pdfA;
        return 1.0f / (1.0f + r * r);
    }
    float r = pdfA / pdfB;
    return r * r / (1.0f + r * r);
}

// A discrete distribution over n items proportional to non-negative weights.
class DiscreteDistribution {
public:
    DiscreteDistribution() = default;
    explicit DiscreteDistribution(const std::vector<double>& weights);

    bool empty() const { return pmf_.empty(); }
    std::size_t size() const { return pmf_.size(); }
    // Picks an index from u in [0,1); pmf of the result via pmf().
    std::size_t sample(float u) const;
    float pmf(std::size_t index) const { return pmf_[index]; }

private:
    std::vector<float> pmf_;
    std::vector<double> cdf_;  // cdf_[i] = P(index <= i); last entry 1
};

}  // namespace fluence
