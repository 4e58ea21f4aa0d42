// OrenNayarBsdf: rough diffuse reflection, the qualitative model of Oren & Nayar 1994
// ("Generalization of Lambert's reflectance model", SIGGRAPH; their equation 30), as MaterialX's
// oren_nayar_diffuse_bsdf evaluates it for Standard Surface's diffuse_roughness.
//
//   f = albedo / pi * (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta))
//   A = 1 - 0.5 s^2 / (s^2 + 0.33),  B = 0.45 s^2 / (s^2 + 0.09),  s = sigma (radians)
//   alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o)   (wo and wi on one side; two-sided)
//
// | parameter | meaning                                                         |
// |-----------|-----------------------------------------------------------------|
// | albedo    | the Lambertian albedo the surface would have with sigma = 0      |
// | sigma     | standard deviation of the facet slope angle, radians, >= 0      |
//
// sigma = 0 is exactly Lambertian. Rough surfaces back-scatter (brighter towards the light) and
// reflect a little less than `albedo` overall (the model ignores interreflection between facets).
// Sampling is cosine-weighted; f and pdf follow render/bsdf.h. Flags: reflection, diffuse. D.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/sampling.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

class OrenNayarBsdf final : public TwoSidedReflection<OrenNayarBsdf> {
public:
    OrenNayarBsdf(const RGB& albedo, float sigma) : albedo_(albedo) {
        float s2 = std::max(sigma, 0.0f) * std::max(sigma, 0.0f);
        a_ = 1.0f - 0.5f * s2 / (s2 + 0.33f);
        b_ = 0.45f * s2 / (s2 + 0.09f);
    }

    unsigned flags() const override { return kBsdfReflection | kBsdfDiffuse; }

private:
    friend class TwoSidedReflection<OrenNayarBsdf>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const {
        float sinI = std::sqrt(std::max(0.0f, 1.0f - wi.z * wi.z)),
              sinO = std::sqrt(std::max(0.0f, 1.0f - wo.z * wo.z));
        float term = 0.0f;
        if (sinI > 1e-4f && sinO > 1e-4f) {
            float cosDeltaPhi = (wi.x * wo.x + wi.y * wo.y) / (sinI * sinO);
            // alpha is the larger polar angle: its sine is the larger; beta's tangent the smaller angle's.
            float sinAlpha = wi.z < wo.z ? sinI : sinO;
            float tanBeta = wi.z < wo.z ? sinO / wo.z : sinI / wi.z;
            term = std::max(0.0f, cosDeltaPhi) * sinAlpha * tanBeta;
        }
        return albedo_ * (kInvPi * (a_ + b_ * term));
    }
    float pdfUpper(const Vec3f&, const Vec3f& wi) const { return cosineHemispherePdf(wi.z); }
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float, Vec2f u) const {
        Vec3f wi = sampleCosineHemisphere(u);
        float p = cosineHemispherePdf(wi.z);
        if (p == 0.0f) return std::nullopt;
        return BsdfSample{fUpper(wo, wi), wi, p};
    }

    RGB albedo_;
    float a_, b_;
};

}  // namespace fluence::render
