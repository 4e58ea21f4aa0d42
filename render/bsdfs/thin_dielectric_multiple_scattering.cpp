#include "render/bsdfs/thin_dielectric_multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/bsdf_checks.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/lobe_choice.h"
#include "render/bsdfs/local_geometry.h"
#include "render/bsdfs/thin_dielectric_albedo.h"

namespace fluence::render {

namespace {

// Keeps 1 / (1 - Eavg) finite where the sheet scatters (almost) everything once.
constexpr float kMinLoss = 1e-4f;

}  // namespace

CompensatedThinDielectricBsdf::CompensatedThinDielectricBsdf(float eta, const GgxDistribution& ggx,
                                                             const DielectricTints& tints)
    : single_(eta, ggx, tints), eta_(eta), alpha_(std::sqrt(ggx.alphaX() * ggx.alphaY())) {
    const float fAvg = ggxReflectionAverageAlbedo(0.0f, f0FromEta(eta_));
    const float k = 2.0f * fAvg / (1.0f + fAvg);
    const float scale = kInvPi / std::max(1.0f - thinSheetAverageAlbedo(alpha_, eta_), kMinLoss);
    reflected_ = tints.reflected(k) * scale;
    transmitted_ = tints.transmitted(k) * scale;
    const float r = lobeProbability(tints.reflected(k)), t = lobeProbability(tints.transmitted(k));
    pReflected_ = r + t > 0.0f ? r / (r + t) : 1.0f;
}

float CompensatedThinDielectricBsdf::loss(const Vec3f& w) const {
    return std::clamp(1.0f - thinSheetAlbedo(std::abs(w.z), alpha_, eta_), 0.0f, 1.0f);
}

RGB CompensatedThinDielectricBsdf::multipleScattering(const Vec3f& wo, const Vec3f& wi) const {
    return (wo.z * wi.z > 0.0f ? reflected_ : transmitted_) * (loss(wo) * loss(wi));
}

float CompensatedThinDielectricBsdf::multipleScatteringPdf(const Vec3f& wo, const Vec3f& wi) const {
    return (wo.z * wi.z > 0.0f ? pReflected_ : 1.0f - pReflected_) * std::abs(wi.z) * kInvPi;
}

RGB CompensatedThinDielectricBsdf::f(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    if (wo.z == 0.0f || wi.z == 0.0f) return RGB(0.0f);
    return single_.f(wo, wi) + multipleScattering(wo, wi);
}

float CompensatedThinDielectricBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
    const float pMultiple = loss(wo);
    return (1.0f - pMultiple) * single_.pdf(wo, wi) + pMultiple * multipleScatteringPdf(wo, wi);
}

std::optional<BsdfSample> CompensatedThinDielectricBsdf::sample(const Vec3f& wo, float uLobe, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float pMultiple = loss(wo);
    Vec3f wi;
    if (uLobe < pMultiple) {
        wi = sampleCosineHemisphere(u);
        const bool reflected = uLobe / pMultiple < pReflected_;
        if ((wo.z > 0.0f) != reflected) wi = mirrorZ(wi);  // on the side the lobe leaves by
    } else {
        const float uSingle = std::min((uLobe - pMultiple) / (1.0f - pMultiple), 0x1.fffffep-1f);
        std::optional<BsdfSample> s = single_.sample(wo, uSingle, u);
        if (!s) return std::nullopt;
        if (s->specular) {
            s->pdf *= 1.0f - pMultiple;
            return s;
        }
        wi = s->wi;
    }
    if (wi.z == 0.0f) return std::nullopt;
    const float density = pdf(wo, wi);
    if (!(density > 0.0f)) return std::nullopt;
    return BsdfSample{f(wo, wi), wi, density};
}

const Bsdf& energyCompensatedThinDielectric(float eta, const GgxDistribution& ggx, const DielectricTints& tints,
                                            BsdfArena& arena) {
    if (ggx.isSmooth() || eta == 1.0f) return arena.make<ThinDielectricBsdf>(eta, ggx, tints);
    return arena.make<CompensatedThinDielectricBsdf>(eta, ggx, tints);
}

}  // namespace fluence::render
