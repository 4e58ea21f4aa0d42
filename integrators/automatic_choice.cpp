#include "integrators/automatic_choice.h"

#include <bit>

namespace fluence::integrators {

AutomaticChoice chooseIntegrator(unsigned sceneClasses) {
    AutomaticChoice best;
    int fewestMissed = 0;
    for (const char* name : {"direct", "whitted", "path", "sppm"}) {
        const IntegratorInfo* info = findIntegrator(name);
        const int missed = std::popcount(sceneClasses & ~info->covers);
        if (!best.integrator || missed < fewestMissed) {
            best.integrator = info;
            fewestMissed = missed;
        }
        if (missed == 0) break;
    }
    const std::string classes = describePathClasses(sceneClasses);
    const unsigned missed = sceneClasses & ~best.integrator->covers;
    best.reason = missed == 0 ? "the cheapest method that covers the scene's light paths (" + classes + ")"
                              : "no method covers all the scene's light paths (" + classes + "); this one misses the fewest: " +
                                    describePathClasses(missed);
    return best;
}

}  // namespace fluence::integrators
