// Shadow rays of lights that some surfaces cast no shadow of (RenderScene::shadowTest,
// surfacesReached): UsdLux ShadowAPI's shadow:enable = false, and geometry a light's
// collection:shadowLink excludes (render/light_links.h).
//
// The rule every integrator follows: such a light's light reaches a surface point through the
// surfaces it casts no shadow of, as far as the first that does (for a shadowless light: through
// all of them). Next-event estimation is the only strategy that finds light passing a surface
// (a BSDF-sampled ray stops at the first surface it hits), so it counts that light with MIS weight 1
// (ShadowTest::PassedThrough) and the usual weight where nothing is in the way (Clear). So in `path`,
// `direct`, `whitted` and `bdpt` (its s = 1 strategy) the light passes surfaces, while BSDF-sampled
// rays, bdpt's light subpaths and its other strategies meet surfaces as always and find only the
// light that nothing blocks. `sppm`, which has no next-event estimation, deposits the photon of
// such a light's first segment on every surface the segment reaches (surfacesReached) and goes on
// from one of them; `radiosity` samples lights alone and counts the passed light in full. Only the
// segment leaving the light passes surfaces: light reflected by a surface is shadowed as usual.
#include <optional>
#include <vector>

#include "render/render_scene.h"

namespace fluence::render {

ShadowTest RenderScene::shadowTest(int light, const Vec3f& origin, const Vec3f& direction, float distance,
                                   float time) const {
    const bool surfaceInTheWay = occluded(origin, direction, distance, time);
    if (surfaceInTheWay && !lightPassesSurfaces(light)) return ShadowTest::Blocked;
    // Another light's shape ends a BSDF-sampled ray as a surface does: it blocks the shadow ray too,
    // unless the light casts no shadows at all (then only next-event estimation reaches past it).
    const bool shapeInTheWay = meetsOtherLightShape(light, origin, direction, distance, time);
    if (shapeInTheWay && !shadowless(light)) return ShadowTest::Blocked;
    if (!surfaceInTheWay) return shapeInTheWay ? ShadowTest::PassedThrough : ShadowTest::Clear;
    // The surfaces on the way, as far as the first that blocks this light (every one, at most
    // kMaxSurfacesPassed: more than that counts as blocked).
    const Ray segment{origin, direction, 0.0f, distance * (1.0f - kShadowRayShortening), time};
    const std::vector<SurfaceHit> reached = surfacesReached(light, segment);
    if (reached.size() >= std::size_t(kMaxSurfacesPassed)) return ShadowTest::Blocked;
    return !reached.empty() && blocksShadowsOf(light, reached.back()) ? ShadowTest::Blocked : ShadowTest::PassedThrough;
}

bool RenderScene::shadowless(int light) const {
    return static_cast<std::size_t>(light) < shadowless_.size() && shadowless_[std::size_t(light)];
}

bool RenderScene::blocksShadowsOf(int light, const SurfaceHit& hit) const {
    return !shadowless(light) && links_.shadows(light, hit.linkGroup);
}

std::vector<SurfaceHit> RenderScene::surfacesReached(int light, const Ray& ray) const {
    std::vector<SurfaceHit> reached;
    Ray next = ray;
    const bool passes = lightPassesSurfaces(light);
    for (int crossed = 0; crossed < kMaxSurfacesPassed; ++crossed) {
        std::optional<SurfaceHit> hit = intersect(next);
        if (!hit) break;
        const Vec3f& ng = hit->geometricNormal;
        const Vec3f onward = dot(ng, next.direction) > 0.0f ? ng : -ng;
        next.origin = offsetRayOrigin(hit->point, onward);
        next.tMin = 0.0f;
        next.tMax -= hit->t;
        if (hit->lightShape) continue;
        const bool blocks = !passes || blocksShadowsOf(light, *hit);
        reached.push_back(std::move(*hit));
        if (blocks) break;
    }
    return reached;
}

}  // namespace fluence::render
