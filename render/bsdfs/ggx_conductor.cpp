#include "render/bsdfs/ggx_conductor.h"

#include "render/bsdfs/fresnel.h"

namespace fluence::render {

RGB GgxConductorBsdf::fUpper(const Vec3f& wo, const Vec3f& wi) const {
    if (distribution_.isSmooth()) return RGB(0.0f);
    Vec3f h = normalize(wo + wi);
    return fresnelSchlick(f0_, dot(wo, h)) * distribution_.reflectionTerm(wo, wi, h);
}

float GgxConductorBsdf::pdfUpper(const Vec3f& wo, const Vec3f& wi) const {
    if (distribution_.isSmooth()) return 0.0f;
    return distribution_.reflectionPdf(wo, normalize(wo + wi));
}

std::optional<BsdfSample> GgxConductorBsdf::sampleUpper(const Vec3f& wo, float, Vec2f u) const {
    if (distribution_.isSmooth()) {
        Vec3f wi = mirrorZ(-wo);
        return BsdfSample{fresnelSchlick(f0_, wo.z) / wi.z, wi, 1.0f, true};
    }
    Vec3f h = distribution_.sampleVisibleNormal(wo, u);
    Vec3f wi = reflect(wo, h);
    if (wi.z <= 0.0f) return std::nullopt;
    float p = distribution_.reflectionPdf(wo, h);
    if (!(p > 0.0f)) return std::nullopt;
    return BsdfSample{fresnelSchlick(f0_, dot(wo, h)) * distribution_.reflectionTerm(wo, wi, h), wi, p};
}

}  // namespace fluence::render
