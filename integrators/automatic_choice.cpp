#include "integrators/automatic_choice.h"

namespace fluence::integrators {

AutomaticChoice chooseIntegrator(unsigned sceneClasses) {
    const std::string classes = describePathClasses(sceneClasses);
    for (const char* name : {"direct", "whitted", "path"}) {
        const IntegratorInfo* info = findIntegrator(name);
        if ((sceneClasses & ~info->covers) == 0)
            return {info, "the cheapest method that covers the scene's light paths (" + classes + ")"};
    }
    return {findIntegrator("sppm"), "it covers the scene's light paths (" + classes +
                                        "), which direct, whitted and path do not (bdpt covers them too)"};
}

}  // namespace fluence::integrators
