// `whitted`: Whitted ray tracing. Covers LD?S*E: emitters and diffuse or glossy surfaces lit
// directly, seen straight or through any chain of mirrors and smooth glass.
//
// THE METHOD (Whitted 1980, "An Improved Illumination Model for Shaded Display", with area lights,
// soft shadows and MIS in place of its point lights). The camera ray is followed through perfect
// specular (delta) lobes: at each hit one direction is drawn from the BSDF, and a delta sample
// carries the ray on: a mirror reflection, or a smooth refraction or reflection, chosen between by
// the BSDF's own lobe probabilities (so the expectation holds both rays Whitted traced). At the
// first vertex with a diffuse or glossy lobe the path takes direct lighting exactly as `direct`
// does (integrators/direct_lighting.h: next-event estimation and that BSDF sample, combined by
// MIS) and ends there; a glossy surface is an endpoint like a diffuse one. A material with both
// kinds of lobe (a smooth clear coat over a diffuse base) takes direct lighting through its
// non-delta lobes and continues when its sample falls in the delta lobe. Paths end at maxDepth
// scattering events, with Russian roulette after three (integrators/russian_roulette.h), as in `path`; with
// maxDepth 1 it is `direct`.
//
// WHAT IT MISSES. Light that reaches a diffuse or glossy surface other than straight from an
// emitter: interreflection (LD(D|S)*DS*E) and caustics (LS+DS*E), so shadows of glass are black.
// Shadow rays are blocked by glass like any surface. Media and subsurface materials are treated as
// by `direct`: media only attenuate (including a glass's interior medium, integrators/
// medium_stack.h), the walk under a subsurface material is not followed.
#pragma once

#include "integrators/integrator.h"

namespace fluence::integrators {

class Whitted final : public Integrator {
public:
    explicit Whitted(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth) {}

    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override;

private:
    int maxDepth_;
};

}  // namespace fluence::integrators
