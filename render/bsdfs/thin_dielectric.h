// ThinDielectricBsdf: a thin dielectric sheet (a window pane, a soap film, a leaf or a sheet of
// paper's clear part; Standard Surface's thin_walled): it reflects, and lets light through
// straight, without bending it, because the ray leaves by a face parallel to the one it entered.
//
// Each microfacet (or the smooth sheet) is a slab with parallel faces of index eta between equal
// media. Summing the incoherent inter-reflections inside it (Stokes' relations), a slab whose
// faces reflect F = Fresnel(cos theta, eta) reflects R_s = F + (1 - F)^2 F / (1 - F^2) = 2F / (1 + F)
// and transmits 1 - R_s = (1 - F) / (1 + F). With the tints of render/bsdfs/dielectric_tints.h
// applied to that split (reflected R(R_s), transmitted T(R_s)):
//   rough reflection: f = R(R_s(wo.h)) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i)  (GGX)
//   smooth reflection: a delta mirror of reflectance R(R_s(cos theta_o))
//   transmission:     a delta along -wo (straight through), rough or smooth
//
// | parameter | meaning                                                                   |
// |-----------|---------------------------------------------------------------------------|
// | eta       | the sheet's index relative to the medium on both sides; > 0               |
// | ggx       | GGX widths of the sheet's faces (x along the tangent)                      |
// | tints     | reflection tint (specular weight x colour), transmission tint (the        |
// |           | sheet's transmission_color, applied once: the sheet is crossed once)       |
//
// Rough sheets: the faces are rough but locally parallel, so roughness blurs the reflection only;
// the transmitted light keeps its direction (a frosted sheet's blurred transmission would need
// the two faces to be rough independently, which this model does not attempt). Sampling: h from
// the visible normals of wo (Heitz 2018), then reflection with probability P = R's
// reflectProbability(R_s(wo.h)), else transmission. The transmitted delta's coefficient is then
// T(R_s(wo.h)) / |cos theta_o| with pdf 1 - P: a one-sample estimate, over h, of the delta lobe's
// weight (its expectation is the transmitted share of the light hitting visible microfacets),
// which is all an integrator does with a delta sample. pdf(wo, wi) of the reflection is
// P(h) D_wo(h) / (4 wo.h). Energy: reflected + transmitted <= 1 for every microfacet, so the albedo
// is at most 1, exactly 1 when smooth and untinted; rough, what the microfacets reflect into
// one another is lost here, and returned by render/bsdfs/thin_dielectric_multiple_scattering.h
// (which materials use).
//
// Symmetric: both sides of the sheet are alike, so the model is written for wo.z > 0 and mirrored
// by TwoSidedReflection (render/bsdfs/two_sided.h): its non-delta part only reflects, and the
// straight-through delta mirrors to -wo. Transmitted samples have eta = 1 (the same medium on
// both sides). Reciprocal. Flags: reflection, transmission, specular (the transmission, and the
// reflection when smooth), glossy when rough. Path-class label: S for the deltas, D for the rough
// reflection.
#pragma once

#include <optional>

#include "render/bsdfs/dielectric_tints.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

// R_s: the reflectance of a slab of index eta lit at cosTheta, 2F / (1 + F) (Stokes' sum).
inline float slabReflectance(float cosTheta, float eta) {
    const float F = fresnelDielectric(cosTheta, eta);
    return 2.0f * F / (1.0f + F);
}

class ThinDielectricBsdf final : public TwoSidedReflection<ThinDielectricBsdf> {
public:
    ThinDielectricBsdf(float eta, const GgxDistribution& ggx, const DielectricTints& tints = {})
        : eta_(eta), distribution_(ggx), tints_(tints) {}

    unsigned flags() const override {
        return kBsdfReflection | kBsdfTransmission | kBsdfSpecular | (distribution_.isSmooth() ? 0u : kBsdfGlossy);
    }

private:
    friend class TwoSidedReflection<ThinDielectricBsdf>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const;
    float pdfUpper(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const;

    float eta_;
    GgxDistribution distribution_;
    DielectricTints tints_;
};

}  // namespace fluence::render
