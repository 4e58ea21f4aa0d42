// `naive`: the reference estimator beside `path`. Covers L(S|D)*E except paths whose light
// vertex is a delta light (a DistantLight of angle 0), which no BSDF sample can hit. It honours
// light links (render/light_links.h), but, with no shadow rays, not shadow:enable = false or
// shadow links: light that passes surfaces (render/shadow_rays.cpp) only next-event estimation finds.
//
// It continues every path by sampling the BSDF (and, in volumes, by delta-tracked free flights and
// phase-function sampling) and counts emission only where a path happens to hit an emitter or is
// absorbed by an emitting medium: no next-event estimation, no multiple importance sampling. It is slow and
// noisy, and it is deliberately simple, so that it can be trusted: the tests check that `path`
// agrees with it within noise on scenes with every kind of light (pbrt-v4 keeps a SimplePath for
// the same reason).
#pragma once

#include "integrators/integrator.h"

namespace fluence::integrators {

class NaivePathTracer final : public Integrator {
public:
    explicit NaivePathTracer(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth) {}

    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override;

private:
    int maxDepth_;
};

}  // namespace fluence::integrators
