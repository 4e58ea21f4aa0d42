// `--integrator auto`: the cheapest solution method whose path classes cover the scene's, and why.
//
// The candidates, cheapest first by their cost per sample on the Cornell box
// (bench/results/2026-11-27-integrators.md): direct, whitted, path, sppm. `radiosity` is left
// out (its discretisation is a bias no sample count removes), as is `naive` (a test reference).
// `sppm` covers every class (caustics from delta lights, volumes and subsurface included), so
// there is always a choice: it is taken when the cheaper three miss something
// (tests/integrators/automatic_choice_test.cpp checks that it covers them all). `bdpt` covers the
// same classes since it traces light to the camera (t = 1), but it is not chosen: it costs 1.8 times
// sppm per sample on the Cornell box (11.7 s against 6.44 s at 256 spp, same RMSE), and misses
// point-light caustics seen through glass or in mirrors (LS+DS+E), which sppm renders.
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
