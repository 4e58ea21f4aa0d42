#include "integrators/path_tracer.h"

#include <algorithm>
#include <utility>

#include "core/frame.h"
#include "core/name_table.h"
#include "integrators/diffusion_probe.h"
#include "integrators/first_hit.h"
#include "integrators/light_path_tracker.h"
#include "integrators/medium_stack.h"
#include "media/free_flight.h"
#include "media/phase.h"
#include "media/ratio_tracking.h"
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

// The multiple-importance weights of a path, in the two forms the path tracer uses: Veach's power
// heuristic on scalar densities where the scene has no medium, and, with one, the balance
// heuristic in the spectral-MIS form of media/tracking.h (rU, rL: the path's densities under its
// own sampling and under light sampling of its last segment, over the hero channel's density).
struct MisState {
    const bool spectral;
    RGB rU{1.0f}, rL{1.0f};
    float bsdfPdf = 0.0f;  // scalar form: the density of the direction that produced the ray

    // The weight of emission Le reached by the ray, whose light strategy had density lightPdf;
    // `unique`: no light strategy could have produced it (camera ray, delta lobe).
    float emitter(float lightPdf, bool unique) const {
        if (!spectral) return unique ? 1.0f : powerHeuristic(bsdfPdf, lightPdf);
        return 1.0f / media::channelAverage(unique ? rU : rU + rL * lightPdf);
    }
    // The weight of a light sample of density lightPdf whose direction the BSDF or phase function
    // would have drawn with scatterPdf (0 for a delta light), through transmittance `tr`.
    RGB lightSample(float lightPdf, float scatterPdf, const media::TransmittanceEstimate& tr) const {
        if (!spectral) return RGB(scatterPdf > 0.0f ? powerHeuristic(lightPdf, scatterPdf) / lightPdf : 1.0f / lightPdf);
        return tr.throughput / media::channelAverage(rU * (tr.pdfRatio * lightPdf + tr.throughput * scatterPdf));
    }
    // The ray continues in a direction drawn with density pdf (a delta lobe's: its lobe probability).
    void scattered(float pdf) {
        bsdfPdf = pdf;
        rL = rU / pdf;
    }
};

// The event of a scattering in a medium (integrators/light_path_tracker.h).
PathEvent volumeEvent(bool subsurface) {
    return PathEvent{EventType::Volume, Scattering::Diffuse, subsurface ? "subsurface" : ""};
}

}  // namespace

void PathTracer::prepare(const render::RenderScene& scene, const render::Camera&, std::uint64_t) const {
    lightLabels_.clear();
    lightEvents_.clear();
    if (!aovs_ || aovs_->empty()) return;
    for (std::size_t i = 0; i < scene.lightCount(); ++i) lightLabels_.push_back(primName(scene.light(i).name()));
    for (std::size_t i = 0; i < scene.lightCount(); ++i) {
        const bool surface = scene.light(i).isSurfaceEmitter();
        lightEvents_.push_back(PathEvent{surface ? EventType::Object : EventType::Light, Scattering::None, lightLabels_[i]});
    }
}

FilmSample PathTracer::sample(const render::RenderScene& scene, const render::Camera& camera, const Ray& cameraRay,
                              SampleStream& rng, RenderCounters& counters) const {
    return scene.hasMedia() ? trace<true>(scene, camera, cameraRay, rng, counters)
                            : trace<false>(scene, camera, cameraRay, rng, counters);
}

template <bool kMedia>
FilmSample PathTracer::trace(const render::RenderScene& scene, const render::Camera& camera, const Ray& cameraRay,
                             SampleStream& rng, RenderCounters& counters) const {
    FilmSample out;
    RGB radiance(0.0f), throughput(1.0f);
    Ray ray = cameraRay;
    MediumStack inside(scene);  // the media the path is in
    const bool withMedia = kMedia && scene.hasMedia();  // trace<true> renders media-less scenes as trace<false> does
    MisState mis{withMedia};
    const int hero = withMedia ? media::sampleHeroChannel(rng.next()) : 0;
    bool specularBounce = false;  // `ray` left a delta lobe: no light strategy could have found it
    float etaScale = 1.0f;        // product of eta^2 over the refractions so far (Russian roulette)
    render::BsdfArena arena;
    Vec3f previousPoint = ray.origin, previousNormal(0.0f);
    const bool haveLights = !scene.lightSelection().empty();
    LightPathTracker lightPaths(aovs_ ? std::span<const LightPathAov>(*aovs_) : std::span<const LightPathAov>());
    if (lightPaths.active()) out.clearLightPaths(aovs_->size());

    // Next-event estimation from `from` (with `fromNormal` for the light tree): one light, its
    // shadow ray (from shadowFrom(wi), a point and the medium the ray starts in) through the
    // surfaces and the medium, weighted against the
    // scattering strategy; scatter(wi) gives the BSDF or phase value (cosine included) and its density,
    // and vertexEvents(wi) the vertex's events for the light path expressions.
    // Its random numbers are drawn even when it is not `enabled`, so that every vertex uses as many.
    auto sampleLight = [&](bool enabled, const Vec3f& from, const Vec3f& fromNormal, auto&& shadowFrom, auto&& scatter,
                           auto&& vertexEvents) {
        float uLight = rng.next();
        Vec2f uPoint = rng.next2D();
        if (!enabled) return;
        render::LightChoice choice = scene.chooseLight(from, fromNormal, uLight);
        if (choice.light < 0 || choice.probability <= 0.0f) return;
        std::optional<render::LightSample> ls = scene.light(choice.light).sample(from, uPoint);
        if (!ls || ls->pdf <= 0.0f || isBlack(ls->Li)) return;
        auto [f, scatterPdf] = scatter(ls->wi);
        if (isBlack(f)) return;
        ++counters.shadow;
        const auto [shadowOrigin, shadowMedium] = shadowFrom(ls->wi);
        if (scene.occluded(shadowOrigin, ls->wi, ls->distance)) return;
        media::TransmittanceEstimate tr;
        if (kMedia && shadowMedium) tr = media::ratioTrackingTransmittance(*shadowMedium, {shadowOrigin, ls->wi, ls->distance}, hero, rng);
        const RGB contribution = throughput * f * ls->Li * mis.lightSample(choice.probability * ls->pdf, ls->delta ? 0.0f : scatterPdf, tr);
        radiance += contribution;
        if (lightPaths.active()) lightPaths.connect(vertexEvents(ls->wi), lightEvents_[std::size_t(choice.light)], contribution, out);
    };
    // Emission `le` of light `index` reached by the ray (at `lh` on its shape, if it has one),
    // weighted against the light strategy unless only this path could have found it.
    auto addEmitted = [&](const RGB& le, int index, const LightHit& lh, int depth) {
        const bool unique = depth == 0 || specularBounce;
        float weight = mis.emitter(
            unique ? 0.0f : lightStrategyPdf(scene, index, previousPoint, previousNormal, ray.direction, lh), unique);
        radiance += throughput * le * weight;
        if (lightPaths.active()) lightPaths.reach(lightEvents_[std::size_t(index)], throughput * le * weight, out);
    };

    int interiorScatterings = 0;
    std::optional<SurfaceHit> diffusionExit;  // where diffusion subsurface scattering brings the path out
    for (int depth = 0;; ++depth) {
        // The next vertex: where the ray hits, or, after a diffusion entry, its exit (no ray traced).
        // (Initialised in place from either: a SurfaceHit is large, and copying it showed in profiles.)
        const bool exiting = kMedia && diffusionExit.has_value();
        if (!exiting) ++(depth == 0 ? counters.camera : counters.bounce);
        std::optional<SurfaceHit> hit = exiting ? std::exchange(diffusionExit, std::nullopt) : scene.intersect(ray);

        if (const media::Medium* medium = !kMedia || exiting ? nullptr : inside.medium()) {  // the stretch of medium up to the surface (or out of the scene)
            media::FreeFlight flight = media::sampleFreeFlight(
                *medium, {ray.origin, ray.direction, hit ? hit->t : std::numeric_limits<float>::infinity()}, hero, rng);
            throughput *= flight.throughput;
            mis.rU *= flight.pdfRatio;
            mis.rL *= flight.lightPdfRatio;
            if (depth == 0 && flight.event != media::FlightEvent::Escaped)
                recordFirstVolumeEvent(out, flight.p, flight.properties.sigmaS,
                                       flight.properties.sigmaA + flight.properties.sigmaS, camera);
            if (flight.event == media::FlightEvent::Absorbed) {
                const RGB emitted = throughput * flight.properties.emission / media::channelAverage(mis.rU);
                radiance += emitted;
                if (lightPaths.active()) lightPaths.reach(PathEvent{EventType::Object}, emitted, out);
                break;
            }
            if (flight.event == media::FlightEvent::Scattered) {
                const bool walking = inside.depth() > 0;  // inside a material's interior (first_hit.h)
                if (walking ? ++interiorScatterings > kMaxInteriorScatterings : depth >= maxDepth_) break;
                const Vec3f wo = -ray.direction;
                const media::HenyeyGreenstein phase(flight.properties.g);
                const VertexEvents event(volumeEvent(inside.inSubsurface()));
                // Inside a material's interior no light is sampled: the closed surface around the
                // point blocks every shadow ray but those to lights inside it, which phase sampling
                // still finds, then weighted as the only strategy (as after a delta lobe).
                sampleLight(haveLights && !walking, flight.p, Vec3f(0.0f), [&](const Vec3f&) { return std::pair(flight.p, medium); },
                            [&](const Vec3f& wi) {
                    float p = phase.p(wo, wi);
                    return std::pair(RGB(p), p);
                }, [&](const Vec3f&) { return event; });
                media::PhaseSample ps = phase.sample(wo, rng.next2D());
                if (ps.pdf <= 0.0f) break;
                throughput *= ps.p / ps.pdf;
                if (!continueInMedium(throughput, etaScale, depth, walking, rng)) break;
                lightPaths.scatter(event);
                mis.scattered(ps.pdf);
                specularBounce = walking;  // no light strategy at this vertex
                previousPoint = flight.p;
                previousNormal = Vec3f(0.0f);
                ray = Ray{flight.p, ps.wi, 0.0f, std::numeric_limits<float>::infinity()};
                depth -= walking;  // not a bounce
                continue;
            }
        }

        if (!hit) {
            for (int index : scene.lightsAtInfinity()) {
                RGB le = scene.light(index).escaped(ray.direction);
                if (!isBlack(le)) addEmitted(le, index, LightHit{}, depth);
            }
            break;
        }

        const Vec3f wo = exiting ? -hit->shadingNormal : -ray.direction;  // an exit is seen from inside
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);

        // Emission reached by this ray: light shapes and emissive surfaces.
        if (!exiting && hit->light >= 0) {
            LightHit lh{hit->point, hit->geometricNormal};
            RGB le = hit->lightShape ? scene.light(hit->light).emitted(lh, wo) : hit->emission;
            if (!isBlack(le)) addEmitted(le, hit->light, lh, depth);
        }
        if (hit->lightShape || depth >= maxDepth_) break;

        arena.reset();
        const render::Bsdf& bsdf =
            exiting ? render::subsurfaceExitBsdf(hit->material, arena) : render::materialBsdf(hit->material, arena);
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

        // Next-event estimation: one light, chosen by the light tree for this point and normal; the
        // shadow ray leaves a transmissive surface on the light's side, in the medium on that side.
        auto shadowFrom = [&](const Vec3f& wi) {
            return std::pair(transmissive ? spawnOrigin(hit->point, ng, wi) : lightFrom,
                             kMedia ? inside.after(*hit, wo, wi).medium() : nullptr);
        };
        sampleLight(haveLights && connectable, lightFrom, lightNormal, shadowFrom, [&](const Vec3f& wi) {
            Vec3f wiLocal = frame.toLocal(wi);
            bool agree = sidesAgree(wo, wi, ng, woLocal.z, wiLocal.z);
            return std::pair(agree ? bsdf.f(woLocal, wiLocal) * std::abs(wiLocal.z) : RGB(0.0f),
                             agree ? bsdf.pdf(woLocal, wiLocal) : 0.0f);
        }, [&](const Vec3f& wi) {
            const Vec3f wiLocal = frame.toLocal(wi);
            return VertexEvents(woLocal.z * wiLocal.z < 0.0f, bsdf.fByKind(woLocal, wiLocal));
        });

        // Continue the path by sampling the BSDF (a plain Lambertian has one lobe: no lobe number drawn).
        const float uLobe = bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, rng.next2D());
        if (!bs) break;
        Vec3f wi = frame.toWorld(bs->wi);
        if (!sidesAgree(wo, wi, ng, woLocal.z, bs->wi.z)) break;  // the shading frame disagrees with the surface
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        etaScale *= bs->eta * bs->eta;
        if (!continuePath(throughput, etaScale, depth, rng)) break;
        if (lightPaths.active()) {
            const bool transmitted = woLocal.z * bs->wi.z < 0.0f;
            lightPaths.scatter(bs->specular ? VertexEvents(PathEvent{transmitted ? EventType::Transmission : EventType::Reflection,
                                                                     Scattering::Singular})
                                            : VertexEvents(transmitted, bsdf.fByKind(woLocal, bs->wi)));
        }

        mis.scattered(bs->pdf);
        if constexpr (kMedia) {
            const DiffusionStep step = stepThroughDiffusion(scene, *hit, wo, wi, throughput, diffusionExit, rng, counters);
            if (step == DiffusionStep::Lost) break;
            if (step == DiffusionStep::Exited) {
                lightPaths.scatter(VertexEvents(volumeEvent(true)));
                continue;
            }
            inside = inside.after(*hit, wo, wi);
        }
        specularBounce = bs->specular;
        previousPoint = lightFrom;
        previousNormal = lightNormal;
        ray = Ray{spawnOrigin(hit->point, ng, wi), wi, 0.0f, std::numeric_limits<float>::infinity()};
    }
    out.radiance = radiance;
    return out;
}

template FilmSample PathTracer::trace<true>(const render::RenderScene&, const render::Camera&, const Ray&, SampleStream&,
                                           RenderCounters&) const;
template FilmSample PathTracer::trace<false>(const render::RenderScene&, const render::Camera&, const Ray&, SampleStream&,
                                            RenderCounters&) const;

}  // namespace fluence::integrators
