// `path`: the unidirectional path tracer. Covers L(S|D)*E: glossy and diffuse vertices (D) are
// connected to lights, delta lobes (S) are followed by BSDF sampling alone.
//
// At each non-delta surface vertex it samples one light (chosen by the light tree for that point
// and normal, render/light_tree.h; on a transmissive surface for the point alone, as light may
// arrive from either side) for next-event estimation and one BSDF direction
// (render/material_bsdf.h) to continue the path, reflected or transmitted, and combines the two
// strategies for hitting emitters with multiple importance sampling (Veach's power heuristic;
// emission reached through a delta lobe takes full weight). Two-sided opaque surfaces are shaded
// on the side the path arrives from; transmissive ones keep their orientation (render/bsdf.h,
// SIDES). Paths end when they leave the scene, reach maxDepth scattering events, or are stopped
// by Russian roulette (after three bounces, with survival probability equal to the throughput's
// largest component, discounting the 1/eta^2 radiance scaling of refraction, capped at 0.95) —
// roulette keeps the estimator unbiased.
#pragma once

#include "integrators/integrator.h"

namespace fluence::integrators {

class PathTracer final : public Integrator {
public:
    explicit PathTracer(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth) {}

    FilmSample sample(const render::RenderScene& scene, const render::Camera& camera, const render::Ray& ray,
                      SampleStream& rng, RenderCounters& counters) const override;

private:
    int maxDepth_;
};

}  // namespace fluence::integrators
