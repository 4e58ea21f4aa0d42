#include "render/bsdfs/ggx_dielectric.h"

#include <cmath>

#include "render/bsdfs/bsdf_checks.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

std::optional<GgxDielectricBsdf::Configuration> GgxDielectricBsdf::configuration(const Vec3f& wo,
                                                                                 const Vec3f& wi) const {
    if (wo.z == 0.0f || wi.z == 0.0f || isSmooth()) return std::nullopt;
    Configuration c;
    c.eta = relativeEta(wo);
    c.wo = wo.z > 0.0f ? wo : mirrorZ(wo);
    c.wi = wo.z > 0.0f ? wi : mirrorZ(wi);
    c.reflected = c.wi.z > 0.0f;
    Vec3f h = c.reflected ? c.wo + c.wi : c.wo + c.wi * c.eta;
    if (lengthSquared(h) == 0.0f) return std::nullopt;
    c.h = normalize(h);
    if (c.h.z < 0.0f) c.h = -c.h;
    // The microfacet must face wo, and face wi from the same side (reflection) or the other
    // side (refraction).
    float cosO = dot(c.wo, c.h), cosI = dot(c.wi, c.h);
    if (cosO <= 0.0f || (c.reflected ? cosI <= 0.0f : cosI >= 0.0f)) return std::nullopt;
    c.fresnel = fresnelDielectric(cosO, c.eta);
    return c;
}

RGB GgxDielectricBsdf::value(const Configuration& c) const {
    if (c.reflected) return tints_.reflected(c.fresnel) * distribution_.reflectionTerm(c.wo, c.wi, c.h);
    float cosO = dot(c.wo, c.h), cosI = dot(c.wi, c.h);
    float denom = cosO + c.eta * cosI;
    return tints_.transmitted(c.fresnel) * (distribution_.D(c.h) * distribution_.G2(c.wo, c.wi) * std::abs(cosI) *
                                            cosO / (c.wo.z * std::abs(c.wi.z) * denom * denom));
}

float GgxDielectricBsdf::density(const Configuration& c) const {
    float pReflect = tints_.reflectProbability(c.fresnel);
    if (c.reflected) return pReflect * distribution_.reflectionPdf(c.wo, c.h);
    // dh/dwi for refraction: eta'^2 |wi.h| / (wo.h + eta' wi.h)^2 (Walter et al. 2007, eq. 17).
    float cosI = dot(c.wi, c.h);
    float denom = dot(c.wo, c.h) + c.eta * cosI;
    return (1.0f - pReflect) * distribution_.visibleNormalPdf(c.wo, c.h) * c.eta * c.eta * std::abs(cosI) /
           (denom * denom);
}

RGB GgxDielectricBsdf::f(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    std::optional<Configuration> c = configuration(wo, wi);
    return c ? value(*c) : RGB(0.0f);
}

float GgxDielectricBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
    dcheckDirections(wo, wi);
    std::optional<Configuration> c = configuration(wo, wi);
    return c ? density(*c) : 0.0f;
}

std::optional<BsdfSample> GgxDielectricBsdf::sampleSmooth(const Vec3f& wo, float uLobe) const {
    float eta = relativeEta(wo);
    float cosO = std::abs(wo.z);
    float F = fresnelDielectric(cosO, eta);
    float pReflect = tints_.reflectProbability(F);
    if (uLobe < pReflect) {
        Vec3f wi = mirrorZ(-wo);
        return BsdfSample{tints_.reflected(F) / cosO, wi, pReflect, true};
    }
    // Total internal reflection (F = 1) leaves nothing to refract: the share a reflection tint
    // withheld is lost (render/bsdfs/dielectric_tints.h).
    Vec3f n(0.0f, 0.0f, wo.z > 0.0f ? 1.0f : -1.0f);
    std::optional<Vec3f> wi = refract(wo, n, eta);
    if (!wi) return std::nullopt;
    return BsdfSample{tints_.transmitted(F) / (eta * eta * std::abs(wi->z)), *wi, 1.0f - pReflect, true, eta};
}

std::optional<BsdfSample> GgxDielectricBsdf::sample(const Vec3f& wo, float uLobe, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    if (isSmooth()) {
        std::optional<BsdfSample> s = sampleSmooth(wo, uLobe);
        dcheckSample(wo, s);
        return s;
    }
    Configuration c;
    c.eta = relativeEta(wo);
    c.wo = wo.z > 0.0f ? wo : mirrorZ(wo);
    c.h = distribution_.sampleVisibleNormal(c.wo, u);
    float cosO = dot(c.wo, c.h);
    if (cosO <= 0.0f) return std::nullopt;
    c.fresnel = fresnelDielectric(cosO, c.eta);
    c.reflected = uLobe < tints_.reflectProbability(c.fresnel);
    if (c.reflected) {
        c.wi = reflect(c.wo, c.h);
        if (c.wi.z <= 0.0f) return std::nullopt;
    } else {
        std::optional<Vec3f> t = refract(c.wo, c.h, c.eta);
        if (!t || t->z >= 0.0f) return std::nullopt;
        c.wi = *t;
    }
    float p = density(c);
    if (!(p > 0.0f)) return std::nullopt;
    Vec3f wi = wo.z > 0.0f ? c.wi : mirrorZ(c.wi);
    std::optional<BsdfSample> s = BsdfSample{value(c), wi, p, false, c.reflected ? 1.0f : c.eta};
    dcheckSample(wo, s);
    return s;
}

}  // namespace fluence::render
