#include "render/bsdfs/coated.h"

#include <algorithm>
#include <stdexcept>

#include "render/bsdfs/fresnel.h"

namespace fluence::render {

CoatedBsdf::CoatedBsdf(const Bsdf& base, float eta, float alpha) : base_(&base), eta_(eta), distribution_(alpha) {
    if (base.flags() & kBsdfTransmission) throw std::invalid_argument("CoatedBsdf: the base must not transmit");
}

float CoatedBsdf::coatFresnel(float cosTheta) const { return fresnelDielectric(cosTheta, eta_); }

RGB CoatedBsdf::fUpper(const Vec3f& wo, const Vec3f& wi) const {
    RGB f = base_->f(wo, wi) * ((1.0f - coatFresnel(wo.z)) * (1.0f - coatFresnel(wi.z)));
    if (distribution_.isSmooth()) return f;
    Vec3f h = normalize(wo + wi);
    return f + RGB(coatFresnel(dot(wo, h)) * distribution_.reflectionTerm(wo, wi, h));
}

float CoatedBsdf::pdfUpper(const Vec3f& wo, const Vec3f& wi) const {
    float pCoat = coatFresnel(wo.z);
    float p = (1.0f - pCoat) * base_->pdf(wo, wi);
    if (distribution_.isSmooth()) return p;
    return p + pCoat * distribution_.reflectionPdf(wo, normalize(wo + wi));
}

std::optional<BsdfSample> CoatedBsdf::sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const {
    float pCoat = coatFresnel(wo.z);
    if (uLobe < pCoat) {
        if (distribution_.isSmooth()) {
            Vec3f wi = mirrorZ(-wo);
            return BsdfSample{RGB(pCoat / wi.z), wi, pCoat, true};
        }
        Vec3f wi = reflect(wo, distribution_.sampleVisibleNormal(wo, u));
        if (wi.z <= 0.0f) return std::nullopt;
        float p = pdfUpper(wo, wi);
        if (!(p > 0.0f)) return std::nullopt;
        return BsdfSample{fUpper(wo, wi), wi, p};
    }
    // Reuse uLobe for the base's own lobe choice: uniform again in [0, 1) once rescaled.
    float uBase = std::min((uLobe - pCoat) / (1.0f - pCoat), 0x1.fffffep-1f);
    std::optional<BsdfSample> s = base_->sample(wo, uBase, u);
    if (!s) return std::nullopt;
    if (s->specular) {
        s->f *= (1.0f - pCoat) * (1.0f - coatFresnel(s->wi.z));
        s->pdf *= 1.0f - pCoat;
        return s;
    }
    float p = pdfUpper(wo, s->wi);
    if (!(p > 0.0f)) return std::nullopt;
    return BsdfSample{fUpper(wo, s->wi), s->wi, p};
}

}  // namespace fluence::render
