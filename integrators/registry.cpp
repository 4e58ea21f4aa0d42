#include "integrators/integrator.h"
#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"

namespace fluence::integrators {

const std::vector<IntegratorInfo>& integratorRegistry() {
    static const std::vector<IntegratorInfo> registry = {
        {"path", "L(S|D)*E", kAllPathClasses & ~kDeltaLightCaustics,
         "unidirectional path tracing with next-event estimation, MIS and Russian roulette",
         [](const IntegratorSettings& s) { return std::make_unique<PathTracer>(s); }},
        {"naive", "L(S|D)*E without delta lights", kAllPathClasses & ~(kDeltaLights | kDeltaLightCaustics),
         "reference path tracing by BSDF sampling only (no NEE, no MIS): slow; for validating `path`",
         [](const IntegratorSettings& s) { return std::make_unique<NaivePathTracer>(s); }},
    };
    return registry;
}

const IntegratorInfo* findIntegrator(const std::string& name) {
    for (const IntegratorInfo& info : integratorRegistry())
        if (info.name == name) return &info;
    return nullptr;
}

}  // namespace fluence::integrators
