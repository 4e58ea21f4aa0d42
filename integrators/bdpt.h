// `bdpt`: bidirectional path tracing (Veach's thesis, ch. 10; Veach & Guibas 1995; pbrt's
// BDPTIntegrator, 3rd and 4th editions), through participating media (pbrt-v3's volumetric BDPT
// for the vertices; Miller, Georgiev & Jarosz 2019 for the null-scattering densities and the
// spectral MIS). Covers L(S|D|V)*E from lights that rays can hit; from delta lights (point, spot,
// line, angle-0 distant), every path whose first vertex is diffuse (LD(S|D|V)*E) or which holds
// two adjacent joinable vertices (L(S|D|V)*DD(S|D|V)*E, V a scattering in a volume): so, unlike
// `path`, a point light's caustic once it lights another diffuse surface (LS+DD+E), but not the
// caustic seen directly or through mirrors (LS+DS*E), which needs t = 1 (below).
//
// PER CAMERA SAMPLE: a light subpath y_0 ... y_{n-1} (a light chosen in proportion to its power
// among those that offer emission sampling, render/light.h; a point and direction from
// Light::sampleEmission; then BSDF sampling with the ADJOINT BSDF, f*(wo, wi) = f(wi, wo),
// including Veach's shading-normal correction |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|), since
// render/bsdf.h's f transports radiance) and a camera subpath z_0 ... from the given ray, as
// `path` traces it. Every prefix pair (s, t) with t >= 2 is a strategy:
//   s = 0   the camera subpath hits a light (its shape, an emissive triangle, or a light at
//           infinity as it leaves the scene);
//   s = 1   next-event estimation at z_{t-1}: a light chosen by the light tree and sampled by
//           its own sampler (exactly `path`'s), with a shadow ray;
//   s >= 2  y_{s-1} joined to z_{t-1} by a shadow ray, both non-delta.
// LEFT OUT: t = 1 (light tracing to the camera) and t = 0 (the camera cannot be hit). Their
// contributions land in other pixels than the sample's, and Fluence's render loop adds a sample
// to its own pixel only (so images stay bit-identical at any thread count). The MIS weights are
// therefore normalised over the strategies with t >= 2 (integrators/bdpt_mis.h), which keeps
// the estimator unbiased for every path that one of them can produce. The price: a caustic from
// a point or angle-0 distant light seen DIRECTLY (LS+DE) needs t = 1, and is missed as by
// `path`; once it lights another diffuse surface (LS+DDE), s >= 3 with t = 2 finds it. Light
// from cylinder and line lights (no emission sampling) is found by s = 0 and s = 1 alone.
//
// MEDIA. Both subpaths track the media they are in as `path` does (integrators/medium_stack.h:
// the scene's volumes everywhere, the materials' interiors inside closed surfaces; the camera
// outside every closed surface). A light subpath starts in the interiors that hold its light
// (bdpt::mediaAt, a probe ray), so a light inside a glass of liquid lights it from inside. Along
// every ray each subpath draws a free flight by delta tracking (media::sampleFreeFlight, hero
// channel h): a scattering is a medium vertex whose "BSDF" is the Henyey-Greenstein phase
// function (no cosines, its own adjoint); an absorption ends the subpath. Joins and next-event
// estimation (s >= 1) multiply by the transmittance of their shadow segment, by ratio tracking
// (media::ratioTrackingTransmittance) through the medium on the camera vertex's side of it (the
// stack after the vertex towards the light, as `path`'s shadowFrom). One hero channel, drawn
// per sample, serves both subpaths; the MIS weights are the power heuristic over (hero,
// strategy) pairs, with the free-flight densities of the medium vertices (bdpt_mis.h: MEDIA and
// SPECTRAL MIS, which says exactly which densities: the true ones through homogeneous media, a
// consistent model with the same zeros through heterogeneous ones).
//   Material interiors (random walks). A scattering inside a material's interior (a subsurface
// random walk, a murky liquid) is a walk step, as in `path`: it counts against its own budget of
// kMaxInteriorScatterings per subpath (not maxDepth), plays no Russian roulette, and is never
// joined (no next-event estimation, no s >= 2 join at it, on either subpath): the closed surface
// around it blocks the shadow rays of every light outside, and joining walks of hundreds of
// steps pairwise would cost their product in shadow rays. Strategies that would join there do not
// exist for the MIS (bdpt_mis.h, `joinable`), so the estimator stays unbiased; light reaches walk
// vertices through the surface vertices around them (a subsurface boundary is diffuse and
// joinable) and by the walks themselves (a light subpath walks through a subsurface object too).
// A path whose two subpaths' walks together exceed the budget is weighted as if every strategy
// could draw it (only the walk that reaches the budget loses light, as in `path`).
//   Emission in media (blackbody, emissive volumes) is found by the camera subpath alone, where
// its flight is absorbed (the absorption estimator, weighted over heroes as in `path`): no light
// subpath starts in a medium and no next-event estimation samples one; as those strategies
// cannot draw such paths, the camera's is their only strategy, which is unbiased.
//   Left out with media: lights at infinity (dome, distant) start no light subpath when the
// scene has volumes, because RenderScene::bounds(), over which they emit, does not include the
// volumes (a volume outside it would lose light): their light reaches volumes by s = 0 and s = 1,
// as in `path`. Diffusion subsurface materials (SubsurfaceMethod::Diffusion) are rendered by the
// random walk through their interior medium, not by integrators/diffusion_probe.h's profile.
//
// Paths hold at most maxDepth scattering vertices (s + t - 2, as `path` counts them; walk steps
// apart); both subpaths play Russian roulette (integrators/first_hit.h). Two-sided surfaces are
// shaded on the side a subpath arrives from, transmissive ones keep their orientation
// (render/bsdf.h, SIDES), and every join drops directions on which the shading frame and the
// surface disagree, as `path` does.
#pragma once

#include <vector>

#include "core/sampling.h"
#include "integrators/integrator.h"

namespace fluence::integrators {

class Bdpt final : public Integrator {
public:
    explicit Bdpt(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth) {}

    // Builds the choice of light for light subpaths.
    void prepare(const render::RenderScene& scene, const render::Camera& camera, std::uint64_t seed) const override;
    FilmSample sample(const render::RenderScene& scene, const render::Camera& camera, const render::Ray& ray,
                      SampleStream& rng, RenderCounters& counters) const override;

private:
    int maxDepth_;
    // Over emitting lights, by power; index -> light, and light -> its probability (0: none).
    mutable DiscreteDistribution emitterChoice_;
    mutable std::vector<int> emitters_;
    mutable std::vector<float> emitterProbability_;
};

}  // namespace fluence::integrators
