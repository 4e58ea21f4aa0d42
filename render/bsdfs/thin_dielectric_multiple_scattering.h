// A rough thin sheet that keeps the light its microfacets scatter more than once: the single-
// scattering sheet (render/bsdfs/thin_dielectric.h) plus a multiple-scattering lobe on each side,
// Kulla & Conty's energy compensation (2017) with one energy budget for the sheet's reflection
// and transmission.
//
// With E the sheet's single-scattering albedo, reflected and transmitted together
// (render/bsdfs/thin_dielectric_albedo.h, at the width sqrt(ax ay)) and Eavg its cosine-weighted
// average, the lobe adds, for wo and wi on the same side or on opposite sides,
//
//   same side:     R(k) (1 - E(wo)) (1 - E(wi)) / (pi (1 - Eavg))
//   opposite side: T(k) (1 - E(wo)) (1 - E(wi)) / (pi (1 - Eavg))
//   k = 2 Favg / (1 + Favg)
//
// R, T: the tints' split of render/bsdfs/dielectric_tints.h; Favg: the cosine-weighted average
// Fresnel reflectance of the sheet's smooth face (render/bsdfs/ggx_albedo.h at width 0), so that
// k is the share of diffuse light a smooth slab reflects (Stokes' sum, as for R_s). The light
// that meets a second microfacet leaves by either side of the sheet in that proportion. Untinted,
// R(k) + T(k) = 1, and every direction keeps E(wo) + (1 - E(wo)) = 1 of its light, at every width
// and index (to the table's accuracy; tests/render/bsdf_energy_test.cpp). The lobe is symmetric
// in wo and wi and the same on both sides, so the sheet stays reciprocal with alike sides. What
// it approximates: the returned light leaves with a cosine distribution, not the shape a
// simulation of the microsurface would give, and the transmitted part of it is diffuse, not
// straight through.
//
// Sampling (render/bsdfs/multiple_scattering_mixture.h): the multiple-scattering lobe with
// probability 1 - E(wo) (cosine-weighted, on wo's
// side with probability lobeProbability(R(k)) / (lobeProbability(R(k)) + lobeProbability(T(k))),
// else on the other), else the single-scattering sheet's own sampling; a non-delta sample returns
// the whole f and the mixture's pdf, the straight-through delta keeps its coefficient with its
// probability times 1 - (1 - E(wo)). Flags: the sheet's (reflection, transmission, specular,
// glossy). Path-class label: S for the delta, D for the rest. A smooth sheet (or eta = 1)
// scatters once and is returned as the single-scattering sheet by energyCompensatedThinDielectric.
#pragma once

#include "render/bsdf_arena.h"
#include "render/bsdfs/multiple_scattering_mixture.h"
#include "render/bsdfs/thin_dielectric.h"

namespace fluence::render {

// The multiple-scattering lobe's weights, per unit of (1 - E(wo)) (1 - E(wi)) / pi: R(k) and
// T(k), each divided by 1 - Eavg (its albedo at wo is then R(k) (1 - E(wo)), or T(k) (1 - E(wo))).
struct ThinSheetMultipleScattering {
    RGB reflected, transmitted;
};
ThinSheetMultipleScattering thinSheetMultipleScattering(float eta, float alpha, const DielectricTints& tints);

class CompensatedThinDielectricBsdf final : public MultipleScatteringMixture<CompensatedThinDielectricBsdf> {
public:
    CompensatedThinDielectricBsdf(float eta, const GgxDistribution& ggx, const DielectricTints& tints = {});

private:
    friend class MultipleScatteringMixture<CompensatedThinDielectricBsdf>;

    const Bsdf& single() const { return single_; }
    RGB multipleScattering(const Vec3f& wo, const Vec3f& wi) const;
    float multipleScatteringProbability(const Vec3f& wo) const;  // 1 - E at wo's angle, either side
    float reflectedShare(const Vec3f&) const { return pReflected_; }
    float multipleScatteringPdf(const Vec3f& wo, const Vec3f& wi) const;
    float crossingEta(const Vec3f&) const { return 1.0f; }  // the same medium on both sides

    ThinDielectricBsdf single_;
    float eta_, alpha_;
    RGB reflected_, transmitted_;  // R(k) and T(k) / (pi (1 - Eavg))
    float pReflected_;             // the probability of the multiple-scattering lobe's wo side
};

// A rough sheet with its multiple scattering; a smooth one (or an index of 1) as is.
const Bsdf& energyCompensatedThinDielectric(float eta, const GgxDistribution& ggx, const DielectricTints& tints,
                                            BsdfArena& arena);

}  // namespace fluence::render
