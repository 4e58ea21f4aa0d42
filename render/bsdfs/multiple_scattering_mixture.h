// MultipleScatteringMixture<Model>: a single-scattering BSDF plus a multiple-scattering lobe that
// leaves cosine-distributed on either side (Kulla & Conty 2017's energy compensation), its
// evaluation and sampling written once for the models that have one: rough glass
// (render/bsdfs/ggx_dielectric_multiple_scattering.h) and the rough thin sheet
// (render/bsdfs/thin_dielectric_multiple_scattering.h).
//
// A model derives from MultipleScatteringMixture<Model> (the curiously recurring template
// pattern) and implements:
//     const Bsdf& single()                            the single-scattering BSDF
//     RGB multipleScattering(wo, wi)                  the lobe's value
//     float multipleScatteringProbability(wo)         in [0, 1]: 1 - E(wo), the light it returns
//     float reflectedShare(wo)                        the probability the lobe leaves on wo's side
//     float multipleScatteringPdf(wo, wi)             that side's share times |wi.z| / pi
//     float crossingEta(wo)                           a sample's eta when it crosses to the other side
//
//   f = f_single + f_ms;   pdf = (1 - P) pdf_single + P pdf_ms,   P = multipleScatteringProbability(wo)
//
// Sampling: the multiple-scattering lobe with probability P (cosine-weighted, on wo's side with
// probability reflectedShare(wo), else on the other), else the single-scattering BSDF's own
// sampling (uLobe rescaled); a non-delta sample returns the whole f and the mixture's pdf, a
// delta sample of the single BSDF its coefficient with its probability times 1 - P. Flags: the
// single BSDF's (the lobe is glossy or diffuse where the single BSDF is rough).
#pragma once

#include <algorithm>
#include <optional>

#include "core/sampling.h"
#include "render/bsdf.h"
#include "render/bsdfs/bsdf_checks.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

// Keeps 1 / (1 - Eavg) finite where a model scatters (almost) everything once.
inline constexpr float kMinMultipleScatteringLoss = 1e-4f;

template <typename Model>
class MultipleScatteringMixture : public Bsdf {
public:
    RGB f(const Vec3f& wo, const Vec3f& wi) const final {
        dcheckDirections(wo, wi);
        if (wo.z == 0.0f || wi.z == 0.0f) return RGB(0.0f);
        return model().single().f(wo, wi) + model().multipleScattering(wo, wi);
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const final {
        dcheckDirections(wo, wi);
        if (wo.z == 0.0f || wi.z == 0.0f) return 0.0f;
        const float pMultiple = model().multipleScatteringProbability(wo);
        return (1.0f - pMultiple) * model().single().pdf(wo, wi) + pMultiple * model().multipleScatteringPdf(wo, wi);
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const final {
        if (wo.z == 0.0f) return std::nullopt;
        const float pMultiple = model().multipleScatteringProbability(wo);
        Vec3f wi;
        if (uLobe < pMultiple) {
            wi = sampleCosineHemisphere(u);
            const bool reflected = uLobe / pMultiple < model().reflectedShare(wo);
            if ((wo.z > 0.0f) != reflected) wi = mirrorZ(wi);  // on the side the lobe leaves by
        } else {
            const float uSingle = std::min((uLobe - pMultiple) / (1.0f - pMultiple), 0x1.fffffep-1f);
            std::optional<BsdfSample> s = model().single().sample(wo, uSingle, u);
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
        const bool crossed = wo.z * wi.z < 0.0f;
        return BsdfSample{f(wo, wi), wi, density, false, crossed ? model().crossingEta(wo) : 1.0f};
    }
    unsigned flags() const final { return model().single().flags(); }

protected:
    ~MultipleScatteringMixture() = default;

private:
    const Model& model() const { return static_cast<const Model&>(*this); }
};

}  // namespace fluence::render
