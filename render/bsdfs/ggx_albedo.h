// The directional albedo of single-scattering GGX reflection, tabulated: what energy-preserving
// layers and the multiple-scattering compensation of rough metals need (Kulla & Conty 2017,
// "Revisiting Physically Based Shading at Imageworks").
//
//   E(mu, alpha, f0) = integral over the hemisphere of F(wo.h) D(h) G2(wo, wi) / (4 mu) dwi,
//                      mu = cos theta_o, h = normalize(wo + wi)
//   Eavg(alpha, f0)  = 2 integral_0^1 E(mu, alpha, f0) mu dmu   (the cosine-weighted average)
//   F: the exact Fresnel reflectance of the dielectric whose normal-incidence reflectance is f0
//      (index etaFromF0(f0), render/bsdfs/fresnel.h); f0 = 1 stands for F = 1, the bare
//      microfacet albedo (the "E(mu)" of Kulla & Conty)
//   D, G2: isotropic GGX with height-correlated Smith masking-shadowing (render/bsdfs/ggx.h)
//
// The table (render/bsdfs/albedo_table.h, shared with the dielectric's) holds 32 values of mu in [0, 1] (mu = 0 as seen at 1e-4) by 32 values of
// sqrt(alpha) (a material's roughness) in [0, 1] by 33 values of sqrt(f0) in [0, 1], all evenly
// spaced, each integrated by a 32 x 32-point quadrature over the visible normals of wo (Heitz
// 2018), its points crowded towards GGX's long tail. A slice of one f0 is computed on first use
// (a material needs the two around its index; metals the slice F = 1), and the table is
// interpolated linearly in each of the three (tests/render/bsdf_energy_test.cpp measures the
// cost and holds the table to an independent Monte Carlo estimate). Eavg is integrated exactly
// from the same piecewise-linear E, so that a lobe weighted by 1 - E(mu) has exactly the
// cosine-weighted average 1 - Eavg: the normalisation of render/bsdfs/layered.h's diffuse bases
// then conserves energy whatever the table's own error against the true albedo.
//
// The table is isotropic. The albedo of a stretched GGX depends on the azimuth of wo as well
// (the bare, F = 1 one is tabulated over it by render/bsdfs/ggx_anisotropic_albedo.h, for
// metals); a dielectric lobe with anisotropic widths is looked up at its geometric-mean width
// sqrt(ax ay), an approximation. Widths above 1 are clamped to 1.
//
// ggxReflectionQuadrature is the albedo at one direction wo (wo.z > 0, any azimuth, any widths)
// by the table's quadrature: what each table's nodes hold.
#pragma once

#include "core/vec.h"

namespace fluence::render {

class GgxDistribution;

float ggxReflectionAlbedo(float cosTheta, float alpha, float f0);
float ggxReflectionAverageAlbedo(float alpha, float f0);
float ggxReflectionQuadrature(const GgxDistribution& ggx, const Vec3f& wo, float f0);
// F(cos) of a facet of the dielectric of normal-incidence reflectance f0; 1 for f0 = 1.
float ggxFacetReflectance(float cosTheta, float f0);

}  // namespace fluence::render
