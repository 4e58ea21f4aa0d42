// Pieces every surface integrator shares: the first-hit AOVs, the shading frame of a hit (two-
// sided surfaces oriented towards the incoming ray, transmissive ones kept as they are), the check
// that a direction leaves on the side the shading frame says, Russian roulette, and the budget of
// scatterings inside material interiors.
#pragma once

#include <algorithm>

#include "core/film.h"
#include "core/frame.h"
#include "core/random.h"
#include "render/camera.h"
#include "render/ray.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// Fills the AOVs of a camera sample from its first hit.
inline void recordFirstHit(FilmSample& out, const render::SurfaceHit& hit, const Vec3f& wo, const render::Camera& camera) {
    out.hit = true;
    out.depth = camera.viewDepth(hit.point);
    out.albedo = hit.material.diffuse;
    out.normal = dot(hit.shadingNormal, wo) < 0.0f ? -hit.shadingNormal : hit.shadingNormal;
    out.objectName = hit.objectName;
    out.materialName = hit.materialName;
}

// Fills the AOVs of a camera sample whose first event is a real collision in a volume at p: it
// counts as covered (so a pixel's alpha estimates the volume's opacity along it, 1 - T), with the
// medium's single-scattering albedo and no normal.
inline void recordFirstVolumeEvent(FilmSample& out, const Vec3f& p, const RGB& sigmaS, const RGB& sigmaT,
                                   const render::Camera& camera) {
    out.hit = true;
    out.depth = camera.viewDepth(p);
    for (int c = 0; c < 3; ++c) out.albedo[c] = sigmaT[c] > 0.0f ? sigmaS[c] / sigmaT[c] : 0.0f;
    out.normal = Vec3f(0.0f);
}

// The local shading frame of a hit, z along the shading normal and x along the surface's tangent
// where it has one (so anisotropic lobes follow the surface), with the geometric normal on the
// same side. Following render/bsdf.h ("SIDES"): for a reflection-only BSDF (two-sided) both are
// flipped to the side of wo; a transmissive BSDF is one-sided, so the surface's own orientation
// is kept: its normal's side is the outside, and wo may be below the frame.
struct SurfaceFrame {
    Frame frame;
    Vec3f geometricNormal;
};
inline SurfaceFrame shadingFrame(const render::SurfaceHit& hit, const Vec3f& wo, bool transmissive) {
    bool flip = !transmissive && dot(hit.geometricNormal, wo) < 0.0f;
    Vec3f ng = flip ? -hit.geometricNormal : hit.geometricNormal;
    Vec3f ns = flip ? -hit.shadingNormal : hit.shadingNormal;
    return {Frame::fromNormalAndTangent(ns, hit.tangent), ng};
}

// Whether wi (world) leaves the geometric surface on the side its local direction says: on wo's
// side for a reflection (wiLocalZ on wo's side of the shading frame), on the other side for a
// transmission. Shading normals can disagree with the geometry; following them there would let a
// reflection leak through the surface or a refraction turn back, so such directions are dropped
// (by next-event estimation as by BSDF sampling, so both strategies cover the same paths).
inline bool sidesAgree(const Vec3f& wo, const Vec3f& wi, const Vec3f& ng, float woLocalZ, float wiLocalZ) {
    float geometric = dot(wo, ng) * dot(wi, ng);
    return geometric != 0.0f && (geometric > 0.0f) == (woLocalZ * wiLocalZ > 0.0f);
}

// The origin of a ray leaving the hit point p along wi: offset off the surface to the side wi
// leaves by (through it, for a transmission).
inline Vec3f spawnOrigin(const Vec3f& p, const Vec3f& ng, const Vec3f& wi) {
    return render::offsetRayOrigin(p, dot(wi, ng) > 0.0f ? ng : -ng);
}

// Russian roulette after three bounces: survive with probability min(max(throughput x etaScale),
// 0.95) and reweight the survivors, which keeps the estimator unbiased. etaScale is the product of
// eta^2 over the path's refractions (BsdfSample::eta): radiance is scaled by 1 / eta^2 on entering
// a denser medium and back on leaving it (render/bsdf.h), which is no reason to end a path inside
// glass (pbrt-v4's rrBeta). Returns false to end the path.
inline bool continuePath(RGB& throughput, float etaScale, int depth, SampleStream& rng) {
    constexpr int kRouletteStartDepth = 3;
    constexpr float kMaxSurvival = 0.95f;
    if (isBlack(throughput)) return false;
    if (depth + 1 < kRouletteStartDepth) return true;
    float survive = std::min(maxComponent(throughput) * etaScale, kMaxSurvival);
    if (rng.next() >= survive) return false;
    throughput /= survive;
    return true;
}

// Scatterings inside a material's interior (MediumStack::depth() > 0: a subsurface walk, a murky
// liquid) are not bounces: a walk takes hundreds of steps. They count against their own budget of
// kMaxInteriorScatterings per path instead of maxDepth (a walk that reaches it ends and loses its
// light; the white furnaces of tests/integrators/subsurface_test.cpp, which would read below 1,
// show no such loss), and play no Russian roulette: delta
// tracking already ends walks by absorption, and continuePath's survival, capped at 0.95 per step,
// would end long walks and weigh the few survivors heavily.
inline constexpr int kMaxInteriorScatterings = 1024;

// Russian roulette after a scattering in a medium, inside an interior (`walking`) or not.
inline bool continueInMedium(RGB& throughput, float etaScale, int depth, bool walking, SampleStream& rng) {
    return walking ? !isBlack(throughput) : continuePath(throughput, etaScale, depth, rng);
}

}  // namespace fluence::integrators
