// When a path ends: Russian roulette after surface and medium scatterings, and the budget of
// scatterings inside material interiors, shared by every integrator that traces paths.
#pragma once

#include <algorithm>

#include "core/random.h"
#include "core/rgb.h"

namespace fluence::integrators {
// Russian roulette after three bounces: survive with probability min(max(throughput x etaScale),
// 0.95) and reweight the survivors, which keeps the estimator unbiased. etaScale is the product of
// eta^2 over the path's refractions (BsdfSample::eta): radiance is scaled by 1 / eta^2 on entering
// a denser medium and back on leaving it (render/bsdf.h), which is no reason to end a path inside
// glass (pbrt-v4's rrBeta). Returns false to end the path.
inline bool continuePath(RGB& throughput, float etaScale, int depth, SampleStream& rng) {
    constexpr int kRouletteStartDepth = 3;
    constexpr float kMaxSurvival = 0.95f;
    if (isBlack(throughput)) return false;
    if (depth + 1 < kRouletteStartDepth) return true;
    float survive = std::min(maxComponent(throughput) * etaScale, kMaxSurvival);
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
