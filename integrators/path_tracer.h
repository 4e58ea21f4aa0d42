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
//
// SUBSURFACE. Where the camera ray enters a guided random-walk interior (render::SubsurfaceMethod::
// RandomWalkGuided, media/guided_walk.h), N walks leave from the entry (N = subsurfaceWalks_, the
// parameter "subsurface-walks", default 1): each samples a light at its exit with weight 1/N, and
// the path goes on past the first walk's exit only. Where a walk leaves (lit or in shadow) can be
// most of a translucent object's variance: N = 2 took the Cycles subsurface peer's relMSE x CPU to
// 0.90x, but the subsurface sample's to 1.07x (bench/results/2026-12-06-subsurface-4-s18.md).
// A walk draws its steps with one hero channel's coefficients and is weighted by MIS over whole
// walks (the parameter "walk-hero", default 1; 0: a channel per step; media/guided_walk.h, THE
// STEP AND ITS MIS); the N walks of an entry take stratified heroes.
//
// WALKS AFTER DIFFUSE (the parameter "walks-after-diffuse", default 1). With 0, a path that has
// scattered diffusely (a sample where the BSDF's diffuse part outweighs its glossy part, outside
// any interior; a walk's exit is one) no longer walks: a subsurface material it meets reflects its
// subsurface share as diffuse reflection of its subsurface colour, its other lobes unchanged
// (render::SubsurfaceShare::Diffuse; a thin wall, which no walk enters, is as before). This
// is what Cycles' Principled BSDF does on paths with a diffuse ancestor: biased (the walk's albedo
// and spread are not a diffuse lobe's; -2% in red on the Cycles subsurface peer), but the light a
// subsurface object sends to other surfaces then costs no walk and has several times less variance
// (bench/results/2026-12-06-floor-variance-s23.md). Camera rays and paths after glossy or specular
// bounces still walk.
//
// EXACT FLIGHTS (the parameter "exact-flights", default 3). Where the scene's volume has exact
// extinction (media/medium.h: grids without a colour grid or negative values, homogeneous media),
// free flights can be drawn by regular tracking instead of delta tracking (media/exact_tracking.h):
// 1, the camera ray's flight; 2, every flight through the scene's volume, with exact transmittance
// on the shadow rays that phase or BSDF sampling competes with (the two strategies' MIS weights are
// then both in classical path space: integrators/path_tracer.cpp, EXACT FLIGHTS); 3, also on the
// shadow rays to delta lights (ray-marched otherwise). Guided walks and interiors are tracked; in a
// scene with lights the equiangular strategy samples (local lights), a flight it is weighted
// against is tracked, and 2 and 3 act as 1. 0 is delta tracking everywhere. The default, 3, wins at
// equal CPU once a constant sky is left to phase sampling (render/dome_light_sampling.h, auto) and
// the cell walk takes Simpson's rule (volumes/trilinear_cells.h): on the Cycles peer's smoke, two
// interleaved runs of 8 and 6 seeds, level 3 has 0.97x level 2's relMSE (both runs) for 0.93-0.97x its
// CPU (relMSE x CPU 0.91-0.95x), level 1 1.25x level 2's (bench/results/2026-12-06-lead-s20.md;
// bench/results/2026-12-06-dome-sampling-s20.md for levels 0-3 before the cheaper walk, when 2 won). When the sky was sampled, 1 had won
// (bench/results/2026-12-06-exact-tracking-s19.md).
//
// Light path expression AOVs (IntegratorSettings::lightPathAovs): each camera sample follows its
// path's events through the expressions (integrators/light_path_tracker.h) and adds the light
// each matches to the sample's layers; the beauty is unchanged.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrators/equiangular_strategy.h"
#include "integrators/integrator.h"
#include "integrators/light_path_tracker.h"
#include "integrators/path_events.h"
#include "media/guided_walk.h"

namespace fluence::integrators {

class PathTracer final : public Integrator {
public:
    // Guided random walks per entry into a subsurface interior, unless the settings' parameter
    // "subsurface-walks" says otherwise (SUBSURFACE above).
    static constexpr int kDefaultSubsurfaceWalks = 1;
    static constexpr int kMaxSubsurfaceWalks = 64;  // the parameter's bound (integrators/registry.cpp)
    // Guided walks' channels unless the parameter "walk-hero" says otherwise: 1 a hero per walk,
    // 0 a channel per step (SUBSURFACE above).
    static constexpr int kDefaultWalkHero = 1;
    static constexpr int kDefaultWalksAfterDiffuse = 1;  // WALKS AFTER DIFFUSE above
    static constexpr int kDefaultExactFlights = 3;
    static constexpr int kMaxExactFlights = 3;  // the "exact-flights" levels (EXACT FLIGHTS above)

    explicit PathTracer(const IntegratorSettings& settings)
        : maxDepth_(settings.maxDepth),
          subsurfaceWalks_(walksPerEntry(settings.parameter("subsurface-walks", kDefaultSubsurfaceWalks))),
          walkChannels_(walkChannelsOf(settings.parameter("walk-hero", kDefaultWalkHero))),
          walksAfterDiffuse_(walksAfterDiffuseOf(settings.parameter("walks-after-diffuse", kDefaultWalksAfterDiffuse))),
          exactFlights_(exactFlightLevel(settings.parameter("exact-flights", kDefaultExactFlights))),
          aovs_(settings.lightPathAovs) {}

    // The per-render state: the lights' events for the light path expression AOVs (none without).
    std::unique_ptr<RenderState> prepare(const render::RenderScene& scene, const render::Camera& camera,
                                         std::uint64_t seed, SplatFilm* splats) const override;
    // trace<scene.hasMedia()>.
    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override;
    // The path tracer with (kMedia) or without the machinery of volumes and subsurface scattering:
    // free flights, ratio-tracked shadow rays (ray-marched where no strategy is weighted against
    // them: delta lights), the medium stack, spectral MIS, diffusion probes. A
    // scene without media pays for none of it; on such a scene both give the same image, bit for
    // bit (tests/integrators/path_tracer_test.cpp), and bench/media_overhead_bench.cpp times them.
    // `lightEvents`: the scene's (integrators/path_events.h) where there are light path expression
    // AOVs; unused without. `equiangularLights`: the scene's (integrators/equiangular_strategy.h),
    // used with kMedia.
    template <bool kMedia>
    FilmSample trace(const LightEvents& lightEvents, const EquiangularLights& equiangularLights,
                     const render::RenderScene& scene, const render::Camera& camera, const render::Ray& ray,
                     SampleStream& rng, RenderCounters& counters) const;

private:
    // The parameter "subsurface-walks" as a count; the CLI and the RenderSettings reader check it,
    // a program that builds IntegratorSettings itself gets this error instead of a cast of NaN.
    static int walksPerEntry(double value) {
        if (!(value >= 1.0 && value <= kMaxSubsurfaceWalks) || value != double(int(value)))
            throw std::invalid_argument("path: subsurface-walks must be a whole number from 1 to " +
                                        std::to_string(kMaxSubsurfaceWalks));
        return int(value);
    }
    static int exactFlightLevel(double value) {
        if (!(value >= 0.0 && value <= kMaxExactFlights) || value != double(int(value)))
            throw std::invalid_argument("path: exact-flights must be 0, 1, 2 or 3");
        return int(value);
    }
    static bool walksAfterDiffuseOf(double value) {
        if (value != 0.0 && value != 1.0) throw std::invalid_argument("path: walks-after-diffuse must be 0 or 1");
        return value == 1.0;
    }
    static media::WalkChannels walkChannelsOf(double value) {
        if (value != 0.0 && value != 1.0) throw std::invalid_argument("path: walk-hero must be 0 or 1");
        return value == 1.0 ? media::WalkChannels::Hero : media::WalkChannels::PerStep;
    }
    int maxDepth_;
    int subsurfaceWalks_;
    media::WalkChannels walkChannels_;
    bool walksAfterDiffuse_;
    int exactFlights_;
    std::shared_ptr<const std::vector<LightPathAov>> aovs_;  // null: none
};

}  // namespace fluence::integrators
