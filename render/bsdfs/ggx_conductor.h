// GgxConductorBsdf: a metal, as GGX microfacet reflection with Schlick's Fresnel.
//
//   f = F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),    h = normalize(wo + wi)
//   D, G2: GGX with height-correlated Smith masking-shadowing (render/bsdfs/ggx.h)
//   F: Schlick's approximation from the reflectance at normal incidence F0 (render/bsdfs/fresnel.h)
//
// | parameter | meaning                                                                    |
// |-----------|----------------------------------------------------------------------------|
// | f0        | reflectance at normal incidence, per channel (the metal's "specular colour")|
// | ggx       | GGX widths (x along the tangent; anisotropic for a brushed metal); below    |
// |           | kGgxSmoothAlpha (1e-3) the surface is a perfect mirror                      |
//
// The microfacet model of the seeds' Torrance-Sparrow / Cook-Torrance (000), with the GGX
// distribution (Walter et al. 2007) in place of Beckmann's for its longer highlight tails.
// Fresnel: Schlick's F0 form, chosen over the complex index of refraction because F0 is what
// material descriptions (UsdPreviewSurface's specularColor, metalness workflows) provide; it
// lacks the dip of real metals near grazing angles.
//
// f, sample and pdf are those of GgxReflectionBsdf (render/bsdfs/ggx_reflection.h). Rough:
// sampled by visible normals (Heitz 2018), so f cos / pdf = F G2 / G1(wo) <= 1. Single
// scattering: light that would bounce between microfacets more than once is lost, a deficit that
// grows with alpha (Kulla & Conty 2017); with F0 = 1 the albedo is 1 at alpha -> 0 and below 1
// otherwise (tests/render/bsdf_microfacet_test.cpp and tests/integrators/furnace_test.cpp measure
// it); materials add the lost light back (render/bsdfs/ggx_multiple_scattering.h). Smooth: a
// delta mirror, f = F(cos theta_o) / cos theta_i, chosen with probability 1.
//
// Reciprocal; two-sided. Flags: reflection and glossy (rough) or specular (smooth).
// Path-class label: D (glossy) when rough, S when smooth.
#pragma once

#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_anisotropic_albedo.h"
#include "render/bsdfs/ggx_reflection.h"

namespace fluence::render {

// Schlick's reflectance of a metal of normal-incidence reflectance f0. Its albedo is the bare
// microfacet albedo (F = 1): the share of the light that leaves after one bounce whatever the
// metal, which is what the multiple-scattering lobe takes the rest of
// (render/bsdfs/ggx_multiple_scattering.h).
struct SchlickFresnel {
    SchlickFresnel(const RGB& f0) : f0(f0) {}  // implicit: GgxConductorBsdf(f0, ggx) reads as a metal of F0 f0
    RGB operator()(float cosTheta) const { return fresnelSchlick(f0, cosTheta); }
    RGB albedo(const Vec3f& w, const GgxDistribution& ggx) const { return RGB(ggxBareAlbedo(w, ggx)); }
    RGB averageAlbedo(const GgxDistribution& ggx) const { return RGB(ggxBareAverageAlbedo(ggx)); }
    RGB f0;
};

using GgxConductorBsdf = GgxReflectionBsdf<SchlickFresnel>;

}  // namespace fluence::render
