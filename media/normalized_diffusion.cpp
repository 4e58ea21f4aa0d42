#include "media/normalized_diffusion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fluence::media {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// p(r) = (e^(-r/d) + e^(-r/(3d))) / (4d): the mixture of SAMPLING, 1/4 (1/d) e^(-r/d) +
// 3/4 (1/(3d)) e^(-r/(3d)).
double radiusDensity(double r, double d) { return (std::exp(-r / d) + std::exp(-r / (3.0 * d))) / (4.0 * d); }

// p(r) / (2 pi r), with r held above kMinRadiusOverD d (see r -> 0).
double areaDensity(double r, double d) {
    return radiusDensity(r, d) / (kTwoPi * std::max(r, NormalizedDiffusion::kMinRadiusOverD * d));
}

// The r / d at which F = kMaxRadiusEnergyFraction. F(r) >= 1 - e^(-r/(3d)), so F reaches the
// fraction f by r / d = 3 ln(1 / (1 - f)): bisection on [0, that].
double maxRadiusOverD() {
    constexpr double f = NormalizedDiffusion::kMaxRadiusEnergyFraction;
    double lo = 0.0, hi = 3.0 * std::log(1.0 / (1.0 - f));
    for (int i = 0; i < 100; ++i) {
        double mid = 0.5 * (lo + hi);
        (normalizedDiffusionCdf(mid, 1.0) < f ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace

float normalizedDiffusionScale(float albedo) {
    const double a = albedo, offset = std::abs(a - 0.8);
    return float(1.85 - a + 7.0 * offset * offset * offset);
}

double normalizedDiffusionCdf(double r, double d) {
    // 1 - e^(-r/d) / 4 - 3 e^(-r/(3d)) / 4, through expm1 so that small r keeps its precision.
    return -0.25 * std::expm1(-r / d) - 0.75 * std::expm1(-r / (3.0 * d));
}

NormalizedDiffusion::NormalizedDiffusion(const RGB& albedo, const RGB& meanFreePath) {
    for (int c = 0; c < 3; ++c) {
        albedo_[c] = std::clamp(albedo[c], 0.0f, 1.0f);
        d_[c] = meanFreePath[c] / normalizedDiffusionScale(albedo_[c]);
    }
}

RGB NormalizedDiffusion::profile(float r) const {
    RGB value;
    for (int c = 0; c < 3; ++c) value[c] = float(albedo_[c] * areaDensity(r, d_[c]));
    return value;
}

float NormalizedDiffusion::sampleRadius(int channel, float u) const {
    // u < 1/4 picks the component at rate 1/d, the rest the one at rate 1/(3d); either way u is
    // remapped to [0, 1) and that exponential's CDF, 1 - e^(-r/length), inverted.
    const double d = d_[channel], scaled = 4.0 * double(u);
    const bool steep = scaled < 1.0;
    const double remapped = steep ? scaled : (scaled - 1.0) / 3.0;
    return float((steep ? d : 3.0 * d) * -std::log1p(-remapped));
}

float NormalizedDiffusion::pdfRadius(int channel, float r) const { return float(radiusDensity(r, d_[channel])); }

float NormalizedDiffusion::pdfArea(int channel, float r) const { return float(areaDensity(r, d_[channel])); }

float NormalizedDiffusion::maxRadius(int channel) const {
    static const double ratio = maxRadiusOverD();
    return float(ratio * d_[channel]);
}

}  // namespace fluence::media
