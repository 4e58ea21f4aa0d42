#include "render/bsdfs/hair.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/bsdf_checks.h"
#include "render/bsdfs/fresnel.h"

namespace fluence::render {

namespace {

float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safeAsin(float x) { return std::asin(std::clamp(x, -1.0f, 1.0f)); }

// log I0(x), the modified Bessel function of the first kind (x >= 0): its power series
// sum (x^2/4)^k / (k!)^2 below 12 (summed until a term adds less than 1e-8 of the sum; at most 40
// terms there), the asymptotic series above, where I0 itself would soon overflow floats.
float logBesselI0(float x) {
    x = std::max(x, 0.0f);  // cos theta of +-pi/2 rounds to -4e-8 in float
    if (x < 12.0f) {
        const float y = 0.25f * x * x;
        float term = 1.0f, sum = 1.0f;
        for (int k = 1; k <= 40 && term > 1e-8f * sum; ++k) {
            term *= y / float(k * k);
            sum += term;
        }
        return std::log(sum);
    }
    const float inv = 1.0f / x;
    return x - 0.5f * std::log(2.0f * kPi * x) + std::log1p(inv / 8.0f + 9.0f * inv * inv / 128.0f);
}

// A logistic distribution of scale s on [-pi, pi] (its density, its sample from u in [0, 1)).
float logisticCdf(float x, float s) { return 1.0f / (1.0f + std::exp(-x / s)); }
float trimmedLogistic(float x, float s) {
    const float e = std::exp(-std::abs(x) / s);
    return e / (s * (1.0f + e) * (1.0f + e)) / (logisticCdf(kPi, s) - logisticCdf(-kPi, s));
}
float sampleTrimmedLogistic(float u, float s) {
    const float lo = logisticCdf(-kPi, s), k = logisticCdf(kPi, s) - lo;
    return std::clamp(-s * std::log(1.0f / (u * k + lo) - 1.0f), -kPi, kPi);
}

// An angle wrapped into [-pi, pi].
float wrapped(float phi) { return std::remainder(phi, 2.0f * kPi); }

float mean(const RGB& c) { return (c.x + c.y + c.z) / 3.0f; }

// Fibre angles of a direction in the hair frame.
struct FibreAngles {
    float sinTheta, cosTheta, phi;
};
FibreAngles anglesOf(const Vec3f& w) {
    const float sinTheta = std::clamp(w.x, -1.0f, 1.0f);
    return {sinTheta, safeSqrt(1.0f - sinTheta * sinTheta), std::atan2(w.z, w.y)};
}

}  // namespace

struct HairBsdf::Incidence {
    FibreAngles o;
    float gammaT = 0.0f;
    std::array<RGB, kLobes + 1> attenuation;             // A_p
    std::array<float, kLobes + 1> probability;           // A_p / sum A, by channel mean
    std::array<float, kLobes + 1> sinThetaO, cosThetaO;  // theta_o tilted per lobe
};

HairBsdf::HairBsdf(const HairParams& params)
    : sigmaA_(params.absorption), eta_(params.ior), h_(std::clamp(params.offset, -1.0f, 1.0f)) {
    gammaO_ = safeAsin(h_);
    const float bm = std::clamp(params.longitudinalRoughness, 0.01f, 1.0f);
    const float bn = std::clamp(params.azimuthalRoughness, 0.01f, 1.0f);
    const float v0 = 0.726f * bm + 0.812f * bm * bm + 3.7f * std::pow(bm, 20.0f);
    v_[0] = v0 * v0;
    v_[1] = 0.25f * v_[0];
    v_[2] = v_[3] = 4.0f * v_[0];
    s_ = std::sqrt(kPi / 8.0f) * (0.265f * bn + 1.194f * bn * bn + 5.372f * std::pow(bn, 22.0f));
    const float alpha = params.tiltDegrees * kPi / 180.0f;
    const float tilt[kLobes] = {-2.0f * alpha, alpha, 4.0f * alpha};  // R, TT, TRT
    for (int p = 0; p < kLobes; ++p) {
        sinTilt_[p] = std::sin(tilt[p]);
        cosTilt_[p] = std::cos(tilt[p]);
    }
}

float HairBsdf::longitudinal(float cosThetaI, float cosThetaO, float sinThetaI, float sinThetaO, float v) {
    // csch(1/v) / (2 v) exp(-sin sin / v) I0(cos cos / v), in logarithms: 2 v sinh(1/v) =
    // v exp(1/v) (1 - exp(-2/v)).
    const float a = cosThetaI * cosThetaO / v, b = sinThetaI * sinThetaO / v;
    return std::exp(logBesselI0(a) - b - 1.0f / v - std::log(v) - std::log1p(-std::exp(-2.0f / v)));
}

HairBsdf::Incidence HairBsdf::incidence(const Vec3f& wo) const {
    Incidence in;
    in.o = anglesOf(wo);
    const float sinThetaT = in.o.sinTheta / eta_, cosThetaT = safeSqrt(1.0f - sinThetaT * sinThetaT);
    // The index the fibre's cross-section shows to wo (Bravais), and the refracted azimuth.
    const float etaP =
        std::sqrt(std::max(eta_ * eta_ - in.o.sinTheta * in.o.sinTheta, 0.0f)) / std::max(in.o.cosTheta, 1e-6f);
    const float sinGammaT = h_ / etaP, cosGammaT = safeSqrt(1.0f - sinGammaT * sinGammaT);
    in.gammaT = safeAsin(sinGammaT);
    const float length = 2.0f * cosGammaT / std::max(cosThetaT, 1e-6f);
    const RGB transmittance(std::exp(-sigmaA_.x * length), std::exp(-sigmaA_.y * length),
                            std::exp(-sigmaA_.z * length));
    const float fresnel = fresnelDielectric(in.o.cosTheta * safeSqrt(1.0f - h_ * h_), eta_);
    in.attenuation[0] = RGB(fresnel);
    in.attenuation[1] = transmittance * ((1.0f - fresnel) * (1.0f - fresnel));
    for (int p = 2; p < kLobes; ++p) in.attenuation[p] = in.attenuation[p - 1] * transmittance * fresnel;
    const RGB tf = transmittance * fresnel;
    in.attenuation[kLobes] = in.attenuation[kLobes - 1] * tf / (RGB(1.0f) - tf);
    float total = 0.0f;
    for (const RGB& a : in.attenuation) total += mean(a);
    for (int p = 0; p <= kLobes; ++p) in.probability[p] = total > 0.0f ? mean(in.attenuation[p]) / total : 0.0f;
    for (int p = 0; p < kLobes; ++p) {
        in.sinThetaO[p] = in.o.sinTheta * cosTilt_[p] + in.o.cosTheta * sinTilt_[p];
        in.cosThetaO[p] = std::abs(in.o.cosTheta * cosTilt_[p] - in.o.sinTheta * sinTilt_[p]);
    }
    in.sinThetaO[kLobes] = in.o.sinTheta;
    in.cosThetaO[kLobes] = in.o.cosTheta;
    return in;
}

template <typename Weight>
Weight HairBsdf::lobeSum(const Incidence& in, const Vec3f& wi, const std::array<Weight, kLobes + 1>& weights) const {
    const FibreAngles i = anglesOf(wi);
    const float phi = i.phi - in.o.phi;
    Weight sum(0.0f);
    for (int p = 0; p <= kLobes; ++p) {
        const float m = longitudinal(i.cosTheta, in.cosThetaO[p], i.sinTheta, in.sinThetaO[p], v_[p]);
        const float n = p < kLobes
                            ? trimmedLogistic(wrapped(phi - (2.0f * p * in.gammaT - 2.0f * gammaO_ + p * kPi)), s_)
                            : 1.0f / (2.0f * kPi);
        sum += weights[p] * (m * n);
    }
    return sum;
}

RGB HairBsdf::f(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    const float cosine = std::abs(wi.z);
    if (!(cosine > 0.0f)) return RGB(0.0f);
    const Incidence in = incidence(wo);
    return lobeSum(in, wi, in.attenuation) / cosine;
}

float HairBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    const Incidence in = incidence(wo);
    return lobeSum(in, wi, in.probability);
}

std::optional<BsdfSample> HairBsdf::sample(const Vec3f& wo, float uLobe, Vec2f u) const {
    const Incidence in = incidence(wo);
    // The lobe, and uLobe rescaled within it to draw the azimuth.
    int p = 0;
    for (; p < kLobes && uLobe >= in.probability[p]; ++p) uLobe -= in.probability[p];
    if (!(in.probability[p] > 0.0f)) return std::nullopt;
    const float uPhi = std::clamp(uLobe / in.probability[p], 0.0f, 1.0f - 1e-7f);
    // theta_i about -theta_o (tilted) from M_p.
    const float v = v_[p];
    const float u0 = std::max(u.x, 1e-5f);
    const float cosTheta = 1.0f + v * std::log(u0 + (1.0f - u0) * std::exp(-2.0f / v));
    const float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
    const float cosPhi = std::cos(2.0f * kPi * u.y);
    const float sinThetaI = std::clamp(-cosTheta * in.sinThetaO[p] + sinTheta * cosPhi * in.cosThetaO[p], -1.0f, 1.0f);
    const float cosThetaI = safeSqrt(1.0f - sinThetaI * sinThetaI);
    const float dPhi = p < kLobes ? 2.0f * p * in.gammaT - 2.0f * gammaO_ + p * kPi + sampleTrimmedLogistic(uPhi, s_)
                                  : 2.0f * kPi * uPhi;
    const float phiI = in.o.phi + dPhi;
    BsdfSample s;
    s.wi = normalize(Vec3f(sinThetaI, cosThetaI * std::cos(phiI), cosThetaI * std::sin(phiI)));
    s.pdf = lobeSum(in, s.wi, in.probability);
    const float cosine = std::abs(s.wi.z);
    if (!(s.pdf > 0.0f) || !(cosine > 0.0f)) return std::nullopt;
    s.f = lobeSum(in, s.wi, in.attenuation) / cosine;
    std::optional<BsdfSample> result(s);
    dcheckSample(wo, result);
    return result;
}

RGB hairAbsorptionFromColour(const RGB& colour, float azimuthalRoughness) {
    const float b = std::clamp(azimuthalRoughness, 0.01f, 1.0f);
    const float denominator = 5.969f - 0.215f * b + 2.532f * b * b - 10.73f * std::pow(b, 3.0f) +
                              5.574f * std::pow(b, 4.0f) + 0.245f * std::pow(b, 5.0f);
    auto channel = [&](float c) {
        const float l = std::log(std::clamp(c, 1e-4f, 1.0f)) / denominator;
        return l * l;
    };
    return {channel(colour.x), channel(colour.y), channel(colour.z)};
}

}  // namespace fluence::render
