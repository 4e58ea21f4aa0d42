// The directional albedo of a single-scattering rough thin sheet (ThinDielectricBsdf, untinted),
// its reflection and its straight-through transmission together, and the straight-through share
// alone, tabulated: what the sheet's multiple-scattering compensation
// (render/bsdfs/thin_dielectric_multiple_scattering.h) and a coat over the sheet
// (render/bsdfs/coat_return.h) need.
//
//   E(mu, alpha, eta) = mean over the visible normals h of wo of
//                       R_s(wo.h) G2(wo, r) / G1(wo) [r = reflect(wo, h) above] + 1 - R_s(wo.h)
//   S(mu, alpha, eta) = mean over the visible normals h of wo of 1 - R_s(wo.h)
//   R_s(c) = 2 F(c) / (1 + F(c)), the reflectance of a slab whose faces reflect F (Fresnel, eta)
//
// The transmitted share 1 - R_s crosses the sheet straight, so none of it is masked; what the
// sheet loses is the light its microfacets reflect into other microfacets (G2 / G1 < 1). E - S
// is what the sheet reflects. The tables are those of render/bsdfs/albedo_table.h, by the f0 of
// the sheet's faces ((eta - 1) / (eta + 1))^2 (the same for eta and 1 / eta), a slice built on
// first use. Eavg is E's cosine-weighted average. An anisotropic distribution is looked up at
// sqrt(ax ay).
#pragma once

namespace fluence::render {

class GgxDistribution;

float thinSheetAlbedo(float cosTheta, float alpha, float eta);
float thinSheetAverageAlbedo(float alpha, float eta);
// S: the share of the light from cosTheta that crosses the sheet straight.
float thinSheetStraightThrough(float cosTheta, float alpha, float eta);
// E at one direction of cosine mu for the distribution ggx, by the table's quadrature: what the
// table's nodes hold.
float thinSheetQuadrature(const GgxDistribution& ggx, float mu, float eta);

}  // namespace fluence::render
