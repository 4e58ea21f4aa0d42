// A camera sample's cost, for adaptive sampling's budget rule (integrators/adaptive_sampling.h):
// the work its path did, counted, not timed, so that the decisions that read it are the same on
// any machine, under any load, at any thread count and after a resumed checkpoint.
//
// The cost is in units of one shadow ray, each kind of work at its own weight: a camera sample's
// camera ray (with the per-sample work: set-up, film writes), its bounce rays (each an intersection
// that leads to a shading point: hit shading and BSDF sampling), its shadow rays (occlusion only),
// the tentative collisions its free flights and transmittance estimates drew in media (each a
// medium lookup: media/free_flight.h, media/transmittance.h), the steps of its guided subsurface
// random walks (RenderCounters::walkSteps: a free flight inside a randomwalk_guided interior, its
// phase sampling and guiding, on top of its bounce ray; the classic walk's steps are charged by
// their medium collisions, as any medium's, tinted glass included) and the grid cells its exact
// flights and transmittances walked (path --exact-flights: RenderCounters::exactCells;
// media/exact_tracking.h: eight array reads and a cubic) and the exact flights and transmittances
// it started (RenderCounters::exactFlights: each prepares its walks over the majorant and the
// density grids, whether it walks a cell or not). A sample that is one camera ray meeting nothing
// (no surface, light or medium collision) is charged kMissedCameraRayCost for it instead: it traces
// the cheapest ray there is and shades nothing (plus the exact flight it started, if any).
// Measured (bench/sample_cost_calibration.py --tiles 4 --tile-spp 1024 --repeat 2,
// bench/results/2026-12-06-adaptive-8-s20.md): the render CPU of each of 4 x 4 tiles of the Cornell
// box, the smoke and the subsurface scene, 128 x 128, one thread, the least of two rounds; a
// scene's tiles see the kinds in different proportions (the Cornell box's tiles trace 1.5-3.0
// bounce rays a sample, the smoke's and the subsurface scene's background tiles are all missed
// samples), which whole-scene fits cannot separate. Fitted by non-negative least squares on each
// tile's relative error: the ray kinds on the Cornell box (rays only): 46 ns a camera sample, 304
// ns a bounce ray, 47 ns a shadow ray; then, with those fixed, the smoke's collisions 103 ns and
// cells 70 ns and the subsurface scene's walk steps 225 ns (4.8 shadow rays; the 4.9 below is a
// first pass of the fit's, 229 ns, and is what was measured with: within the fit's spread). In the
// smoke and the subsurface scene bounce and shadow rays come together, so they cannot fix the ray
// weights themselves. A missed sample took 92 ns in the subsurface scene and 175 ns in the smoke
// (its camera rays start an exact flight through the volume's bounds and walk no cell; its dome is
// not it: a background tile took 0.17 s of CPU with the dome as without), which no counter then told
// apart: kMissedCameraRayCost was their geometric mean, 1.4x too dear in the one and too cheap in
// the other (until the flights were counted, below). The tiles' CPU over these weights' prediction (each scene's over their mean:
// allocation compares a scene's pixels with each other only), rms: Cornell box 3.7% (4.7% with
// every ray 1, collisions 1.3, walk steps 3.2, cells 0.4, a missed sample 0.43: the weights
// before), smoke 16% (52%: its volume tiles were charged 2-3x what they took against its
// background's), subsurface scene 13% (26%); most of what is left is the missed samples' two costs.
// Refitted after the cell walk took Simpson's rule (volumes/trilinear_cells.h) and path's default
// became --exact-flights 3 (session 20, bench/results/2026-12-06-lead-s20.md): the smoke's 16 tiles
// rendered again at the new default, fitted with the Cornell box's and the subsurface scene's tiles
// above (their code paths unchanged but for a few % of CPU): a cell 30 ns (0.63 shadow rays, was
// 1.5), a missed sample 209 ns in the smoke (its background rays now set up an exact flight at every
// level), geometric mean 138 ns (2.9); smoke rms 19% (52% with the weights before the refit).
// The flights counted apart (session 21, bench/results/2026-12-06-adaptive-9-s21.md): the smoke's
// 16 tiles rendered again with the counter, fitted after the subsurface scene's, whose missed
// samples start no flight and so give a missed sample's own cost, 92 ns (1.94), kept for the
// smoke's: a flight 109 ns (2.3), a cell 28 ns (0.58). Tiles' rms: smoke 7.3% (19%), subsurface
// scene 5.4% (16%: its background was charged 1.5x its CPU); the Cornell box's 3.7% unchanged.
// An integrator counts what it counts (RenderCounters): one that counts nothing costs 0 per
// sample, which adaptive sampling reads as every sample alike.
#pragma once

#include <cstdint>

#include "integrators/integrator.h"

namespace fluence::integrators {

inline constexpr double kCameraRayCost = 1.0;
inline constexpr double kBounceRayCost = 6.4;
inline constexpr double kShadowRayCost = 1.0;
inline constexpr double kMediumCollisionCost = 2.2;
inline constexpr double kWalkStepCost = 4.9;
inline constexpr double kExactCellCost = 0.58;
inline constexpr double kExactFlightCost = 2.3;
inline constexpr double kMissedCameraRayCost = 1.94;

// The cost of the work `c` counts at the weights above (a missed sample's camera ray is charged
// kMissedCameraRayCost instead).
inline double countedCost(const RenderCounters& c) {
    return kCameraRayCost * double(c.camera) + kBounceRayCost * double(c.bounce) + kShadowRayCost * double(c.shadow) +
           kMediumCollisionCost * double(c.mediumCollisions) + kWalkStepCost * double(c.walkSteps) +
           kExactCellCost * double(c.exactCells) + kExactFlightCost * double(c.exactFlights);
}

// The cost of the sample whose counting took the counters from `before` to `after`; `hit`: whether
// its camera ray hit something (FilmSample::hit).
inline double sampleCost(const RenderCounters& before, const RenderCounters& after, bool hit) {
    RenderCounters sample = after;
    sample -= before;
    if (!hit && sample.rays() == 1 && sample.mediumCollisions == 0 && sample.exactCells == 0)
        return kMissedCameraRayCost + kExactFlightCost * double(sample.exactFlights);
    return countedCost(sample);
}

}  // namespace fluence::integrators
