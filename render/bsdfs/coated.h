// CoatedBsdf: a dielectric layer over a base: a clear coat (varnish, car paint, a coated metal,
// coated glass) or the specular layer of a plastic, as the dielectric's reflection laid over the
// base by albedo scaling (render/bsdfs/layered.h).
//
//   f(wo, wi) = f_coat(wo, wi) + a(wo) a(wi) f_base(wo, wi)
//   f_coat    = tint F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i)   (GGX, rough), or
//               a delta mirror of reflectance tint F(cos theta_o)                (smooth)
//   a(w)      = (1 - tint F(cos theta_w)) sqrt(filter) on the coated side (+z), 1 on the other
//   F         = exact dielectric Fresnel of the coat's index eta (render/bsdfs/fresnel.h)
//
// | parameter | meaning                                                                       |
// |-----------|-------------------------------------------------------------------------------|
// | base      | any Bsdf (Lambertian: plastic; GgxConductor: coated metal; a dielectric: coated|
// |           | glass); it must outlive the CoatedBsdf (both live in the same BsdfArena)       |
// | eta       | the coat's index of refraction relative to the outside (1.5 typical), per     |
// |           | channel in the general form                                                    |
// | alpha/ggx | the coat's GGX widths; below kGgxSmoothAlpha (1e-3) the coat is a mirror        |
// | tint      | per-channel scale of the coat's reflection in [0, 1] (a plastic's specular     |
// |           | weight x colour); the base then loses only what the tinted coat reflects       |
// | filter    | per-channel transmittance of the coat in [0, 1] (Standard Surface coat_color): |
// |           | light returned by the base through the coat is multiplied by it once           |
//
// The seeds' recipe of "ambient + diffuse + specular" (000) made physical: the specular term is
// the dielectric's Fresnel reflection (Torrance-Sparrow with the Fresnel term, 000), and only the
// light the coat transmits, in and out, reaches and leaves the base (in the spirit of
// Weidlich & Wilkie 2007, "Arbitrarily Layered Micro-Facet Surfaces", simplified).
// Assumptions:
//   - the coat is thin (no thickness) and smooth as far as the base is concerned: the
//     transmission factors use the macro-surface Fresnel F(cos theta), the stand-in for the
//     rough coat's albedo; its colour is a filter applied once per in-and-out passage (Standard
//     Surface's convention), not an absorption that grows with path length;
//   - the base is evaluated at the outside directions wo, wi: refraction into the coat, which
//     would narrow a glossy base's lobe and move it, is ignored (exact for a Lambertian base);
//   - light the coat reflects back down onto the base (internal reflection, total beyond the
//     critical angle) is dropped.
// Energy: the albedo is at most E_coat(wo) + (1 - tint F(cos theta_o)) E_base, which is <= 1 for a
// smooth coat and, for a rough coat, as long as its single-scattering albedo does not exceed
// tint F(cos theta_o) by more than the base term loses (tests/render/bsdf_coated_test.cpp checks
// albedo <= 1 for rough coats up to alpha = 0.5). What is LOST, against a full simulation of the
// layer (in which a white base returns, after bounces between base and coat, all the light the
// coat lets in): the light reflected back down by the underside of the coat and its later
// re-emergence; with a Lambertian base only the cosine-weighted average of (1 - F) leaves per
// pass, 0.908 for eta = 1.5, so a white plastic (albedo 1, eta 1.5, smooth) reflects
// F(1) + (1 - F(1)) 0.908 = 0.912 at normal incidence instead of 1. A rough coat further loses
// its own multiple scattering, like every single-scattering microfacet model.
//
// Sampling (render/bsdfs/layered.h): the coat with probability lobeProbability(tint F(cos theta_o))
// (F itself for a clear coat), else the base; a non-delta sample returns the whole f and the
// mixture's pdf. Reciprocal when the base is (generalised reciprocity over a refracting base).
// Two-sided over a reflecting base, one-sided (coated outside) over a transmitting one. Flags:
// the coat's reflection and glossy or specular, and the base's. Path-class label: S for a smooth
// coat's mirror sample, D for the rest.
#pragma once

#include "render/bsdfs/dielectric_reflection.h"
#include "render/bsdfs/layered.h"

namespace fluence::render {

class CoatedBsdf final : public LayeredBsdf<DielectricReflectionBsdf> {
public:
    // A clear, untinted, isotropic coat.
    CoatedBsdf(const Bsdf& base, float eta, float alpha)
        : LayeredBsdf(DielectricReflectionBsdf(RGB(eta), GgxDistribution(alpha)), base) {}
    CoatedBsdf(const Bsdf& base, const RGB& eta, const GgxDistribution& ggx, const RGB& tint = RGB(1.0f),
               const RGB& filter = RGB(1.0f))
        : LayeredBsdf(DielectricReflectionBsdf(DielectricFresnel(eta, tint), ggx), base, filter) {}
};

}  // namespace fluence::render
