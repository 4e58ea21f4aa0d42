#include "integrators/naive_path_tracer.h"

#include <algorithm>
#include <utility>

#include "core/frame.h"
#include "integrators/diffusion_probe.h"
#include "integrators/emission.h"
#include "integrators/first_hit.h"
#include "integrators/medium_stack.h"
#include "integrators/russian_roulette.h"
#include "integrators/surface_frame.h"
#include "media/free_flight.h"
#include "media/phase.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

FilmSample NaivePathTracer::sample(const RenderState&, const render::RenderScene& scene, const render::Camera& camera,
                                   const render::Ray& cameraRay, SampleStream& rng, RenderCounters& counters) const {
    FilmSample out;
    RGB radiance(0.0f), throughput(1.0f);
    render::Ray ray = cameraRay;
    render::BsdfArena arena;
    float etaScale = 1.0f;  // product of eta^2 over the refractions so far (Russian roulette)
    // Through volumes: delta tracking alone, weighted as media/tracking.h's spectral MIS says
    // (with no light strategy, the weight of a contribution is 1 / channelAverage(rU)).
    MediumStack inside(scene);  // the media the path is in
    const bool spectral = scene.hasMedia();
    const int hero = spectral ? media::sampleHeroChannel(rng.next()) : 0;
    RGB rU(1.0f);
    auto weighted = [&](const RGB& le) { return spectral ? le / media::channelAverage(rU) : le; };
    int interiorScatterings = 0;
    std::optional<render::SurfaceHit> diffusionExit;  // as in path_tracer.cpp
    int fromLinkGroup = 0;  // of the geometry `ray` left (render/light_links.h); camera rays see every light
    for (int depth = 0;; ++depth) {
        const bool exiting = diffusionExit.has_value();
        std::optional<render::SurfaceHit> hit = std::exchange(diffusionExit, std::nullopt);
        if (!exiting) {
            ++(depth == 0 ? counters.camera : counters.bounce);
            hit = scene.intersect(ray);
        }
        if (const media::Medium* medium = exiting ? nullptr : inside.medium()) {
            media::FreeFlight flight = media::sampleFreeFlight(
                *medium, {ray.origin, ray.direction, hit ? hit->t : std::numeric_limits<float>::infinity()}, hero, rng);
            throughput *= flight.throughput;
            rU *= flight.pdfRatio;
            if (depth == 0 && flight.event != media::FlightEvent::Escaped)
                recordFirstVolumeEvent(out, flight.p, flight.properties.sigmaS,
                                       flight.properties.sigmaA + flight.properties.sigmaS, camera);
            if (flight.event == media::FlightEvent::Absorbed) {
                radiance += throughput * weighted(flight.properties.emission);
                break;
            }
            if (flight.event == media::FlightEvent::Scattered) {
                const bool walking = inside.depth() > 0;  // inside a material's interior (russian_roulette.h)
                if (walking ? ++interiorScatterings > kMaxInteriorScatterings : depth >= maxDepth_) break;
                media::PhaseSample ps =
                    media::HenyeyGreenstein(flight.properties.g).sample(-ray.direction, rng.next2D());
                if (ps.pdf <= 0.0f) break;
                throughput *= ps.p / ps.pdf;
                if (!continueInMedium(throughput, etaScale, depth, walking, rng)) break;
                ray = render::Ray{flight.p, ps.wi, 0.0f, std::numeric_limits<float>::infinity(), ray.time};
                fromLinkGroup = 0;
                depth -= walking;  // not a bounce
                continue;
            }
        }
        if (!hit) {
            forEachLightAtInfinity(scene, ray.direction, ray.time, depth == 0, [&](int index, const RGB& le) {
                if (scene.lightReaches(index, fromLinkGroup)) radiance += throughput * weighted(le);
            });
            break;
        }
        const Vec3f wo = exiting ? -hit->shadingNormal : -ray.direction;
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);
        if (!exiting && hit->light >= 0 && scene.lightReaches(hit->light, fromLinkGroup))
            radiance += throughput * weighted(emittedAtHit(scene, *hit, wo));
        if (hit->lightShape || depth >= maxDepth_) break;

        arena.reset();
        const render::Bsdf& bsdf =
            exiting ? render::subsurfaceExitBsdf(hit->material, arena) : render::materialBsdf(hit->material, arena);
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
        const DiffusionStep step = stepThroughDiffusion(scene, *hit, wo, wi, throughput, diffusionExit, rng, counters);
        if (step == DiffusionStep::Lost) break;
        if (step == DiffusionStep::Exited) continue;
        inside = inside.after(*hit, wo, wi);
        fromLinkGroup = hit->linkGroup;
        ray = render::Ray{spawnOrigin(hit->point, surface.geometricNormal, wi), wi, 0.0f,
                          std::numeric_limits<float>::infinity(), ray.time};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
