#include "integrators/direct_lighting.h"

#include <cmath>
#include <limits>
#include <optional>

#include "core/frame.h"
#include "core/sampling.h"
#include "integrators/emission.h"
#include "integrators/first_hit.h"
#include "integrators/medium_stack.h"
#include "integrators/russian_roulette.h"
#include "integrators/surface_frame.h"
#include "media/transmittance.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

using render::LightHit;
using render::Ray;
using render::SurfaceHit;

namespace {

// An unbiased estimate of the transmittance over `distance` from `origin` along `direction`
// through `medium` (1 where there is none): unbiased ray marching, with a hero channel of its own
// for a ray it cannot march (media/ray_marching_transmittance.h).
RGB transmittance(const media::Medium* medium, const Vec3f& origin, const Vec3f& direction, float distance,
                  SampleStream& rng) {
    if (!medium) return RGB(1.0f);
    const int hero = media::sampleHeroChannel(rng.next());
    return media::estimateTransmittance(media::TransmittanceMethod::RayMarching, *medium, {origin, direction, distance},
                                        hero, rng)
        .estimate();
}

}  // namespace

FilmSample directLightingThroughDeltaLobes(const render::RenderScene& scene, const render::Camera& camera,
                                           const Ray& cameraRay, SampleStream& rng, RenderCounters& counters,
                                           int maxDepth) {
    FilmSample out;
    RGB radiance(0.0f), throughput(1.0f);
    Ray ray = cameraRay;
    MediumStack inside(scene);  // the media the path is in
    render::BsdfArena arena;
    float etaScale = 1.0f;  // product of eta^2 over the refractions so far (Russian roulette)
    const bool haveLights = !scene.lightSelection().empty();
    // How `ray` was drawn: by the camera or a delta lobe (`unique`: no light sample could have
    // found what it reaches), or by a non-delta lobe with density bsdfPdf at a vertex whose lights
    // were chosen from `from` with `fromNormal` (its emission is weighted against that light
    // strategy, and the path ends at its next vertex).
    bool unique = true;
    float bsdfPdf = 0.0f;
    Vec3f from(0.0f), fromNormal(0.0f);
    int fromLinkGroup = 0;  // of the geometry `ray` left (render/light_links.h); camera rays see every light
    auto emitterWeight = [&](int light, const LightHit& lh) {
        if (!scene.lightReaches(light, fromLinkGroup)) return 0.0f;
        if (unique) return 1.0f;
        return powerHeuristic(bsdfPdf, lightStrategyPdf(scene, light, from, fromNormal, ray.direction, lh, ray.time));
    };

    for (int depth = 0;; ++depth) {
        ++(depth == 0 ? counters.camera : counters.bounce);
        const std::optional<SurfaceHit> hit = scene.intersect(ray);
        throughput *= transmittance(inside.medium(), ray.origin, ray.direction,
                                    hit ? hit->t : std::numeric_limits<float>::infinity(), rng);
        if (!hit) {
            forEachLightAtInfinity(scene, ray.direction, ray.time, depth == 0, [&](int index, const RGB& le) {
                radiance += throughput * le * emitterWeight(index, LightHit{});
            });
            break;
        }
        const Vec3f wo = -ray.direction;
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);
        if (hit->light >= 0) {
            const RGB le = emittedAtHit(scene, *hit, wo);
            if (!isBlack(le))
                radiance += throughput * le * emitterWeight(hit->light, LightHit{hit->point, hit->geometricNormal});
        }
        if (hit->lightShape || !unique || depth >= maxDepth) break;

        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const bool transmissive = (bsdf.flags() & render::kBsdfTransmission) != 0;
        const bool connectable = (bsdf.flags() & (render::kBsdfDiffuse | render::kBsdfGlossy)) != 0;
        const SurfaceFrame surface = shadingFrame(*hit, wo, transmissive);
        const Vec3f& ng = surface.geometricNormal;
        const Vec3f woLocal = surface.frame.toLocal(wo);
        // Lights are chosen from just off the surface on wo's side, or, for a transmissive surface
        // that gathers from both sides, from the point itself with no normal (as in `path`).
        const Vec3f lightFrom = transmissive ? hit->point : render::offsetRayOrigin(hit->point, ng);
        const Vec3f lightNormal = transmissive ? Vec3f(0.0f) : ng;

        // Next-event estimation: one light, its shadow ray through the surfaces and the medium on
        // the side it leaves by, weighted against BSDF sampling (fully for a delta light).
        auto sampleLight = [&]() -> RGB {
            const float uLight = rng.next();
            const Vec2f uPoint = rng.next2D();
            const render::LightChoice choice = scene.chooseLight(lightFrom, lightNormal, uLight);
            if (choice.light < 0 || choice.probability <= 0.0f) return RGB(0.0f);
            if (!scene.lightReaches(choice.light, hit->linkGroup)) return RGB(0.0f);  // linked away
            const std::optional<render::LightSample> ls =
                scene.lightAt(choice.light, ray.time).sample(lightFrom, uPoint);
            if (!ls || ls->pdf <= 0.0f || isBlack(ls->Li)) return RGB(0.0f);
            const Vec3f wiLocal = surface.frame.toLocal(ls->wi);
            if (!sidesAgree(wo, ls->wi, ng, woLocal.z, wiLocal.z)) return RGB(0.0f);
            const RGB f = bsdf.f(woLocal, wiLocal) * std::abs(wiLocal.z);
            if (isBlack(f)) return RGB(0.0f);
            ++counters.shadow;
            const Vec3f shadowOrigin = transmissive ? spawnOrigin(hit->point, ng, ls->wi) : lightFrom;
            const render::ShadowTest shadow =
                scene.shadowTest(choice.light, shadowOrigin, ls->wi, ls->distance, ray.time);
            if (shadow == render::ShadowTest::Blocked) return RGB(0.0f);
            const float lightPdf = choice.probability * ls->pdf;
            // Light that passed surfaces (render/shadow_rays.cpp) no BSDF-sampled ray finds: weight 1.
            const bool onlyStrategy = ls->delta || shadow == render::ShadowTest::PassedThrough;
            const float weight = onlyStrategy ? 1.0f : powerHeuristic(lightPdf, bsdf.pdf(woLocal, wiLocal));
            const RGB tr =
                transmittance(inside.after(*hit, wo, ls->wi).medium(), shadowOrigin, ls->wi, ls->distance, rng);
            return f * ls->Li * tr * (weight / lightPdf);
        };
        if (haveLights && connectable) radiance += throughput * sampleLight();

        // One BSDF sample: the ray that finds emission for MIS or, from a delta lobe, continues
        // the path (a plain Lambertian has one lobe: no lobe number drawn).
        const float uLobe = bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
        const std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, rng.next2D());
        if (!bs) break;
        const Vec3f wi = surface.frame.toWorld(bs->wi);
        if (!sidesAgree(wo, wi, ng, woLocal.z, bs->wi.z)) break;
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        etaScale *= bs->eta * bs->eta;
        if (bs->specular ? !continuePath(throughput, etaScale, depth, rng) : isBlack(throughput)) break;

        inside = inside.after(*hit, wo, wi);
        unique = bs->specular;
        bsdfPdf = bs->pdf;
        from = lightFrom;
        fromNormal = lightNormal;
        fromLinkGroup = hit->linkGroup;
        ray = Ray{spawnOrigin(hit->point, ng, wi), wi, 0.0f, std::numeric_limits<float>::infinity(), ray.time};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
