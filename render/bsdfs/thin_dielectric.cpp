#include "render/bsdfs/thin_dielectric.h"

namespace fluence::render {

RGB ThinDielectricBsdf::fUpper(const Vec3f& wo, const Vec3f& wi) const {
    if (distribution_.isSmooth()) return RGB(0.0f);
    Vec3f h = normalize(wo + wi);
    return tints_.reflected(slabReflectance(dot(wo, h), eta_)) * distribution_.reflectionTerm(wo, wi, h);
}

float ThinDielectricBsdf::pdfUpper(const Vec3f& wo, const Vec3f& wi) const {
    if (distribution_.isSmooth()) return 0.0f;
    Vec3f h = normalize(wo + wi);
    return tints_.reflectProbability(slabReflectance(dot(wo, h), eta_)) * distribution_.reflectionPdf(wo, h);
}

std::optional<BsdfSample> ThinDielectricBsdf::sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const {
    const bool smooth = distribution_.isSmooth();
    const Vec3f h = smooth ? Vec3f(0.0f, 0.0f, 1.0f) : distribution_.sampleVisibleNormal(wo, u);
    const float cosO = dot(wo, h);
    if (cosO <= 0.0f) return std::nullopt;
    const float slab = slabReflectance(cosO, eta_);
    const float pReflect = tints_.reflectProbability(slab);
    if (uLobe >= pReflect)  // straight through
        return BsdfSample{tints_.transmitted(slab) / wo.z, -wo, 1.0f - pReflect, true, 1.0f};
    if (smooth) return BsdfSample{tints_.reflected(slab) / wo.z, mirrorZ(-wo), pReflect, true};
    Vec3f wi = reflect(wo, h);
    if (wi.z <= 0.0f) return std::nullopt;
    float p = pdfUpper(wo, wi);
    if (!(p > 0.0f)) return std::nullopt;
    return BsdfSample{fUpper(wo, wi), wi, p};
}

}  // namespace fluence::render
