// The directional albedo of a single-scattering rough dielectric interface (GgxDielectricBsdf,
// untinted), reflection and transmission together, tabulated: what the multiple-scattering
// compensation of rough glass needs (render/bsdfs/ggx_dielectric_multiple_scattering.h).
//
//   E(mu, alpha, eta) = integral over the sphere of f(wo, wi) (n(wi) / n(wo))^2 |cos theta_i| dwi
//
// the flux wo's light keeps after one scattering off the microfacets (the rest is the light
// that, in a real surface, scatters again between them), for wo on the side where the relative
// index n(other side) / n(wo's side) is eta: eta > 1 entering glass from outside, 1 / eta
// leaving it. Under the visible normals of wo each microfacet h reflects F(wo.h) and refracts
// 1 - F(wo.h) with the weight G2(wo, wi) / G1(wo) (flux), so
//
//   E = mean over visible normals h of  F G2(wo, r) / G1(wo) [r above]
//                                      + (1 - F) G2(wo, t) / G1(wo) [t below, no total reflection]
//
// tabulated as render/bsdfs/albedo_table.h describes, one table per side, by the f0 of the
// interface ((eta - 1) / (eta + 1))^2 (the same for eta and 1 / eta). Eavg is its
// cosine-weighted average. An anisotropic distribution is looked up at sqrt(ax ay).
#pragma once

namespace fluence::render {

float ggxDielectricAlbedo(float cosTheta, float alpha, float eta);
float ggxDielectricAverageAlbedo(float alpha, float eta);

}  // namespace fluence::render
