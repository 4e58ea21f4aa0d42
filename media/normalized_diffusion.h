// The normalized diffusion reflectance profile of Christensen & Burley 2015 ("Approximate
// Reflectance Profiles for Efficient Subsurface Scattering", Pixar Technical Memo #15-04; the
// profile's form is Burley's, SIGGRAPH 2015 course "Extending the Disney BRDF to a BSDF with
// Integrated Subsurface Scattering"), per RGB channel, with its radius sampling and densities.
//
// PROFILE. Light entering a flat, semi-infinite medium at one point leaves it at distance r with
// the diffuse reflectance per unit area
//     R(r) = A (e^(-r/d) + e^(-r/(3d))) / (8 pi d r),
// where A is the surface albedo (the profile's total reflectance) and d the shape parameter, a
// length. R is normalised: its integral over the plane, int_0^inf R(r) 2 pi r dr, is exactly A.
//
// SCALING. d = l / s(A), with l the volume mean free path (Standard Surface's subsurface_radius x
// subsurface_scale, in scene units) and
//     s(A) = 1.85 - A + 7 |A - 0.8|^3,
// the paper's fit for the searchlight configuration (a thin beam entering perpendicularly at one
// point, l as the length unit). That configuration is what R(r) above is, the response to light
// entering at a single point, and l is what Standard Surface authors: the paper's other fits are
// for diffuse surface transmission (light entering through the whole surface,
// s = 1.9 - A + 3.5 (A - 0.8)^2) and for the diffuse mean free path (a different length,
// s = 3.5 + 100 (A - 0.33)^4). s is decreasing on [0, 1], from 5.434 at A = 0 to 0.906 at A = 1,
// so d is positive and finite for every albedo. A is clamped to [0, 1]; l must be positive.
//
// SAMPLING. The density of r along the radius, p(r) = R(r) 2 pi r / A, is a mixture of two
// exponentials: weight 1/4 at rate 1/d and weight 3/4 at rate 1/(3d); its CDF is
//     F(r) = 1 - e^(-r/d) / 4 - 3 e^(-r/(3d)) / 4.
// sampleRadius() picks the component with one uniform number u and inverts that component's CDF
// with u remapped to [0, 1). It draws from the whole profile, with no truncation, so a sample's
// weight R 2 pi r / p(r) is exactly A (up to float rounding). pdfArea() is the density on the
// plane of the point at that radius and a uniform angle about the entry point, p(r) / (2 pi r),
// so R / pdfArea = A too.
//
// MAXIMUM RADIUS. maxRadius() is the radius within which the fraction kMaxRadiusEnergyFraction of
// the profile's energy lies (F(r) = 0.999), for the length of probe rays. F depends on r / d only,
// so it is one quantile, found once by bisection on F, times d. A caller that looks for exit
// points only within it loses 1 - 0.999 of the energy; sampleRadius() does not truncate to it, so
// that the loss is the caller's choice and visible there, not hidden in the sampler's weight.
//
// r -> 0. R and pdfArea diverge as 1 / r (R ~ A / (4 pi d r)); the divergence is integrable and
// p(r) stays finite (1 / (2d) at r = 0). Callers evaluate at r > 0, but sampleRadius() returns 0
// for u = 0 and u = 1/4, so R and pdfArea are evaluated at max(r, kMinRadiusOverD d): finite, with
// R / pdfArea = A still, at the cost of the energy within kMinRadiusOverD d, about
// kMinRadiusOverD / 2 = 3e-8 of A, below A's float rounding.
#pragma once

#include "core/rgb.h"

namespace fluence::media {

class NormalizedDiffusion {
public:
    static constexpr double kMaxRadiusEnergyFraction = 0.999;
    static constexpr double kMinRadiusOverD = 0x1p-24;

    // albedo: A per channel (clamped to [0, 1]); meanFreePath: l per channel, > 0, scene units.
    NormalizedDiffusion(const RGB& albedo, const RGB& meanFreePath);

    // d per channel (see SCALING).
    const RGB& shapeParameter() const { return d_; }
    // R(r) per channel, r >= 0 (see PROFILE and r -> 0).
    RGB profile(float r) const;
    // int_0^inf R(r) 2 pi r dr = A.
    const RGB& totalReflectance() const { return albedo_; }

    // Draws r >= 0 with density pdfRadius(channel, r) from u in [0, 1).
    float sampleRadius(int channel, float u) const;
    // p(r) = R_c(r) 2 pi r / A_c, the density of r along the radius.
    float pdfRadius(int channel, float r) const;
    // p(r) / (2 pi r), the density per unit area on the plane (see r -> 0).
    float pdfArea(int channel, float r) const;
    // The radius holding kMaxRadiusEnergyFraction of channel's energy.
    float maxRadius(int channel) const;

private:
    RGB albedo_, d_;
};

// s(A) (see SCALING): the volume mean free path over the shape parameter d.
float normalizedDiffusionScale(float albedo);

// F(r), the fraction of the profile's energy within radius r >= 0 of a profile with shape
// parameter d, in closed form (see SAMPLING).
double normalizedDiffusionCdf(double r, double d);

}  // namespace fluence::media
