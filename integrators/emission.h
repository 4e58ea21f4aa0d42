// Light a ray reaches, as every integrator finds it: the emission of the surface or light shape it
// hits, the lights at infinity (dome, distant) it meets when it leaves the scene, and the density
// with which next-event estimation would have sampled that light instead (for the MIS weight of
// emission reached by BSDF sampling).
#pragma once

#include "core/rgb.h"
#include "core/vec.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// Every light is taken where it is at the path's time in the shutter (RenderScene::lightAt): the
// hit's, or the ray's.

// The radiance towards wo of what `hit` emits: its light's shape, or an emissive surface (the
// hit's own emission, black on a surface that does not emit). Meaningful where hit.light >= 0 or
// hit.lightShape.
inline RGB emittedAtHit(const render::RenderScene& scene, const render::SurfaceHit& hit, const Vec3f& wo) {
    return hit.lightShape ? scene.lightAt(hit.light, hit.time).emitted({hit.point, hit.geometricNormal}, wo)
                          : hit.emission;
}

// Calls reached(index, le) for every light at infinity that sends radiance le (not black) along
// -direction to a ray that left the scene along `direction` at `time`, in the scene's order; a
// camera ray (straight from the camera) sees only those visible to the camera
// (RenderScene::lightsAtInfinity).
template <class Reached>
void forEachLightAtInfinity(const render::RenderScene& scene, const Vec3f& direction, float time, bool cameraRay,
                            Reached&& reached) {
    for (int index : scene.lightsAtInfinity(cameraRay)) {
        const RGB le = scene.lightAt(index, time).escaped(direction);
        if (!isBlack(le)) reached(index, le);
    }
}

// The density with which next-event estimation from `from` (with `fromNormal` for the light tree)
// would pick light `index` and sample direction wi towards `hit` on it, at `time`.
inline float lightStrategyPdf(const render::RenderScene& scene, int index, const Vec3f& from, const Vec3f& fromNormal,
                              const Vec3f& wi, const render::LightHit& hit, float time) {
    return scene.lightProbability(from, fromNormal, index) * scene.lightAt(index, time).pdf(from, wi, hit);
}

}  // namespace fluence::integrators
