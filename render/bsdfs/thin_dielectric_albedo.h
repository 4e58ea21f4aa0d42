// The directional albedo of a single-scattering rough thin sheet (ThinDielectricBsdf, untinted),
// its reflection and its straight-through transmission together, tabulated: what the sheet's
// multiple-scattering compensation needs (render/bsdfs/thin_dielectric_multiple_scattering.h).
//
//   E(mu, alpha, eta) = mean over the visible normals h of wo of
//                       R_s(wo.h) G2(wo, r) / G1(wo) [r = reflect(wo, h) above] + 1 - R_s(wo.h)
//   R_s(c) = 2 F(c) / (1 + F(c)), the reflectance of a slab whose faces reflect F (Fresnel, eta)
//
// The transmitted share 1 - R_s crosses the sheet straight, so none of it is masked; what the
// sheet loses is the light its microfacets reflect into other microfacets (G2 / G1 < 1). The
// table is that of render/bsdfs/albedo_table.h, by the f0 of the sheet's faces
// ((eta - 1) / (eta + 1))^2 (the same for eta and 1 / eta), a slice built on first use. Eavg is
// its cosine-weighted average. An anisotropic distribution is looked up at sqrt(ax ay).
#pragma once

namespace fluence::render {

class GgxDistribution;

float thinSheetAlbedo(float cosTheta, float alpha, float eta);
float thinSheetAverageAlbedo(float alpha, float eta);
// E at one direction of cosine mu for the distribution ggx, by the table's quadrature: what the
// table's nodes hold.
float thinSheetQuadrature(const GgxDistribution& ggx, float mu, float eta);

}  // namespace fluence::render
