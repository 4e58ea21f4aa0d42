#include "integrators/path_tracer.h"

#include <algorithm>

#include "core/frame.h"
#include "integrators/first_hit.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

using render::LightHit;
using render::Ray;
using render::SurfaceHit;

namespace {

// Probability that next-event estimation picks light `index` and samples direction wi towards
// `hit` from `from`: the density the light strategy would have had for a BSDF-sampled hit.
float lightStrategyPdf(const render::RenderScene& scene, int index, const Vec3f& from, const Vec3f& fromNormal,
                       const Vec3f& wi, const LightHit& hit) {
    return scene.lightProbability(from, fromNormal, index) * scene.light(index).pdf(from, wi, hit);
}

}  // namespace

FilmSample PathTracer::sample(const render::RenderScene& scene, const render::Camera& camera, const Ray& cameraRay,
                              SampleStream& rng, RenderCounters& counters) const {
    FilmSample out;
    RGB radiance(0.0f), throughput(1.0f);
    Ray ray = cameraRay;
    float bsdfPdf = 0.0f;  // density of the BSDF sample that produced `ray` (0 for the camera ray)
    bool specularBounce = false;  // `ray` left a delta lobe: no light strategy could have found it
    render::BsdfArena arena;
    Vec3f previousPoint = ray.origin, previousNormal(0.0f);
    const bool haveLights = !scene.lightSelection().empty();

    for (int depth = 0;; ++depth) {
        ++(depth == 0 ? counters.camera : counters.bounce);
        std::optional<SurfaceHit> hit = scene.intersect(ray);

        if (!hit) {
            for (int index : scene.lightsAtInfinity()) {
                RGB le = scene.light(index).escaped(ray.direction);
                if (isBlack(le)) continue;
                float weight = depth == 0 || specularBounce
                                   ? 1.0f
                                   : powerHeuristic(bsdfPdf, lightStrategyPdf(scene, index, previousPoint, previousNormal,
                                                                              ray.direction, LightHit{}));
                radiance += throughput * le * weight;
            }
            break;
        }

        Vec3f wo = -ray.direction;
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);

        // Emission reached by this ray: light shapes and emissive surfaces.
        if (hit->light >= 0) {
            LightHit lh{hit->point, hit->geometricNormal};
            RGB le = hit->lightShape ? scene.light(hit->light).emitted(lh, wo) : hit->emission;
            if (!isBlack(le)) {
                float weight = depth == 0 || specularBounce
                                   ? 1.0f
                                   : powerHeuristic(bsdfPdf, lightStrategyPdf(scene, hit->light, previousPoint, previousNormal,
                                                                              ray.direction, lh));
                radiance += throughput * le * weight;
            }
        }
        if (hit->lightShape || depth >= maxDepth_) break;

        SurfaceFrame surface = orientTowards(*hit, wo);
        const Frame& frame = surface.frame;
        const Vec3f& ng = surface.geometricNormal;
        Vec3f woLocal = frame.toLocal(wo);
        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const bool connectable = (bsdf.flags() & (render::kBsdfDiffuse | render::kBsdfGlossy)) != 0;
        Vec3f origin = render::offsetRayOrigin(hit->point, ng);

        // Next-event estimation: one light, chosen by the light tree for this point and normal.
        if (haveLights && connectable) {
            float uLight = rng.next();
            Vec2f uPoint = rng.next2D();
            render::LightChoice choice = scene.chooseLight(origin, ng, uLight);
            const int index = choice.light;
            const float pick = choice.probability;
            std::optional<render::LightSample> ls;
            if (index >= 0 && pick > 0.0f) ls = scene.light(index).sample(origin, uPoint);
            if (ls && ls->pdf > 0.0f && !isBlack(ls->Li) && dot(ls->wi, ng) > 0.0f) {
                Vec3f wiLocal = frame.toLocal(ls->wi);
                RGB f = bsdf.f(woLocal, wiLocal) * std::abs(wiLocal.z);
                if (!isBlack(f)) {
                    ++counters.shadow;
                    if (!scene.occluded(origin, ls->wi, ls->distance)) {
                        float lightPdf = pick * ls->pdf;
                        float weight = ls->delta ? 1.0f : powerHeuristic(lightPdf, bsdf.pdf(woLocal, wiLocal));
                        radiance += throughput * f * ls->Li * (weight / lightPdf);
                    }
                }
            }
        } else {
            rng.next();
            rng.next2D();
        }

        // Continue the path by sampling the BSDF (a plain Lambertian has one lobe: no lobe number drawn).
        const float uLobe = bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, rng.next2D());
        if (!bs) break;
        Vec3f wi = frame.toWorld(bs->wi);
        if (dot(wi, ng) <= 0.0f) break;  // shading normal sent the path below the surface
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        if (!continuePath(throughput, depth, rng)) break;

        bsdfPdf = bs->pdf;
        specularBounce = bs->specular;
        previousPoint = origin;
        previousNormal = ng;
        ray = Ray{origin, wi, 0.0f, std::numeric_limits<float>::infinity()};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
