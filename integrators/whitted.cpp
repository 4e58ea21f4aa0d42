#include "integrators/whitted.h"

#include "integrators/direct_lighting.h"

namespace fluence::integrators {

FilmSample Whitted::sample(const RenderState&, const render::RenderScene& scene, const render::Camera& camera,
                           const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const {
    return directLightingThroughDeltaLobes(scene, camera, ray, rng, counters, maxDepth_);
}

}  // namespace fluence::integrators
