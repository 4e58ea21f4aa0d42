// The first-hit AOVs of a camera sample (depth, albedo, normal, names), filled by every integrator
// from the first surface or volume event of its camera ray.
#pragma once

#include "core/film.h"
#include "render/camera.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// Fills the AOVs of a camera sample from its first hit.
inline void recordFirstHit(FilmSample& out, const render::SurfaceHit& hit, const Vec3f& wo,
                           const render::Camera& camera) {
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

}  // namespace fluence::integrators
