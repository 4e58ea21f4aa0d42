// Free-flight sampling by delta tracking (Woodcock et al. 1965, "Techniques used in the GEM code
// for Monte Carlo neutronics calculations"), with the spectral MIS of Miller et al. 2019: the
// derivation, and the exact way a path tracer uses the result with next-event estimation and
// MIS, are in media/tracking.h (THE ESTIMATORS, SPECTRAL MIS, HOW A PATH TRACER USES THEM).
//
// Tentative collisions are drawn at the hero's majorant sigmaMaj_h; at each, one number from the
// stream chooses absorption, scattering or a null collision with probabilities sigmaA_h, sigmaS_h
// and sigmaN_h over sigmaMaj_h. (Should a broken majorant fall below sigmaT, the three are
// renormalised by sigmaT, which keeps the weights finite but not unbiased: media/majorant_check.h
// catches such media in their tests.) The flight ends at the first absorption or scattering, or
// escapes at ray.tMax. Through a gray medium whose majorant is exact (a homogeneous one), every
// weight is exactly 1. Randomness: one number per exponential step and one per tentative
// collision, from the stream passed in (or, in the second form, one number given for all the
// events). The flight counts its tentative collisions (its medium lookups), the work adaptive
// sampling weighs a sample's cost by (integrators/sample_cost.h).
#pragma once

#include "core/random.h"
#include "core/rgb.h"
#include "media/medium.h"
#include "media/tracking.h"

namespace fluence::media {

enum class FlightEvent { Escaped, Absorbed, Scattered };

struct FreeFlight {
    FlightEvent event = FlightEvent::Escaped;
    float t = 0.0f;                  // the real collision's distance, or ray.tMax on escape
    Vec3f p;                         // ray.at(t) at a real collision
    MediumProperties properties;     // the coefficients there (emission for Absorbed, g for Scattered)
    RGB throughput{1.0f};            // f_c / p_h: Tmaj sigmaN per null point, then Tmaj sigmaA (Absorbed;
                                     // the caller multiplies by Le), Tmaj sigmaS (Scattered; the caller
                                     // multiplies by the phase function) or Tmaj to tMax (Escaped)
    RGB pdfRatio{1.0f};              // p_c / p_h: delta tracking's density had channel c been the hero
    RGB lightPdfRatio{1.0f};         // Escaped only: ratio tracking's density of the same null points and
                                     // escape (the shadow-ray strategy) in channel c, over p_h
    RGB ratioTrackedPdfRatio{0.0f};  // Scattered or Absorbed: ratio tracking's density of the same null
                                     // points and of no further point before t, in channel c, over p_h
                                     // (how a strategy that picks t itself, as equiangular sampling
                                     // does, reaches the same collision: integrators/equiangular_strategy.h)
    RGB absorbedThroughput{0.0f};    // an exact flight's (media/exact_tracking.h), Scattered: the weight
                                     // T sigmaA / p_h of absorption at the same point, whose emission
                                     // the caller scores there; the flight itself goes on scattering
    int collisions = 0;              // tentative collisions drawn (each one medium lookup): the work done
};

FreeFlight sampleFreeFlight(const Medium& medium, const MediumRay& ray, int hero, SampleStream& stream);

// The same flight, with the events at its tentative collisions chosen by the one number uEvent in
// [0, 1), remapped after each null collision (and fresh numbers from `steps` once the remapped
// number has lost half its bits): where the flight stops is then an inverse-CDF function of
// uEvent given the tentative collisions, so a stratified uEvent (a Sobol dimension of the sample)
// stratifies the flight's distance and its escape over a pixel's samples. `steps` gives the
// exponential steps; pass a stream whose draws do not shift the sample's other dimensions
// (SampleStream::independentStream). Unbiased as the other form: each choice keeps its
// probability given the choices before it.
FreeFlight sampleFreeFlight(const Medium& medium, const MediumRay& ray, int hero, float uEvent, SampleStream& steps);

}  // namespace fluence::media
