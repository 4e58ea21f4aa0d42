// Pieces every surface integrator shares: the first-hit AOVs, orienting a two-sided surface
// towards the incoming ray, and Russian roulette.
#pragma once

#include <algorithm>

#include "core/film.h"
#include "core/frame.h"
#include "core/random.h"
#include "render/camera.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// Fills the AOVs of a camera sample from its first hit.
inline void recordFirstHit(FilmSample& out, const render::SurfaceHit& hit, const Vec3f& wo, const render::Camera& camera) {
    out.hit = true;
    out.depth = camera.viewDepth(hit.point);
    out.albedo = hit.material.diffuse;
    out.normal = dot(hit.shadingNormal, wo) < 0.0f ? -hit.shadingNormal : hit.shadingNormal;
}

// Surfaces are two-sided: the shading frame and geometric normal flipped to the side of wo.
struct SurfaceFrame {
    Frame frame;
    Vec3f geometricNormal;
};
inline SurfaceFrame orientTowards(const render::SurfaceHit& hit, const Vec3f& wo) {
    bool flip = dot(hit.geometricNormal, wo) < 0.0f;
    Vec3f ng = flip ? -hit.geometricNormal : hit.geometricNormal;
    Vec3f ns = flip ? -hit.shadingNormal : hit.shadingNormal;
    return {Frame::fromNormal(ns), ng};
}

// Russian roulette after three bounces: survive with probability min(max throughput, 0.95) and
// reweight the survivors, which keeps the estimator unbiased. Returns false to end the path.
inline bool continuePath(RGB& throughput, int depth, SampleStream& rng) {
    constexpr int kRouletteStartDepth = 3;
    constexpr float kMaxSurvival = 0.95f;
    if (isBlack(throughput)) return false;
    if (depth + 1 < kRouletteStartDepth) return true;
    float survive = std::min(maxComponent(throughput), kMaxSurvival);
    if (rng.next() >= survive) return false;
    throughput /= survive;
    return true;
}

}  // namespace fluence::integrators
