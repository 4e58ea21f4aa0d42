// The geometry of scattering at a surface hit, as every surface integrator sees it: the shading
// frame (two-sided surfaces oriented towards the incoming ray, transmissive ones kept as they
// are), the check that a direction leaves on the side the shading frame says, where a ray leaving
// the hit starts, and Veach's shading-normal correction of the adjoint BSDF for paths that carry
// importance (light subpaths, photons).
#pragma once

#include <cmath>

#include "core/frame.h"
#include "render/ray.h"
#include "render/render_scene.h"

namespace fluence::integrators {
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

// Veach's correction (thesis, 1997, sec. 5.3, eq. 5.19) of the adjoint BSDF for shading normals,
// times |wi.ns|: |wo.ns| |wi.ng| / |wo.ng|, the cosine factor of importance (a light subpath, a
// photon) leaving along wi having arrived from wo (both world, away from the surface), with ns the
// shading normal and ng the geometric one. render/bsdf.h's f transports radiance; f(wi, wo) times
// this is the adjoint's value with its cosine.
inline float adjointShadingCosine(const Vec3f& wo, const Vec3f& wi, const Vec3f& ns, const Vec3f& ng) {
    const float woNg = std::abs(dot(wo, ng));
    return woNg > 0.0f ? std::abs(dot(wo, ns)) * std::abs(dot(wi, ng)) / woNg : 0.0f;
}

}  // namespace fluence::integrators
