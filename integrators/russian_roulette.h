// When a path ends: Russian roulette after surface and medium scatterings, and the budget of
// scatterings inside material interiors, shared by every integrator that traces paths.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/random.h"
#include "core/rgb.h"

namespace fluence::integrators {
// Russian roulette from the fifth path vertex on (kRouletteStartDepth: the first four, camera hit
// included, are always shaded): survive with probability min(sqrt(max(throughput x etaScale)),
// 0.95) and reweight the survivors, which keeps the estimator unbiased. The square root is Cycles'
// rule (path_state_continuation_probability): where a throughput-proportional survival ended 62%
// of the Cornell box's white-wall paths in one step (0.725^3 = 0.38), this ends them a few at a
// time, and the reweighted throughput settles at the albedo, each bounce surviving with about the
// albedo's probability. On the Cornell box it takes relMSE per sample to 0.66x for 1.2x the CPU
// (bench/results/2026-12-05-cornell-variance.md, with the start depths and exponents tried). The
// 0.95 cap keeps paths of albedo near 1 finite. etaScale is the product of eta^2 over the path's
// refractions (BsdfSample::eta): radiance is scaled by 1 / eta^2 on entering a denser medium and
// back on leaving it (render/bsdf.h), which is no reason to end a path inside glass (pbrt-v4's
// rrBeta). Returns false to end the path.
inline bool continuePath(RGB& throughput, float etaScale, int depth, SampleStream& rng) {
    constexpr int kRouletteStartDepth = 4;
    constexpr float kMaxSurvival = 0.95f;
    if (isBlack(throughput)) return false;
    if (depth + 1 < kRouletteStartDepth) return true;
    float survive = std::min(std::sqrt(maxComponent(throughput) * etaScale), kMaxSurvival);
    if (rng.next() >= survive) return false;
    throughput /= survive;
    return true;
}

// Scatterings inside a material's interior (MediumStack::depth() > 0: a subsurface walk, a murky
// liquid) are not bounces: a walk takes hundreds of steps. They count against their own budget of
// kMaxInteriorScatterings per path instead of maxDepth (a walk that reaches it ends and loses its
// light; the white furnaces of tests/integrators/subsurface_test.cpp, which would read below 1,
// show no such loss), and play no Russian roulette: delta
// tracking already ends walks by absorption, and continuePath's survival, capped at 0.95 per step,
// would end long walks and weigh the few survivors heavily.
inline constexpr int kMaxInteriorScatterings = 1024;

// Russian roulette after a scattering in a medium, inside an interior (`walking`) or not.
inline bool continueInMedium(RGB& throughput, float etaScale, int depth, bool walking, SampleStream& rng) {
    return walking ? !isBlack(throughput) : continuePath(throughput, etaScale, depth, rng);
}

}  // namespace fluence::integrators
