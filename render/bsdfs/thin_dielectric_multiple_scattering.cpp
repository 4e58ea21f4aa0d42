#include "render/bsdfs/thin_dielectric_multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/lobe_choice.h"
#include "render/bsdfs/thin_dielectric_albedo.h"

namespace fluence::render {

CompensatedThinDielectricBsdf::CompensatedThinDielectricBsdf(float eta, const GgxDistribution& ggx,
                                                             const DielectricTints& tints)
    : single_(eta, ggx, tints), eta_(eta), alpha_(std::sqrt(ggx.alphaX() * ggx.alphaY())) {
    const float fAvg = ggxReflectionAverageAlbedo(0.0f, f0FromEta(eta_));
    const float k = 2.0f * fAvg / (1.0f + fAvg);
    const float scale = kInvPi / std::max(1.0f - thinSheetAverageAlbedo(alpha_, eta_), kMinMultipleScatteringLoss);
    reflected_ = tints.reflected(k) * scale;
    transmitted_ = tints.transmitted(k) * scale;
    const float r = lobeProbability(tints.reflected(k)), t = lobeProbability(tints.transmitted(k));
    pReflected_ = r + t > 0.0f ? r / (r + t) : 1.0f;
}

float CompensatedThinDielectricBsdf::multipleScatteringProbability(const Vec3f& w) const {
    return std::clamp(1.0f - thinSheetAlbedo(std::abs(w.z), alpha_, eta_), 0.0f, 1.0f);
}

RGB CompensatedThinDielectricBsdf::multipleScattering(const Vec3f& wo, const Vec3f& wi) const {
    return (wo.z * wi.z > 0.0f ? reflected_ : transmitted_) *
           (multipleScatteringProbability(wo) * multipleScatteringProbability(wi));
}

float CompensatedThinDielectricBsdf::multipleScatteringPdf(const Vec3f& wo, const Vec3f& wi) const {
    return (wo.z * wi.z > 0.0f ? pReflected_ : 1.0f - pReflected_) * std::abs(wi.z) * kInvPi;
}

const Bsdf& energyCompensatedThinDielectric(float eta, const GgxDistribution& ggx, const DielectricTints& tints,
                                            BsdfArena& arena) {
    if (ggx.isSmooth() || eta == 1.0f) return arena.make<ThinDielectricBsdf>(eta, ggx, tints);
    return arena.make<CompensatedThinDielectricBsdf>(eta, ggx, tints);
}

}  // namespace fluence::render
