#include "render/bsdfs/cook_torrance.h"

#include <algorithm>

#include "render/bsdfs/fresnel.h"

namespace fluence::render {

namespace {
constexpr float kMinSlope = 1e-3f;
}  // namespace

CookTorranceBsdf::CookTorranceBsdf(const RGB& ks, float eta, float m)
    : ks_(ks), eta_(eta), distribution_(std::max(m, kMinSlope)) {}

RGB CookTorranceBsdf::fUpper(const Vec3f& wo, const Vec3f& wi) const {
    Vec3f h = normalize(wo + wi);
    float cosOH = dot(wo, h);  // == wi.h
    float g = std::min({1.0f, 2.0f * h.z * wo.z / cosOH, 2.0f * h.z * wi.z / cosOH});
    float F = fresnelDielectric(cosOH, eta_);
    return ks_ * (F * distribution_.D(h) * g / (4.0f * wo.z * wi.z));
}

float CookTorranceBsdf::pdfUpper(const Vec3f& wo, const Vec3f& wi) const {
    Vec3f h = normalize(wo + wi);
    return distribution_.normalPdf(h) / (4.0f * dot(wo, h));
}

std::optional<BsdfSample> CookTorranceBsdf::sampleUpper(const Vec3f& wo, float, Vec2f u) const {
    Vec3f h = distribution_.sampleNormal(u);
    if (dot(wo, h) <= 0.0f) return std::nullopt;
    Vec3f wi = reflect(wo, h);
    if (wi.z <= 0.0f) return std::nullopt;
    float p = pdfUpper(wo, wi);
    if (p == 0.0f) return std::nullopt;
    return BsdfSample{fUpper(wo, wi), wi, p};
}

}  // namespace fluence::render
