#include "integrators/naive_path_tracer.h"

#include <algorithm>

#include "core/frame.h"
#include "integrators/first_hit.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

FilmSample NaivePathTracer::sample(const render::RenderScene& scene, const render::Camera& camera,
                                   const render::Ray& cameraRay, SampleStream& rng, RenderCounters& counters) const {
    FilmSample out;
    RGB radiance(0.0f), throughput(1.0f);
    render::Ray ray = cameraRay;
    render::BsdfArena arena;
    float etaScale = 1.0f;  // product of eta^2 over the refractions so far (Russian roulette)
    for (int depth = 0;; ++depth) {
        ++(depth == 0 ? counters.camera : counters.bounce);
        std::optional<render::SurfaceHit> hit = scene.intersect(ray);
        if (!hit) {
            for (int index : scene.lightsAtInfinity()) radiance += throughput * scene.light(index).escaped(ray.direction);
            break;
        }
        Vec3f wo = -ray.direction;
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);
        if (hit->light >= 0)
            radiance += throughput * (hit->lightShape ? scene.light(hit->light).emitted({hit->point, hit->geometricNormal}, wo)
                                                      : hit->emission);
        if (hit->lightShape || depth >= maxDepth_) break;

        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const SurfaceFrame surface = shadingFrame(*hit, wo, (bsdf.flags() & render::kBsdfTransmission) != 0);
        const Vec3f woLocal = surface.frame.toLocal(wo);
        // A plain Lambertian has one lobe: no lobe number drawn.
        const float uLobe = bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, rng.next2D());
        if (!bs) break;
        Vec3f wi = surface.frame.toWorld(bs->wi);
        if (!sidesAgree(wo, wi, surface.geometricNormal, woLocal.z, bs->wi.z)) break;
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        etaScale *= bs->eta * bs->eta;
        if (!continuePath(throughput, etaScale, depth, rng)) break;
        ray = render::Ray{spawnOrigin(hit->point, surface.geometricNormal, wi), wi, 0.0f,
                          std::numeric_limits<float>::infinity()};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
