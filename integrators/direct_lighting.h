// `direct`: local illumination with shadows. Covers LE and LDE (and, through one delta lobe, LSE):
// emitters the camera sees, and the light that reaches the first surface hit straight from an
// emitter, shadowed by every surface in between; no interreflection.
//
// THE METHOD. At the first surface hit, one light is chosen by the light tree
// (render/light_tree.h) for that point and normal and sampled (next-event estimation, with a
// shadow ray), and one direction is drawn from the BSDF (render/material_bsdf.h); emission the
// BSDF-sampled ray reaches, on a light's shape, an emissive surface or a light at infinity, counts
// too. The two strategies are combined by multiple importance sampling with Veach's power
// heuristic (Veach 1997, "Robust Monte Carlo Methods for Light Transport Simulation", ch. 9), so
// small bright lights (found by light sampling) and glossy lobes under large ones (found by BSDF
// sampling) both converge. Delta lights (point, angle-0 distant, line) are reached by light
// sampling alone; emission reached through a delta lobe of the BSDF takes full weight, as no light
// sample could have found it. This is, in expectation, what `path` gives with maxDepth 1
// (IntegratorSettings{1}); a maxDepth of 0 leaves only the emitters seen.
//
// WHAT IT MISSES. Everything after the first bounce: interreflection (LD(D|S)*DE), what mirrors
// and glass show (L(D|S)S+E, but for the emitters a delta lobe reflects or refracts straight at
// the first hit, LSE), caustics (LS+DE). Transmissive and thin surfaces gather light from both
// sides (as `path` does: render/bsdf.h, SIDES), so a thin lit sheet glows through.
//
// MEDIA. Where the scene has media (volumes, or material interiors such as Standard Surface's
// transmission_depth, integrators/medium_stack.h), every segment of a path (the camera ray, the
// BSDF-sampled ray, each shadow ray) is attenuated by an estimate of its transmittance: unbiased
// ray marching (media/ray_marching_transmittance.h; a hero channel drawn for that estimate alone
// where it falls back on ratio tracking), so each is unbiased and independent of the others (the MIS weights are those of the directions
// alone, and still sum to 1). Media neither scatter nor emit here: in-scattering and volume
// emission (V events, and the first-volume-event AOVs) are missed, so volumes only darken what is
// behind them.
//
// SUBSURFACE. The walk under a subsurface material is not followed: its diffuse transmission lobe
// gathers only the lights on its far side (through a thin wall, or a light inside the object), and
// the light that enters a solid is lost, so subsurface materials render darker by their subsurface
// weight.
//
// The estimator below is also Whitted's (integrators/whitted.h): it follows the camera ray through
// delta lobes, gathering direct lighting at every vertex it reaches, up to maxDepth scattering
// events; `direct` runs it with maxDepth at most 1.
#pragma once

#include "integrators/integrator.h"

namespace fluence::integrators {

// The radiance along `ray` from emitters seen directly and from direct lighting (next-event
// estimation and one BSDF sample, by MIS) at each non-delta surface vertex the ray reaches through
// delta lobes, over at most maxDepth scattering events. A path ends at its first non-delta BSDF
// sample, once that sample's ray has found its emission; it follows a delta sample (mirror
// reflection, smooth refraction) with Russian roulette after three bounces (integrators/russian_roulette.h).
FilmSample directLightingThroughDeltaLobes(const render::RenderScene& scene, const render::Camera& camera,
                                           const render::Ray& ray, SampleStream& rng, RenderCounters& counters,
                                           int maxDepth);

class DirectLighting final : public Integrator {
public:
    explicit DirectLighting(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth < 1 ? 0 : 1) {}

    FilmSample sample(const RenderState&, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override {
        return directLightingThroughDeltaLobes(scene, camera, ray, rng, counters, maxDepth_);
    }

private:
    int maxDepth_;
};

}  // namespace fluence::integrators
