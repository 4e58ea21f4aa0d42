#include "render/bsdfs/ggx_dielectric_multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/bsdf_checks.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/ggx_dielectric_albedo.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

// Keeps 1 / (1 - A) finite where a side scatters (almost) everything once.
constexpr float kMinLoss = 1e-4f;

}  // namespace

CompensatedGgxDielectricBsdf::CompensatedGgxDielectricBsdf(float eta, const GgxDistribution& ggx,
                                                           const DielectricTints& tints)
    : single_(eta, ggx, tints), eta_(eta), alpha_(std::sqrt(ggx.alphaX() * ggx.alphaY())), tints_(tints) {
    outside_.average = ggxDielectricAverageAlbedo(alpha_, eta_);
    inside_.average = ggxDielectricAverageAlbedo(alpha_, 1.0f / eta_);
    const float lossOut = std::max(1.0f - outside_.average, kMinLoss),
                lossIn = std::max(1.0f - inside_.average, kMinLoss);
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
    return outside_.reflected / std::max(1.0f - outside_.average, kMinLoss);
}

float CompensatedGgxDielectricBsdf::albedo(const Vec3f& w) const {
    return ggxDielectricAlbedo(std::abs(w.z), alpha_, w.z > 0.0f ? eta_ : 1.0f / eta_);
}

RGB CompensatedGgxDielectricBsdf::multipleScattering(const Vec3f& wo, const Vec3f& wi) const {
    const Side& from = sideOf(wo);
    const float lossO = 1.0f - albedo(wo), lossI = 1.0f - albedo(wi);
    if (wo.z * wi.z > 0.0f)
        return tints_.reflection * (from.reflected * lossO * lossI * kInvPi / std::max(1.0f - from.average, kMinLoss));
    return tints_.transmission * (from.crossing * lossO * lossI * kInvPi);
}

float CompensatedGgxDielectricBsdf::multipleScatteringPdf(const Vec3f& wo, const Vec3f& wi) const {
    const Side& from = sideOf(wo);
    return (wo.z * wi.z > 0.0f ? from.reflected : from.transmitted) * std::abs(wi.z) * kInvPi;
}

RGB CompensatedGgxDielectricBsdf::f(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    if (wo.z == 0.0f || wi.z == 0.0f) return RGB(0.0f);
    return single_.f(wo, wi) + multipleScattering(wo, wi);
}

float CompensatedGgxDielectricBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
    const float pMultiple = std::clamp(1.0f - albedo(wo), 0.0f, 1.0f);
    return (1.0f - pMultiple) * single_.pdf(wo, wi) + pMultiple * multipleScatteringPdf(wo, wi);
}

std::optional<BsdfSample> CompensatedGgxDielectricBsdf::sample(const Vec3f& wo, float uLobe, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float pMultiple = std::clamp(1.0f - albedo(wo), 0.0f, 1.0f);
    Vec3f wi;
    if (uLobe < pMultiple) {
        const Side& from = sideOf(wo);
        const float uSide = uLobe / pMultiple;
        wi = sampleCosineHemisphere(u);
        const bool reflected = uSide < from.reflected;
        if ((wo.z > 0.0f) != reflected) wi = mirrorZ(wi);  // on the side the lobe leaves by
    } else {
        const float uSingle = std::min((uLobe - pMultiple) / (1.0f - pMultiple), 0x1.fffffep-1f);
        const std::optional<BsdfSample> s = single_.sample(wo, uSingle, u);
        if (!s) return std::nullopt;
        wi = s->wi;
    }
    if (wi.z == 0.0f) return std::nullopt;
    const float density = pdf(wo, wi);
    if (!(density > 0.0f)) return std::nullopt;
    const bool crossed = wo.z * wi.z < 0.0f;
    return BsdfSample{f(wo, wi), wi, density, false, crossed ? (wo.z > 0.0f ? eta_ : 1.0f / eta_) : 1.0f};
}

const Bsdf& energyCompensatedDielectric(float eta, const GgxDistribution& ggx, const DielectricTints& tints,
                                        BsdfArena& arena) {
    if (ggx.isSmooth() || eta == 1.0f) return arena.make<GgxDielectricBsdf>(eta, ggx, tints);
    return arena.make<CompensatedGgxDielectricBsdf>(eta, ggx, tints);
}

}  // namespace fluence::render
