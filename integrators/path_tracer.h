// `path`: the unidirectional path tracer. Covers L(S|D)*E (in this slice every surface is
// diffuse, so L D* E).
//
// At each surface vertex it samples one light (chosen proportionally to power) for next-event
// estimation and one BSDF direction to continue the path, and combines the two strategies for
// hitting emitters with multiple importance sampling (Veach's power heuristic). Paths end when
// they leave the scene, reach maxDepth scattering events, or are stopped by Russian roulette
// (after three bounces, with survival probability equal to the throughput's largest component,
// capped at 0.95) — roulette keeps the estimator unbiased.
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
