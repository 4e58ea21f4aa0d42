// A camera sample's cost, for adaptive sampling's budget rule (integrators/adaptive_sampling.h):
// the work its path did, counted, not timed, so that the decisions that read it are the same on
// any machine, under any load, at any thread count and after a resumed checkpoint.
//
// The cost is in units of one ray: the rays the sample traced (camera, bounce and shadow rays: a
// random-walk step through a subsurface interior is a bounce ray, and costs more below), plus the tentative collisions
// its free flights and transmittance estimates drew in media (each a medium lookup:
// media/free_flight.h, media/transmittance.h) at kMediumCollisionCost rays each. The weight was
// measured once (bench/sample_cost_calibration.py, bench/results/2026-12-05-adaptive-2.md): the
// CPU time of 128 extra uniform samples per pixel of the Cornell box (rays only), the smoke (rays
// and lookups in a VDB grid) and the subsurface scene, fitted by least squares as
// a (rays + collisions x kMediumCollisionCost): 1.32, and the fit predicts each scene's time within
// 2%. (A per-sample term fitted too came out negative, -0.33 rays: not a cost, so there is none.)
// A sample that is one camera ray meeting nothing (no surface, light or medium: a background
// without a sky) costs kMissedCameraRayCost rays instead of 1: it traces the cheapest ray there is
// and shades nothing. Measured (bench/results/2026-12-05-adaptive-3.md): the CPU time of 128 extra
// samples per pixel, 128 x 128, of the subsurface scene without its geometry against the Cornell
// box's per ray, three interleaved rounds: 0.080 us a missed sample, 0.185 us a ray, 0.41-0.45 ray.
// Counted as a whole ray, the background pixels adaptive sampling stops early were credited with
// more CPU than they free, and its renders of the subsurface scene overspent their budget.
// A step of a guided subsurface random walk (a free flight inside a randomwalk_guided interior:
// RenderCounters::walkSteps) costs kWalkStepCost rays on top of its ray: the walk's free flight,
// phase sampling and guiding; the classic walk's steps are charged by their medium collisions (as
// any medium's, tinted glass included) and are not counted here: the fit below is the guided
// walk's. Measured (bench/results/2026-12-06-adaptive-5.md): the CPU time of each of 4 x 4 tiles
// of the subsurface scene, 128 spp, one thread, the least of two rounds, fitted as
// a (rays + w walk steps): w = 3.17, each tile within 6% (the whole-scene fit above cannot see it:
// a scene's rays and steps come together). Without it the blob's tiles took 1.8x the CPU their
// counted cost said, and adaptive renders of that scene, which give the blob more samples,
// 1.13-1.29x the CPU of the uniform render of the same counted cost (now 1.00-1.03).
// A grid cell an exact flight or transmittance walks (path --exact-flights: RenderCounters::
// exactCells; media/exact_tracking.h) costs kExactCellCost rays: eight array reads and a cubic, not
// a medium lookup, and walks visit several cells per lookup that delta tracking would make, so
// charging them as lookups overcharged volume pixels several-fold. Measured (session 19): render
// CPU of the smoke peer, 128 x 128, 64 spp, one thread, three interleaved rounds at --exact-flights
// 0, 1 and 3 (0 cells, 5.2 M and 31.2 M), fitted as a (rays + 1.3 collisions + w cells): w = 0.40,
// each configuration within 4%.
// An integrator counts what it counts (RenderCounters): one that counts nothing costs 0 per
// sample, which adaptive sampling reads as every sample alike.
#pragma once

#include <cstdint>

#include "integrators/integrator.h"

namespace fluence::integrators {

inline constexpr double kMediumCollisionCost = 1.3;
inline constexpr double kMissedCameraRayCost = 0.43;
inline constexpr double kWalkStepCost = 3.2;
inline constexpr double kExactCellCost = 0.4;

// The cost of the sample whose counting took the counters from `before` to `after`; `hit`: whether
// its camera ray hit something (FilmSample::hit).
inline double sampleCost(const RenderCounters& before, const RenderCounters& after, bool hit) {
    const std::uint64_t rays = after.rays() - before.rays(),
                        collisions = after.mediumCollisions - before.mediumCollisions,
                        steps = after.walkSteps - before.walkSteps, cells = after.exactCells - before.exactCells;
    if (!hit && rays == 1 && collisions == 0 && cells == 0) return kMissedCameraRayCost;
    return double(rays) + kMediumCollisionCost * double(collisions) + kWalkStepCost * double(steps) +
           kExactCellCost * double(cells);
}

}  // namespace fluence::integrators
