// DielectricTints: the artist's tints on a dielectric interface (Standard Surface's specular
// weight x specular_color on what it reflects, transmission_color on what it lets through),
// applied to the split Fresnel makes between the two.
//
//   reflected(F)   = reflection * F
//   transmitted(F) = transmission * (1 - reflection * F)
//
// F is the interface's Fresnel reflectance (at a microfacet, or at the smooth surface). The
// reflection tint scales what the interface reflects and hands the rest to the transmission, so
// the interface keeps exactly the light it does not reflect: with tints in [0, 1],
// reflected + transmitted <= 1 per channel, with equality for a white transmission tint. Both
// tints white give the physical interface. The factors depend only on F, which is the same on
// both sides of a microfacet (Fresnel's equations are symmetric in the two media), so a BSDF that
// applies them stays reciprocal. Beyond the critical angle (F = 1) no light can pass, so the
// share 1 - reflection a tint withholds from the reflection is lost there: the one case where a
// tint absorbs light the physical interface would have kept.
//
// Sampling picks reflection with probability reflectProbability(F) = lobeProbability(reflection)
// * F (render/bsdfs/lobe_choice.h), which is F itself for a white tint.
#pragma once

#include "core/rgb.h"
#include "render/bsdfs/lobe_choice.h"

namespace fluence::render {

struct DielectricTints {
    RGB reflection{1.0f};    // per channel, in [0, 1]
    RGB transmission{1.0f};  // per channel, in [0, 1]; per crossing of the interface

    RGB reflected(float F) const { return reflection * F; }
    RGB transmitted(float F) const { return transmission * (RGB(1.0f) - reflection * F); }
    float reflectProbability(float F) const { return lobeProbability(reflection) * F; }
};

}  // namespace fluence::render
