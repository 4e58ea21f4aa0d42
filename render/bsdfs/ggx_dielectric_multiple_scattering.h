// Rough glass that keeps the light its microfacets scatter more than once: single-scattering
// GGX refraction and reflection (render/bsdfs/ggx_dielectric.h) plus a multiple-scattering lobe
// on each side, the dielectric form of Kulla & Conty 2017 ("Revisiting Physically Based Shading
// at Imageworks", section "Energy compensation", dielectrics).
//
// With n = IOR inside / outside, E_out, E_in the single-scattering flux albedos seen from each
// side and A_out, A_in their cosine-weighted averages (render/bsdfs/ggx_dielectric_albedo.h, at
// the width sqrt(ax ay)), the lobe adds, for wo on side s and wi on side s':
//
//   same side:      r_s (1 - E_s(wo)) (1 - E_s(wi)) / (pi (1 - A_s))   x reflection tint
//   outside->in:    c     (1 - E_out(wo)) (1 - E_in(wi)) / pi           x transmission tint
//   inside->out:    c n^2 (1 - E_in(wo)) (1 - E_out(wi)) / pi
//
// which keeps the generalised reciprocity f(wo, wi) / n(wo)^2 = f(wi, wo) / n(wi)^2 of
// render/bsdf.h. Integrated with the flux factor (n(wi) / n(wo))^2 it returns at wo the share
// (1 - E_s(wo)) (r_s + t_s) of the light, with t_out = c n^2 (1 - A_in) and t_in = c (1 - A_out)
// the shares that cross. Kulla & Conty's split: from the side of the lower index the light that
// scattered more than once crosses in the proportion a smooth interface lets diffuse light
// through, t = 1 - Favg (Favg: the cosine-weighted average Fresnel reflectance,
// render/bsdfs/ggx_albedo.h at width 0); c follows, and the other side's t from reciprocity
// (c lowered if that side's t would exceed 1). r_s = 1 - t_s, so that untinted, every direction
// keeps E_s(wo) + (1 - E_s(wo)) = 1 of its light, at every width and index (to the tables'
// accuracy; tests/render/bsdf_energy_test.cpp). What it approximates: the returned light leaves
// with a cosine distribution instead of the shape a simulation of the microsurface would give.
//
// Sampling (render/bsdfs/multiple_scattering_mixture.h): the multiple-scattering lobe with
// probability 1 - E_s(wo) (cosine-weighted, on the reflected side with probability r_s, else on
// the other), else the single-scattering BSDF's own sampling; every sample returns the whole f and
// the mixture's pdf. Flags: reflection,
// transmission, glossy. Path-class label: D. A smooth interface (or n = 1) scatters once and is
// returned as the single-scattering BSDF by energyCompensatedDielectric.
#pragma once

#include <algorithm>

#include "render/bsdf_arena.h"
#include "render/bsdfs/ggx_dielectric.h"
#include "render/bsdfs/multiple_scattering_mixture.h"

namespace fluence::render {

class CompensatedGgxDielectricBsdf final : public MultipleScatteringMixture<CompensatedGgxDielectricBsdf> {
public:
    CompensatedGgxDielectricBsdf(float eta, const GgxDistribution& ggx, const DielectricTints& tints = {});

    // The multiple-scattering lobe's reflection seen from outside as K (1 - E_out(wo))
    // (1 - E_out(wi)) / pi: K = r_out / (1 - A_out), untinted.
    float outsideReflectionScale() const;

private:
    friend class MultipleScatteringMixture<CompensatedGgxDielectricBsdf>;

    // One side of the interface: its albedo average, the shares of the multiple-scattering light
    // it reflects and lets through, and the coefficient on the crossing lobe that starts there.
    struct Side {
        float average = 0.0f, reflected = 0.0f, transmitted = 0.0f, crossing = 0.0f;
    };
    const Side& sideOf(const Vec3f& w) const { return w.z > 0.0f ? outside_ : inside_; }
    float albedo(const Vec3f& w) const;  // E on w's side at its angle
    const Bsdf& single() const { return single_; }
    RGB multipleScattering(const Vec3f& wo, const Vec3f& wi) const;
    float multipleScatteringProbability(const Vec3f& wo) const { return std::clamp(1.0f - albedo(wo), 0.0f, 1.0f); }
    float reflectedShare(const Vec3f& wo) const { return sideOf(wo).reflected; }
    float multipleScatteringPdf(const Vec3f& wo, const Vec3f& wi) const;
    float crossingEta(const Vec3f& wo) const { return wo.z > 0.0f ? eta_ : 1.0f / eta_; }

    GgxDielectricBsdf single_;
    float eta_, alpha_;
    DielectricTints tints_;
    Side outside_, inside_;
};

// Rough glass with its multiple scattering; smooth glass (or an index of 1) as is.
const Bsdf& energyCompensatedDielectric(float eta, const GgxDistribution& ggx, const DielectricTints& tints,
                                        BsdfArena& arena);

}  // namespace fluence::render
