// Blackbody colours, for UsdLux colour temperature (inputs:colorTemperature).
//
// A blackbody's spectral radiance is Planck's law, B(λ, T) ∝ λ^-5 / (exp(c2 / (λ T)) - 1) with
// c2 = hc/k = 1.438777e-2 m·K (CODATA 2018). It is integrated against the CIE 1931 2° standard
// observer's colour-matching functions (CIE 015:2018, the 5 nm table from 360 to 830 nm) to give
// XYZ; Illuminant A, a blackbody at 2856 K, comes out at the CIE's (0.44757, 0.40745) to 1e-4.
//
// XYZ is taken to linear Rec.709 (the rendering space, D65 white) by the XYZ-to-RGB matrix of
// IEC 61966-2-1 (sRGB), and scaled to luminance 1, as UsdLux's UsdLuxBlackbodyTemperatureAsRgb
// does: the temperature tints a light without changing its luminance. 6500 K is then close to,
// but not exactly, white: D65 lies slightly off the Planckian locus.
#pragma once

#include "core/rgb.h"

namespace fluence {

// CIE 1931 XYZ of a blackbody at `kelvin` (> 0), scaled to Y = 1.
Vec3d blackbodyXyz(double kelvin);

// Linear Rec.709 colour of a blackbody at `kelvin` (> 0), scaled to luminance 1. Below about
// 1900 K the blackbody lies outside the Rec.709 gamut; its negative components are clamped to 0
// before the scaling.
RGB blackbodyRgb(double kelvin);

}  // namespace fluence
