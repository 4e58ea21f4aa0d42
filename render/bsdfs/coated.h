// CoatedBsdf: a dielectric layer over a base: a clear coat (varnish, car paint, a coated metal,
// coated glass) or the specular layer of a plastic, as the dielectric's reflection laid over the
// base by albedo scaling (render/bsdfs/layered.h).
//
//   f(wo, wi) = f_coat(wo, wi) + a(wo) a(wi) f_base(wo, wi)
//   f_coat    = tint F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i)   (GGX, rough), or
//               a delta mirror of reflectance tint F(cos theta_o)                (smooth)
//   a(w)      = (1 - tint E(cos theta_w)) sqrt(filter) on the coated side (+z), 1 on the other
//   F         = exact dielectric Fresnel of the coat's index eta (render/bsdfs/fresnel.h)
//   E         = the coat lobe's directional albedo (F-weighted GGX, render/bsdfs/ggx_albedo.h;
//               F(cos theta) itself, to the table's resolution, for a smooth coat)
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
// | diffuse   | optional: the base is diffuse; the coat then conserves energy exactly          |
// |           | (render/bsdfs/layered.h, ENERGY-PRESERVING LAYERING)                           |
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
// Energy: over a diffuse base (plastic, a coat over diffuse or over subsurface) the base's
// reflection is divided by 1 - tint Eavg, which returns the light the coat's underside would
// send back after bounces between base and coat: a white base under any coat, smooth or rough,
// reflects exactly 1 at every angle (tests/render/bsdf_energy_test.cpp), where the plain albedo
// scaling reflected F(1) + (1 - F(1)) 0.908 = 0.912 at normal incidence (eta 1.5). Over another
// base the albedo is at most E_coat(wo) + (1 - tint E(wo)) E_base <= 1, and the light the
// coat's underside returns is dropped here (materials return it over a plastic, a sheen, a
// metal, subsurface under a specular layer or solid glass: render/bsdfs/coat_return.h). The coat's own multiple scattering between microfacets
// is not added to its lobe: over a diffuse base that energy reaches the base and comes back out
// diffusely instead; over a metal or glass it is lost.
//
// Sampling (render/bsdfs/layered.h): the coat with probability lobeProbability(tint E(cos theta_o)),
// else the base; a non-delta sample returns the whole f and the
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
               const RGB& filter = RGB(1.0f), const std::optional<DiffuseBase>& diffuse = std::nullopt)
        : LayeredBsdf(DielectricReflectionBsdf(DielectricFresnel(eta, tint), ggx), base, filter, diffuse) {}
};

}  // namespace fluence::render
