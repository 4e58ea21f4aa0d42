// DiffuseGlossyBsdf<Lobe>: the shared form of the Phong family, a constant plus a power lobe,
//
//   f(wo, wi) = kd + ks max(0, Lobe::cosine(wo, wi))^n
//
// where Lobe::cosine is cos alpha (wi against the mirror direction of wo; PhongLobe) or cos
// theta_h (the half vector against the normal; BlinnPhongLobe). The models are this form with
// different constants: the seeds' original Phong (render/bsdfs/phong.h) takes kd and ks as they
// are; the energy-conserving versions (modified_phong.h, blinn_phong.h) come from normalised(),
// which scales each term to reflect a given albedo at normal incidence.
//
// A Lobe provides, for wo.z > 0:
//   static float cosine(wo, wi);
//   static float albedoAtNormalIncidence(float n);  // integral of cosine^n |cos theta_i| dwi, wo = +z
//   static Vec3f sample(wo, Vec2f u, float n);      // may return a direction below the surface
//   static float pdf(wo, wi, float n);              // density of sample(), for wi.z > 0
//
// Sampling picks the diffuse term (cosine-weighted) or the lobe with probabilities proportional
// to their albedos at normal incidence, and returns the mixture's density; directions drawn
// below the surface are rejected, so pdf integrates to less than 1 when the lobe crosses the
// horizon. Reflection only, two-sided; reciprocal for both lobes.
#pragma once

#include <cmath>
#include <optional>

#include "core/sampling.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

template <typename Lobe>
class DiffuseGlossyBsdf final : public TwoSidedReflection<DiffuseGlossyBsdf<Lobe>> {
public:
    // kd, ks: BRDF values (per steradian), not albedos; n >= 0.
    DiffuseGlossyBsdf(const RGB& kd, const RGB& ks, float n) : kd_(kd), ks_(ks), n_(n) {
        float diffuse = kPi * average(kd), glossy = Lobe::albedoAtNormalIncidence(n) * average(ks);
        pDiffuse_ = diffuse + glossy > 0.0f ? diffuse / (diffuse + glossy) : 1.0f;
    }

    // The model whose diffuse term reflects rhoD and whose lobe reflects rhoS at normal
    // incidence (where both reflect the most): kd = rhoD / pi, ks = rhoS / albedoAtNormalIncidence(n).
    // With rhoD + rhoS <= 1 per channel, it reflects at most 1 at every angle.
    static DiffuseGlossyBsdf normalised(const RGB& rhoD, const RGB& rhoS, float n) {
        return DiffuseGlossyBsdf(rhoD * kInvPi, rhoS / Lobe::albedoAtNormalIncidence(n), n);
    }

    unsigned flags() const override {
        return kBsdfReflection | (isBlack(kd_) ? 0u : kBsdfDiffuse) | (isBlack(ks_) ? 0u : kBsdfGlossy);
    }

private:
    friend class TwoSidedReflection<DiffuseGlossyBsdf>;

    static float average(const RGB& c) { return (c.x + c.y + c.z) / 3.0f; }

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const {
        const LobeSplit split = splitUpper(wo, wi);
        return split.diffuse + split.glossy;
    }
    LobeSplit splitUpper(const Vec3f& wo, const Vec3f& wi) const {
        float c = Lobe::cosine(wo, wi);
        return {kd_, c > 0.0f ? ks_ * std::pow(c, n_) : RGB(0.0f)};
    }
    float pdfUpper(const Vec3f& wo, const Vec3f& wi) const {
        return pDiffuse_ * cosineHemispherePdf(wi.z) + (1.0f - pDiffuse_) * Lobe::pdf(wo, wi, n_);
    }
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const {
        Vec3f wi = uLobe < pDiffuse_ ? sampleCosineHemisphere(u) : Lobe::sample(wo, u, n_);
        if (wi.z <= 0.0f) return std::nullopt;
        float p = pdfUpper(wo, wi);
        if (!(p > 0.0f)) return std::nullopt;
        return BsdfSample{fUpper(wo, wi), wi, p};
    }

    RGB kd_, ks_;
    float n_;
    float pDiffuse_;  // probability of sampling the diffuse term
};

}  // namespace fluence::render
