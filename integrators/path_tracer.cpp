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
    float etaScale = 1.0f;        // product of eta^2 over the refractions so far (Russian roulette)
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

        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const bool transmissive = (bsdf.flags() & render::kBsdfTransmission) != 0;
        const bool connectable = (bsdf.flags() & (render::kBsdfDiffuse | render::kBsdfGlossy)) != 0;
        const SurfaceFrame surface = shadingFrame(*hit, wo, transmissive);
        const Frame& frame = surface.frame;
        const Vec3f& ng = surface.geometricNormal;
        const Vec3f woLocal = frame.toLocal(wo);
        // Where lights are chosen and sampled from, with the normal the light tree weighs them by:
        // a two-sided surface gathers from wo's side, just off the surface; a transmissive one
        // from both sides, so from the point itself and with no normal (the tree then counts
        // lights on either side). BSDF-sampled hits on emitters use the same point and normal for
        // their MIS weight.
        const Vec3f lightFrom = transmissive ? hit->point : render::offsetRayOrigin(hit->point, ng);
        const Vec3f lightNormal = transmissive ? Vec3f(0.0f) : ng;

        // Next-event estimation: one light, chosen by the light tree for this point and normal.
        if (haveLights && connectable) {
            float uLight = rng.next();
            Vec2f uPoint = rng.next2D();
            render::LightChoice choice = scene.chooseLight(lightFrom, lightNormal, uLight);
            const int index = choice.light;
            const float pick = choice.probability;
            std::optional<render::LightSample> ls;
            if (index >= 0 && pick > 0.0f) ls = scene.light(index).sample(lightFrom, uPoint);
            if (ls && ls->pdf > 0.0f && !isBlack(ls->Li)) {
                Vec3f wiLocal = frame.toLocal(ls->wi);
                RGB f = sidesAgree(wo, ls->wi, ng, woLocal.z, wiLocal.z) ? bsdf.f(woLocal, wiLocal) * std::abs(wiLocal.z)
                                                                         : RGB(0.0f);
                if (!isBlack(f)) {
                    ++counters.shadow;
                    const Vec3f shadowFrom = transmissive ? spawnOrigin(hit->point, ng, ls->wi) : lightFrom;
                    if (!scene.occluded(shadowFrom, ls->wi, ls->distance)) {
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
        if (!sidesAgree(wo, wi, ng, woLocal.z, bs->wi.z)) break;  // the shading frame disagrees with the surface
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        etaScale *= bs->eta * bs->eta;
        if (!continuePath(throughput, etaScale, depth, rng)) break;

        bsdfPdf = bs->pdf;
        specularBounce = bs->specular;
        previousPoint = lightFrom;
        previousNormal = lightNormal;
        ray = Ray{spawnOrigin(hit->point, ng, wi), wi, 0.0f, std::numeric_limits<float>::infinity()};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
