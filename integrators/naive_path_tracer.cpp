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

        SurfaceFrame surface = orientTowards(*hit, wo);
        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        // A plain Lambertian has one lobe: no lobe number drawn.
        const float uLobe = bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(surface.frame.toLocal(wo), uLobe, rng.next2D());
        if (!bs) break;
        Vec3f wi = surface.frame.toWorld(bs->wi);
        if (dot(wi, surface.geometricNormal) <= 0.0f) break;
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        if (!continuePath(throughput, depth, rng)) break;
        ray = render::Ray{render::offsetRayOrigin(hit->point, surface.geometricNormal), wi, 0.0f,
                          std::numeric_limits<float>::infinity()};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
