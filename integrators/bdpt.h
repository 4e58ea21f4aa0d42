// `bdpt`: bidirectional path tracing (Veach's thesis, ch. 10; Veach & Guibas 1995; pbrt's
// BDPTIntegrator, 3rd and 4th editions). Covers L(S|D)*E from lights that rays can hit; from
// delta lights (point, spot, line, angle-0 distant), every path whose first vertex is diffuse
// (LD(S|D)*E) or which holds two adjacent diffuse vertices (L(S|D)*DD(S|D)*E): so, unlike `path`,
// a point light's caustic once it lights another diffuse surface (LS+DD+E), but not the caustic
// seen directly or through mirrors (LS+DS*E), which needs t = 1 (below). No media.
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
// Paths hold at most maxDepth scattering vertices (s + t - 2, as `path` counts them); both
// subpaths play Russian roulette (integrators/first_hit.h). Two-sided surfaces are shaded on the
// side a subpath arrives from, transmissive ones keep their orientation (render/bsdf.h, SIDES),
// and every join drops directions on which the shading frame and the surface disagree, as `path`
// does. Participating media and subsurface scattering are not supported: a scene with media
// (RenderScene::hasMedia) is refused by prepare() with std::invalid_argument.
#pragma once

#include <vector>

#include "core/sampling.h"
#include "integrators/integrator.h"

namespace fluence::integrators {

class Bdpt final : public Integrator {
public:
    explicit Bdpt(const IntegratorSettings& settings) : maxDepth_(settings.maxDepth) {}

    // Refuses media; builds the choice of light for light subpaths.
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
