#include "render/bsdfs/thin_dielectric_multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/lobe_choice.h"
#include "render/bsdfs/thin_dielectric_albedo.h"

namespace fluence::render {

namespace {

// k = 2 Favg / (1 + Favg): the share of diffuse light a smooth slab of index eta reflects.
float thinSheetDiffuseReflectance(float eta) {
    const float fAvg = ggxReflectionAverageAlbedo(0.0f, f0FromEta(eta));
    return 2.0f * fAvg / (1.0f + fAvg);
}

}  // namespace

ThinSheetMultipleScattering thinSheetMultipleScattering(float eta, float alpha, const DielectricTints& tints) {
    const float k = thinSheetDiffuseReflectance(eta);
    const float scale = 1.0f / std::max(1.0f - thinSheetAverageAlbedo(alpha, eta), kMinMultipleScatteringLoss);
    return {tints.reflected(k) * scale, tints.transmitted(k) * scale};
}

CompensatedThinDielectricBsdf::CompensatedThinDielectricBsdf(float eta, const GgxDistribution& ggx,
                                                             const DielectricTints& tints)
    : single_(eta, ggx, tints), eta_(eta), alpha_(std::sqrt(ggx.alphaX() * ggx.alphaY())) {
    const ThinSheetMultipleScattering lobe = thinSheetMultipleScattering(eta_, alpha_, tints);
    reflected_ = lobe.reflected * kInvPi;
    transmitted_ = lobe.transmitted * kInvPi;
    const float k = thinSheetDiffuseReflectance(eta_);
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
