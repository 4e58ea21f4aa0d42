// The directional albedo of bare (F = 1) GGX reflection with anisotropic widths, tabulated over
// the direction of wo and both widths: what the multiple-scattering lobe of a brushed metal
// (render/bsdfs/ggx_multiple_scattering.h) takes the rest of.
//
//   E(wo, ax, ay) = integral over the hemisphere of D(h) G2(wo, wi) / (4 mu_o) dwi
//   Eavg(ax, ay)  = 1/pi integral E(w, ax, ay) cos theta_w dw   (the cosine-weighted average)
//
// A stretched GGX's albedo depends on the azimuth phi of wo, and not through the masking of wo
// alone: seen along its narrow axis (phi = 90 degrees, x the wide one) the surface masks wo
// little, but its facets, tilted mostly along x, send the light sideways to grazing directions
// where the shadowing is strongest. Measured by Monte Carlo at roughness 0.7, anisotropy 0.8
// (ax 1, ay 0.22), 80 degrees: E = 0.80 along x, 0.55 along y, where the masking width
// alpha(phi) = sqrt(cos^2 phi ax^2 + sin^2 phi ay^2) predicts 0.67 and 0.86 (the isotropic
// table at sqrt(ax ay) 0.81 for both). So the table resolves phi itself: by the symmetries of D
// (x -> -x, y -> -y) phi in [0, 90] degrees is enough.
//
// The table holds, for each pair of widths on a 32 x 32 grid of (sqrt(ax), sqrt(ay)) in
// [0, 1] (the axes of render/bsdfs/albedo_table.h), 32 values of mu by 16 evenly spaced values
// of phi, each integrated by the quadrature of render/bsdfs/albedo_table.h
// (ggxReflectionQuadrature); a slice of one pair is computed on first use (a material needs the
// four around its widths) and the table is interpolated linearly in each of the four. Eavg is
// integrated exactly from the same interpolant (piecewise linear in mu and in phi), so that the
// multiple-scattering lobe weighted by 1 - E(wo) and 1 - E(wi) keeps exactly the light the
// single-scattering lobe loses, as predicted by the table
// (tests/render/bsdf_energy_test.cpp holds the table to Monte Carlo at several azimuths).
//
// ggxBareAlbedo and ggxBareAverageAlbedo take any distribution: an isotropic or smooth one is
// looked up in the isotropic table (render/bsdfs/ggx_albedo.h), as before this table existed.
#pragma once

#include "core/vec.h"
#include "render/bsdfs/ggx.h"

namespace fluence::render {

// wo in the distribution's frame (x along its alphaX), wo.z > 0.
float ggxAnisotropicAlbedo(const Vec3f& wo, float alphaX, float alphaY);
float ggxAnisotropicAverageAlbedo(float alphaX, float alphaY);

float ggxBareAlbedo(const Vec3f& wo, const GgxDistribution& ggx);
float ggxBareAverageAlbedo(const GgxDistribution& ggx);

}  // namespace fluence::render
