// `--integrator auto`: the cheapest solution method whose path classes cover the scene's, and why.
//
// The candidates, cheapest first by their cost per sample on the Cornell box
// (bench/results/2026-11-27-integrators.md): direct, whitted, path, sppm. `radiosity` is left
// out (its discretisation is a bias no sample count removes), as are `naive` (a test reference)
// and `bdpt` (it covers no class `path` misses, at five times its cost). When no candidate covers
// every class the scene has (caustics from delta lights inside a volume, say), the one that misses
// the fewest is chosen, the cheapest among equals, and the reason names what it misses.
#pragma once

#include <string>

#include "integrators/integrator.h"

namespace fluence::integrators {

inline constexpr const char* kAutomaticIntegrator = "auto";

struct AutomaticChoice {
    const IntegratorInfo* integrator = nullptr;
    std::string reason;  // one sentence for the log
};

// The choice for a scene that can produce the PathClass bits `sceneClasses`.
AutomaticChoice chooseIntegrator(unsigned sceneClasses);

}  // namespace fluence::integrators
