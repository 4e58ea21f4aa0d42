// The interior medium of a random-walk subsurface material, from an artist's controls: the colour
// the surface should have (its total diffuse reflectance) and how far light travels inside.
//
// Following Chiang, Kutz & Burley 2016 ("Practical and Controllable Subsurface Scattering for
// Production Path Tracing", SIGGRAPH talk), per channel:
//   sigmaT = 1 / meanFreePath                     (Standard Surface: subsurface_radius x subsurface_scale)
//   alpha  = singleScatteringAlbedo(colour)       the albedo inversion below
//   sigmaS = alpha sigmaT,  sigmaA = (1 - alpha) sigmaT,  g = anisotropy (clamped to +-0.99)
// The inversion is their fit of the single-scattering albedo alpha that gives a semi-infinite,
// index-matched slab with isotropic scattering the total diffuse reflectance A under diffuse
// (cosine-weighted) entry and exit:
//   alpha(A) = 1 - (4.09712 + 4.20863 A - sqrt(9.59217 + 41.6808 A + 17.7126 A^2))^2,
// exact at A = 0 and A = 1. Against Chandrasekhar's exact H-function solution for that slab
// (tests/media/subsurface_medium_test.cpp) the reflectance it gives is within 0.0020 of A
// everywhere (largest near A = 0.2) and within 1e-4 from A = 0.8 up. With
// anisotropy the same alpha is used, so the colour drifts from A (forward scattering g > 0 takes
// light deeper; Chiang et al. fit g = 0 only).
#pragma once

#include "core/rgb.h"
#include "media/medium.h"

namespace fluence::media {

inline constexpr float kMaxSubsurfaceAnisotropy = 0.99f;
inline constexpr float kMinMeanFreePath = 1e-6f;  // scene units; shorter paths are clamped to it

// The single-scattering albedo whose slab reflectance is `reflectance` (clamped to [0, 1]).
float singleScatteringAlbedo(float reflectance);

MediumProperties subsurfaceMedium(const RGB& colour, const RGB& meanFreePath, float anisotropy);

}  // namespace fluence::media
