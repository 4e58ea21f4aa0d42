// A rough metal that keeps the light its microfacets reflect more than once: single-scattering
// GGX (render/bsdfs/ggx_conductor.h) plus the multiple-scattering lobe of Kulla & Conty 2017
// ("Revisiting Physically Based Shading at Imageworks", section "Energy compensation"):
//
//   f = f_ss(wo, wi) + Fms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - Eavg))
//   E, Eavg: the bare (F = 1) microfacet albedo and its cosine-weighted average
//            (render/bsdfs/ggx_albedo.h; over the view azimuth when anisotropic,
//            render/bsdfs/ggx_anisotropic_albedo.h)
//   Fms  = Favg^2 Eavg / (1 - Favg (1 - Eavg)),   Favg = (20 F0 + 1) / 21 (Schlick's average)
//
// Fms sums the light that bounces k = 2, 3, ... times, each bounce losing 1 - Favg; for F0 = 1
// it is 1 and the metal's flux albedo is E(mu_o) + (1 - E(mu_o)) = 1 at every angle and width
// (tests/render/bsdf_energy_test.cpp). Chosen over Turquin et al. 2019's factor
// 1 + F0 (1 - E(mu_o)) / E(mu_o) on f_ss, which conserves energy as well but depends on wo
// alone: the lobe here is symmetric in wo and wi, so the metal stays reciprocal, which
// bidirectional transport and the property tests (tests/render/bsdf_properties_test.cpp) require.
// The lobe is the diffuse base of a LayeredBsdf (render/bsdfs/layered.h: a Lambertian of albedo
// Fms, weighted by 1 - E both ways and normalised by 1 - Eavg), sampled cosine-weighted with
// probability 1 - E(mu_o); it is light the microfacets reflect, so it is reported as glossy
// (flags and fByKind: a light path expression counts it as RG, not RD). A smooth metal (alpha below
// kGgxSmoothAlpha) scatters once and is returned as the single-scattering mirror.
#pragma once

#include "render/bsdf_arena.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/layered.h"

namespace fluence::render {

using CompensatedGgxConductorBsdf = LayeredBsdf<GgxConductorBsdf>;

// Fms of the metal of normal-incidence reflectance f0 whose bare albedo averages eAvg.
inline RGB multipleScatteringAlbedo(const RGB& f0, float eAvg) {
    const RGB fAvg = (f0 * 20.0f + RGB(1.0f)) * (1.0f / 21.0f);
    return fAvg * fAvg * eAvg / (RGB(1.0f) - fAvg * (1.0f - eAvg));
}

inline const Bsdf& energyCompensatedConductor(const RGB& f0, const GgxDistribution& ggx, BsdfArena& arena) {
    const GgxConductorBsdf single(f0, ggx);
    if (ggx.isSmooth()) return arena.make<GgxConductorBsdf>(single);
    const float eAvg = single.averageReflectance().x;
    const RGB fMs = multipleScatteringAlbedo(f0, eAvg);
    return arena.make<CompensatedGgxConductorBsdf>(single, arena.make<LambertianBsdf>(fMs, kBsdfGlossy), RGB(1.0f),
                                                   DiffuseBase{});
}

}  // namespace fluence::render
