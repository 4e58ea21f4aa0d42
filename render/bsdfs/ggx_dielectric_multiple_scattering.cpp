#include "render/bsdfs/ggx_dielectric_multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/ggx_dielectric_albedo.h"

namespace fluence::render {

CompensatedGgxDielectricBsdf::CompensatedGgxDielectricBsdf(float eta, const GgxDistribution& ggx,
                                                           const DielectricTints& tints)
    : single_(eta, ggx, tints), eta_(eta), alpha_(std::sqrt(ggx.alphaX() * ggx.alphaY())), tints_(tints) {
    outside_.average = ggxDielectricAverageAlbedo(alpha_, eta_);
    inside_.average = ggxDielectricAverageAlbedo(alpha_, 1.0f / eta_);
    const float lossOut = std::max(1.0f - outside_.average, kMinMultipleScatteringLoss),
                lossIn = std::max(1.0f - inside_.average, kMinMultipleScatteringLoss);
    const float n2 = eta_ * eta_;
    // From the side of the lower index, 1 - Favg of the light crosses.
    const float crossing = 1.0f - ggxReflectionAverageAlbedo(0.0f, f0FromEta(eta_));
    float c = eta_ >= 1.0f ? crossing / (n2 * lossIn) : crossing / lossOut;
    c = std::min({c, 1.0f / (n2 * lossIn), 1.0f / lossOut});
    outside_.transmitted = c * n2 * lossIn;
    inside_.transmitted = c * lossOut;
    outside_.reflected = 1.0f - outside_.transmitted;
    inside_.reflected = 1.0f - inside_.transmitted;
    outside_.crossing = c;
    inside_.crossing = c * n2;
}

float CompensatedGgxDielectricBsdf::outsideReflectionScale() const {
    return outside_.reflected / std::max(1.0f - outside_.average, kMinMultipleScatteringLoss);
}

float CompensatedGgxDielectricBsdf::albedo(const Vec3f& w) const {
    return ggxDielectricAlbedo(std::abs(w.z), alpha_, w.z > 0.0f ? eta_ : 1.0f / eta_);
}

RGB CompensatedGgxDielectricBsdf::multipleScattering(const Vec3f& wo, const Vec3f& wi) const {
    const Side& from = sideOf(wo);
    const float lossO = 1.0f - albedo(wo), lossI = 1.0f - albedo(wi);
    if (wo.z * wi.z > 0.0f)
        return tints_.reflection *
               (from.reflected * lossO * lossI * kInvPi / std::max(1.0f - from.average, kMinMultipleScatteringLoss));
    return tints_.transmission * (from.crossing * lossO * lossI * kInvPi);
}

float CompensatedGgxDielectricBsdf::multipleScatteringPdf(const Vec3f& wo, const Vec3f& wi) const {
    const Side& from = sideOf(wo);
    return (wo.z * wi.z > 0.0f ? from.reflected : from.transmitted) * std::abs(wi.z) * kInvPi;
}

const Bsdf& energyCompensatedDielectric(float eta, const GgxDistribution& ggx, const DielectricTints& tints,
                                        BsdfArena& arena) {
    if (ggx.isSmooth() || eta == 1.0f) return arena.make<GgxDielectricBsdf>(eta, ggx, tints);
    return arena.make<CompensatedGgxDielectricBsdf>(eta, ggx, tints);
}

}  // namespace fluence::render
