// A camera sample's cost, for adaptive sampling's budget rule (integrators/adaptive_sampling.h):
// the work its path did, counted, not timed, so that the decisions that read it are the same on
// any machine, under any load, at any thread count and after a resumed checkpoint.
//
// The cost is in units of one ray: the rays the sample traced (camera, bounce and shadow rays: a
// random-walk step through a subsurface interior is a bounce ray), plus the tentative collisions
// its free flights and transmittance estimates drew in media (each a medium lookup:
// media/free_flight.h, media/transmittance.h) at kMediumCollisionCost rays each. The weight was
// measured once (bench/sample_cost_calibration.py, bench/results/2026-12-05-adaptive-2.md): the
// CPU time of 128 extra uniform samples per pixel of the Cornell box (rays only), the smoke (rays
// and lookups in a VDB grid) and the subsurface scene, fitted by least squares as
// a (rays + collisions x kMediumCollisionCost): 1.32, and the fit predicts each scene's time within
// 2%. (A per-sample term fitted too came out negative, -0.33 rays: not a cost, so there is none.)
// An integrator counts what it counts (RenderCounters): one that counts nothing costs 0 per
// sample, which adaptive sampling reads as every sample alike.
#pragma once

#include "integrators/integrator.h"

namespace fluence::integrators {

inline constexpr double kMediumCollisionCost = 1.3;

// The cost of the sample whose counting took the counters from `before` to `after`.
inline double sampleCost(const RenderCounters& before, const RenderCounters& after) {
    return double(after.rays() - before.rays()) +
           kMediumCollisionCost * double(after.mediumCollisions - before.mediumCollisions);
}

}  // namespace fluence::integrators
