// CharlieSheenBsdf: the sheen of cloth and dusty surfaces, the "Charlie" microfiber lobe of
// Estevez & Kulla 2017 ("Production Friendly Microfacet Sheen BRDF", Sony Pictures Imageworks).
//
//   f(wo, wi) = tint D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),   h = normalize(wo + wi)
//   D(h)      = (2 + 1/r) sin^(1/r)(theta_h) / (2 pi)         (fibers standing out of the surface)
//   G2        = 1 / (1 + Lambda(cos theta_o) + Lambda(cos theta_i))     (height-correlated Smith)
//   Lambda(c) = exp(L(c)) for c < 1/2, exp(2 L(1/2) - L(1 - c)) otherwise,
//   L(x)      = a / (1 + b x^c) + d x + e, the paper's fit, its five coefficients interpolated
//               between those fitted at r = 0 and r = 1 by (1 - r)^2
//   reflectance(w)         = tint E(cos theta_w, r), E the lobe's directional albedo (tabulated)
//   averageReflectance()   = tint Eavg(r), its cosine-weighted average
//
// | parameter | meaning                                                                    |
// |-----------|----------------------------------------------------------------------------|
// | tint      | per-channel scale in [0, 1] (Standard Surface's sheen x sheen_color)        |
// | roughness | r, Standard Surface's sheen_roughness, used as the paper's r (as MaterialX  |
// |           | does; not squared); clamped to [kSheenMinRoughness, 1]                      |
//
// D is normalised as projected area (the integral of D(h) cos theta_h is 1). Without the
// paper's "terminator softening" (which changes Lambda(wi) only and would break reciprocity).
// Below r = 0.1 the fitted Lambda lets the lobe reflect more than it receives at grazing angles
// (the albedo reaches 1.1 at r = 0.05 and 2.1 at r = 0.01 near cos theta = 0.003), so r is
// clamped to 0.1; from there to 1 the albedo is at most 0.95 (at r = 1, grazing). Sampling:
// uniform over the hemisphere, pdf = 1 / (2 pi): for this broad lobe the albedo estimate has a
// third (cos theta_o = 0.3) to a fifth (0.05) of the variance of cosine sampling, at the grazing
// angles where sheen is strong. Reciprocal; two-sided. Flags: reflection, glossy. Path-class
// label: D.
//
// The directional albedo E(cos theta, r) = integral of f cos theta_i over the hemisphere (tint 1)
// is computed once, on first use (about 50 ms), by a 32 x 32-point quadrature at 32 values of
// cbrt(cos theta), which resolves the steep grazing end, times 24 values of r, and interpolated
// bilinearly between them: tests/render/bsdf_sheen_test.cpp holds it within 0.005 of an adaptive
// quadrature for cos theta >= 0.001. A layer (render/bsdfs/layered.h) takes that energy from its
// base.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/sampling.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

inline constexpr float kSheenMinRoughness = 0.1f;

// The tables' roughness axis: kSheenRoughnesses values of r evenly spaced over
// [kSheenMinRoughness, 1].
inline constexpr int kSheenRoughnesses = 24;
inline float sheenRoughnessAt(int j) {
    return kSheenMinRoughness + (1.0f - kSheenMinRoughness) * float(j) / (kSheenRoughnesses - 1);
}

// Calls visit(wi, weight) at the points of the tables' quadrature over the upper hemisphere, for
// a lobe symmetric about the plane of wo (in the xz plane): the midpoint rule in (t, phi) with
// cos theta_i = t^2 (points crowd towards the horizon, where the lobe's grazing peak is) over phi
// in [0, pi]. The integral of g over the hemisphere is 2 pi / kSheenQuadrature^2 times the sum of
// weight g(wi).
inline constexpr int kSheenQuadrature = 32;  // points per dimension
template <typename Visit>
void forEachSheenQuadraturePoint(Visit visit) {
    for (int i = 0; i < kSheenQuadrature; ++i) {
        float t = (i + 0.5f) / kSheenQuadrature, z = t * t, s = std::sqrt(std::max(0.0f, 1.0f - z * z));
        for (int j = 0; j < kSheenQuadrature; ++j) {
            float phi = kPi * (j + 0.5f) / kSheenQuadrature;
            visit(Vec3f(s * std::cos(phi), s * std::sin(phi), z), 2.0f * t);  // dz = 2 t dt
        }
    }
}

// E(cosTheta, roughness): the directional albedo of the untinted Charlie lobe (tabulated; the
// roughness clamped as the lobe clamps it).
float charlieSheenAlbedo(float cosTheta, float roughness);
// Eavg(roughness) = 2 integral_0^1 E(mu) mu dmu, of the tabulated E (by a 512-point midpoint rule
// at each tabulated roughness, interpolated linearly between them).
float charlieSheenAverageAlbedo(float roughness);

class CharlieSheenBsdf final : public TwoSidedReflection<CharlieSheenBsdf> {
public:
    CharlieSheenBsdf(const RGB& tint, float roughness);

    unsigned flags() const override { return kBsdfReflection | kBsdfGlossy; }
    // The share of the light arriving at cosTheta (> 0) that the lobe reflects: tint E(cos, r).
    RGB reflectance(const Vec3f& w) const { return tint_ * charlieSheenAlbedo(w.z, roughness_); }
    RGB averageReflectance() const { return tint_ * charlieSheenAverageAlbedo(roughness_); }

    float D(const Vec3f& h) const;
    float lambda(float cosTheta) const;

private:
    friend class TwoSidedReflection<CharlieSheenBsdf>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const;
    float pdfUpper(const Vec3f&, const Vec3f&) const;
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const;
    float fitL(float x) const { return a_ / (1.0f + b_ * std::pow(x, c_)) + d_ * x + e_; }

    RGB tint_;
    float roughness_;
    float normalization_;  // (2 + 1/r) / (2 pi)
    float a_, b_, c_, d_, e_;
    float fitLHalf_;  // L(1/2)
};

}  // namespace fluence::render
