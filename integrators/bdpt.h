// `bdpt`: bidirectional path tracing (Veach's thesis, ch. 10; Veach & Guibas 1995; pbrt's
// BDPTIntegrator, 3rd and 4th editions), through participating media (pbrt-v3's volumetric BDPT
// for the vertices; Miller, Georgiev & Jarosz 2019 for the null-scattering densities and the
// spectral MIS). Covers L(S|D|V)*E from lights that rays can hit; from delta lights (point, spot,
// line, angle-0 distant), every path whose first vertex is diffuse (LD(S|D|V)*E), which holds two
// adjacent joinable vertices (L(S|D|V)*DD(S|D|V)*E, V a scattering in a volume), or whose last
// vertex before the camera is joinable (L(S|D|V)*(D|V)E, by light tracing, t = 1): so, unlike
// `path`, a point light's caustic, seen directly (LS+DE) or once it lights another diffuse
// surface (LS+DD+E). Still missed from delta lights: caustics seen only through mirrors or glass
// (LS+DS+E), which no strategy with a pinhole camera can draw.
//
// PER CAMERA SAMPLE: a light subpath y_0 ... y_{n-1} (a light chosen in proportion to its power
// among those that offer emission sampling, render/light.h; a point and direction from
// Light::sampleEmission; then BSDF sampling with the ADJOINT BSDF, f*(wo, wi) = f(wi, wo),
// including Veach's shading-normal correction |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|), since
// render/bsdf.h's f transports radiance) and a camera subpath z_0 ... from the given ray, as
// `path` traces it. Every prefix pair (s, t) with t >= 1 is a strategy:
//   s = 0   the camera subpath hits a light (its shape, an emissive triangle, or a light at
//           infinity as it leaves the scene);
//   s = 1   next-event estimation at z_{t-1}: a light chosen by the light tree and sampled by
//           its own sampler (exactly `path`'s), with a shadow ray;
//   s >= 2  y_{s-1} joined to z_{t-1} by a shadow ray, both non-delta;
//   t = 1   light tracing: y_{s-1} (s >= 2, non-delta) joined to the pinhole, or to a point of a
//           thin lens's aperture drawn per vertex as camera rays draw theirs
//           (render::Camera::connect), with the camera where it is at the sample's time (a moving
//           camera's still copy, Camera::at, which the camera subpath's densities use too), its
//           light splatted into whichever pixel it lands on
//           (core/splat_film.h: fixed-point sums, bit-identical at any thread count), and the
//           splat sums divided by the light paths per pixel (one per camera sample) when the film
//           resolves. The light subpath may then hold maxDepth scattering vertices.
// t = 0 (a light subpath hitting the camera) does not exist: the pinhole cannot be hit.
// LIMITS OF t = 1. It needs the render loop's splat film and a perspective camera: a tile of the
// image (its film a window, integrators/renderer.h) and an orthographic camera leave it out, and say so in
// the render summary (and `fluence render` warns for tiles); the MIS weights then exclude it
// (bdpt_mis.h, StrategyPath::lightTracing) and the estimator stays unbiased for every path the
// other strategies can draw, as before t = 1 was added. A light seen directly is left to s = 0
// (no t = 1 with s = 1: point lights stay invisible, as in `path`). Under adaptive sampling
// (--target-error) t = 1 stays: each pixel's camera strategies are divided by its own samples and
// the splats by the image's mean light paths per pixel, and the MIS weights still sum to one, so
// the image is unbiased (the stopping rule reads the camera samples' statistics only). Light from
// cylinder and line lights (no emission sampling) is found by s = 0 and s = 1 alone.
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
// LIGHT PATH EXPRESSIONS (IntegratorSettings::lightPathAovs). Each strategy's path, read from the
// camera (integrators/bdpt_events.h), is classified as `path` classifies its paths
// (integrators/light_path_tracker.h): the camera subpath's events are followed vertex by vertex,
// each join continues through the joined vertices' and the light subpath's recorded events to its
// light, and the strategy's MIS-weighted light goes to every layer that accepts; t = 1 paths start
// at the camera and splat into the splat film's layers. Layers of a disjoint cover of every path
// sum to the beauty; no random number is drawn for them, so the beauty does not change.
//
// Paths hold at most maxDepth scattering vertices (s + t - 2, as `path` counts them; walk steps
// apart); both subpaths play Russian roulette (integrators/russian_roulette.h). Two-sided surfaces are
// shaded on the side a subpath arrives from, transmissive ones keep their orientation
// (render/bsdf.h, SIDES), and every join drops directions on which the shading frame and the
// surface disagree, as `path` does.
#pragma once

#include <memory>
#include <vector>

#include "integrators/integrator.h"
#include "integrators/light_path_tracker.h"

namespace fluence::integrators {

class Bdpt final : public Integrator {
public:
    explicit Bdpt(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth), aovs_(settings.lightPathAovs) {}

    // The per-render state: the choice of light for light subpaths, and light tracing's splat
    // film (t = 1 is left out without one, or with an orthographic camera, and the summary says why).
    std::unique_ptr<RenderState> prepare(const render::RenderScene& scene, const render::Camera& camera,
                                         std::uint64_t seed, SplatFilm* splats) const override;
    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override;
    // Light tracing (t = 1) splats into the film's splat film.
    bool usesSplats() const override { return true; }

private:
    int maxDepth_;
    std::shared_ptr<const std::vector<LightPathAov>> aovs_;  // null: none
};

}  // namespace fluence::integrators
