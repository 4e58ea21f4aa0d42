#include "integrators/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "core/frame.h"
#include "integrators/diffusion_probe.h"
#include "integrators/emission.h"
#include "integrators/equiangular_strategy.h"
#include "integrators/first_hit.h"
#include "integrators/light_path_tracker.h"
#include "integrators/medium_stack.h"
#include "integrators/russian_roulette.h"
#include "integrators/surface_frame.h"
#include "media/exact_tracking.h"
#include "media/free_flight.h"
#include "media/guided_walk.h"
#include "media/phase.h"
#include "media/transmittance.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

using render::LightHit;
using render::Ray;
using render::SurfaceHit;

namespace {

// The multiple-importance weights of a path, in the two forms the path tracer uses: Veach's power
// heuristic on scalar densities, and the balance heuristic in the spectral-MIS form of
// media/tracking.h (rU, rL: the path's densities under its own sampling and under light sampling
// of its last segment, over the hero channel's density; rE: under equiangular sampling of its last
// medium vertex, integrators/equiangular_strategy.h). The spectral form is needed where the
// densities differ by channel: a scene with media (`spectral`), on a path that has met an event
// drawn by its hero channel (rU not 1 in every channel: a classic walk's or a volume's flight),
// whose last segment crosses a medium, or where the equiangular strategy competes. Elsewhere, in
// particular on the paths of a scene whose only media are guided subsurface walks (whose steps do
// not depend on the hero, pdfRatio 1), both strategies of a connection see the same scalar
// densities and take the power heuristic, as in a scene without media: the condition is the same
// from the light sample's side (rU at the vertex, the shadow ray's medium) and from the
// BSDF-sampled ray's (rU unchanged over a segment without a medium), so the two weights still add
// up to 1.
struct MisState {
    const bool spectral;
    RGB rU{1.0f}, rL{1.0f}, rE{0.0f};
    float bsdfPdf = 0.0f;          // scalar form: the density of the direction that produced the ray
    bool segmentInMedium = false;  // the ray's segment crosses a medium (set per segment by the path)

    // Whether a connection whose segment crosses a medium or not (`inMedium`), with equiangular
    // density equiangularPdf, takes the scalar form.
    bool scalar(bool inMedium, float equiangularPdf) const {
        return !spectral || (!inMedium && equiangularPdf == 0.0f && rU == RGB(1.0f));
    }
    // The weight of emission Le reached by the ray, whose light strategy had density lightPdf and
    // the equiangular strategy equiangularPdf (its distance's times the light's);
    // `unique`: no light strategy could have produced it (camera ray, delta lobe).
    float emitter(float lightPdf, float equiangularPdf, bool unique) const {
        if (scalar(segmentInMedium, equiangularPdf)) return unique ? 1.0f : powerHeuristic(bsdfPdf, lightPdf);
        return 1.0f / media::channelAverage(unique ? rU : rU + rL * lightPdf + rE * equiangularPdf);
    }
    // The weight of a light sample of density lightPdf whose direction the BSDF or phase function
    // would have drawn with scatterPdf (0 for a delta light), through transmittance `tr` of a
    // shadow ray that crosses a medium or not (`inMedium`); the equiangular strategy would have
    // drawn the vertex and the light's point with equiangularPdf.
    RGB lightSample(float lightPdf, float scatterPdf, const media::TransmittanceEstimate& tr, bool inMedium,
                    float equiangularPdf) const {
        if (scalar(inMedium, equiangularPdf))
            return RGB(scatterPdf > 0.0f ? powerHeuristic(lightPdf, scatterPdf) / lightPdf : 1.0f / lightPdf);
        return tr.throughput / media::channelAverage(rU * (tr.pdfRatio * lightPdf + tr.throughput * scatterPdf) +
                                                     rE * tr.pdfRatio * equiangularPdf);
    }
    // The ray continues in a direction drawn with density pdf (a delta lobe's: its lobe probability).
    void scattered(float pdf) {
        bsdfPdf = pdf;
        rL = rU / pdf;
        rE = rE / pdf;
    }
    // scattered(1.0f) without its divisions by 1 (exact: the same values, bit for bit).
    void scatteredWithDensityOne() {
        bsdfPdf = 1.0f;
        rL = rU;
    }
};

// A medium vertex drawn on `segment` at distance t, where the equiangular strategy applies.
struct EquiangularVertex {
    MediumSegment segment;
    float t = 0.0f;
};

// The per-render state (integrators/integrator.h).
struct PathTracerState final : RenderState {
    LightEvents lightEvents;
    EquiangularLights equiangularLights;  // in scenes with media
};

}  // namespace

std::unique_ptr<RenderState> PathTracer::prepare(const render::RenderScene& scene, const render::Camera&, std::uint64_t,
                                                 SplatFilm*) const {
    auto state = std::make_unique<PathTracerState>();
    if (aovs_ && !aovs_->empty()) state->lightEvents = LightEvents(scene);
    if (scene.hasMedia()) state->equiangularLights = EquiangularLights(scene);
    return state;
}

FilmSample PathTracer::sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                              const Ray& cameraRay, SampleStream& rng, RenderCounters& counters) const {
    const auto& s = static_cast<const PathTracerState&>(state);
    return scene.hasMedia() ? trace<true>(s.lightEvents, s.equiangularLights, scene, camera, cameraRay, rng, counters)
                            : trace<false>(s.lightEvents, s.equiangularLights, scene, camera, cameraRay, rng, counters);
}

namespace {

enum class Step {
    Next,     // on to the path's next vertex
    Reached,  // through the medium to the surface the ray hit (or out of the scene)
    End,      // the path ends
};

// A surface vertex of the path, as next-event estimation and BSDF sampling see it.
struct SurfaceVertex {
    const SurfaceHit& hit;
    Vec3f wo;
    const render::Bsdf& bsdf;
    unsigned flags;  // bsdf.flags(), asked once (a virtual call)
    bool transmissive, connectable;
    SurfaceFrame surface;  // the shading frame, and the geometric normal on its side
    Vec3f woLocal;
    // Where lights are chosen and sampled from, with the normal the light tree weighs them by:
    // a two-sided surface gathers from wo's side, just off the surface; a transmissive one
    // from both sides, so from the point itself and with no normal (the tree then counts
    // lights on either side). BSDF-sampled hits on emitters use the same point and normal for
    // their MIS weight.
    Vec3f lightFrom, lightNormal;
};

SurfaceVertex surfaceVertex(const SurfaceHit& hit, const Vec3f& wo, const render::Bsdf& bsdf) {
    const unsigned flags = bsdf.flags();
    const bool transmissive = (flags & render::kBsdfTransmission) != 0;
    const bool connectable = (flags & (render::kBsdfDiffuse | render::kBsdfGlossy)) != 0;
    const SurfaceFrame surface = shadingFrame(hit, wo, transmissive);
    const Vec3f& ng = surface.geometricNormal;
    return {hit,
            wo,
            bsdf,
            flags,
            transmissive,
            connectable,
            surface,
            surface.frame.toLocal(wo),
            transmissive ? hit.point : render::offsetRayOrigin(hit.point, ng),
            transmissive ? Vec3f(0.0f) : ng};
}

// One camera sample of `path` (PathTracer::trace), vertex by vertex: through media, out of the
// scene, at surfaces; with next-event estimation at every vertex that allows it.
template <bool kMedia>
class PathWalk {
public:
    PathWalk(const LightEvents& lightEvents, const EquiangularLights& equiangularLights,
             std::span<const LightPathAov> aovs, int maxDepth, int walksPerEntry, media::WalkChannels walkChannels,
             bool walksAfterDiffuse, int exactFlights, const render::RenderScene& scene, const render::Camera& camera,
             const Ray& cameraRay, SampleStream& rng, RenderCounters& counters)
        : lightEvents_(lightEvents),
          equiangularLights_(equiangularLights),
          maxDepth_(maxDepth),
          walksPerEntry_(walksPerEntry),
          walkChannels_(walkChannels),
          walksAfterDiffuse_(walksAfterDiffuse),
          exactFlights_(exactFlights),
          exactEverywhere_(exactFlights >= 2 && !equiangularLights.any()),
          scene_(scene),
          camera_(camera),
          rng_(&rng),
          pathRng_(&rng),
          walkRng_(rng),
          counters_(counters),
          ray_(cameraRay),
          inside_(scene),
          mis_{kMedia && scene.hasMedia()},
          hero_(mis_.spectral ? media::sampleHeroChannel(rng.next()) : 0),
          previousPoint_(cameraRay.origin),
          haveLights_(!scene.lightSelection().empty()),
          lightPaths_(aovs) {
        if (lightPaths_.active()) out_.clearLightPaths(aovs.size());
    }

    // The path from its vertex `firstDepth` on (0: the camera ray's hit; a split walk starts deeper).
    FilmSample run(int firstDepth = 0) {
        for (int depth = firstDepth;; ++depth) {
            // The next vertex: where the ray hits, or, after a diffusion entry, its exit (no ray traced).
            // (Initialised in place from either: a SurfaceHit is large, and copying it showed in profiles.)
            const bool exiting = kMedia && diffusionExit_.has_value();
            if (!exiting) ++(depth == 0 ? counters_.camera : counters_.bounce);
            if (kMedia && guidedWalk_ && !exiting) startWalkStep();
            std::optional<SurfaceHit> hit = exiting ? std::exchange(diffusionExit_, std::nullopt)
                                            : kMedia && guidedWalk_ && walkStep_.first ? entryStepHit()
                                                                                       : scene_.intersect(ray_);
            const media::Medium* medium = !kMedia || exiting ? nullptr : inside_.medium();
            mis_.segmentInMedium = medium != nullptr;
            if (medium) {
                const Step step = throughMedium(*medium, hit, depth);
                if (step == Step::End) break;
                if (step == Step::Next) continue;
            }
            if (!hit) {
                throughput_ *= std::exchange(exitShare_, 1.0f);  // a split walk's end (splitWalk)
                forEachLightAtInfinity(scene_, ray_.direction, ray_.time, depth == 0,
                                       [&](int index, const RGB& le) { addEmitted(le, index, LightHit{}, depth); });
                break;
            }
            if (atSurface(*hit, exiting, depth) == Step::End) break;
        }
        // The radiance stored into the returned copy, not into out_ before copying it: the copy's
        // 16-byte loads of out_ would read a store still in flight, which the processor cannot
        // forward (a stall per sample).
        FilmSample sample = out_.withLightPaths(lightPaths_.layers());
        sample.radiance = radiance_;
        return sample;
    }

private:
    // The stretch of medium up to the surface hit (or out of the scene): a free flight that passes
    // (Reached), is absorbed (its emission; End), or scatters (scatterInMedium).
    Step throughMedium(const media::Medium& medium, const std::optional<SurfaceHit>& hit, int& depth) {
        const float tBoundary = hit ? hit->t : std::numeric_limits<float>::infinity();
        const RGB rUBefore = mis_.rU, throughputBefore = throughput_;
        if (guidedWalk_) ++counters_.walkSteps;  // a guided subsurface walk's step (integrators/sample_cost.h)
        const std::optional<MediumSegment> segment =
            equiangularApplies(depth) ? mediumSegment(medium, ray_.origin, ray_.direction, tBoundary) : std::nullopt;
        if (segment) sampleEquiangular(medium, *segment);
        const media::MediumRay ray{ray_.origin, ray_.direction, tBoundary};
        const bool exact = !guidedWalk_ && exactFlight(medium, depth, segment.has_value());
        media::FreeFlight flight = guidedWalk_ ? guidedWalk_->fly(walkStep_, walkLength_, tBoundary, *rng_)
                                   : exact     ? media::sampleExactFlight(medium, ray, hero_, rng_->next())
                                               : freeFlight(medium, ray);
        (exact ? counters_.exactCells : counters_.mediumCollisions) += std::uint64_t(flight.collisions);
        counters_.exactFlights += exact ? 1 : 0;
        throughput_ *= flight.throughput;
        mis_.rU *= flight.pdfRatio;
        mis_.rL *= flight.lightPdfRatio;
        mis_.rE *= flight.lightPdfRatio;
        if (flight.event != media::FlightEvent::Escaped) {  // a new medium vertex (or the path's end)
            mis_.rE = segment ? rUBefore * flight.ratioTrackedPdfRatio : RGB(0.0f);
            equiangularVertex_ = segment ? std::optional(EquiangularVertex{*segment, flight.t}) : std::nullopt;
        }
        if (depth == 0 && flight.event != media::FlightEvent::Escaped)
            recordFirstVolumeEvent(out_, flight.p, flight.properties.sigmaS,
                                   flight.properties.sigmaA + flight.properties.sigmaS, camera_);
        if (flight.event == media::FlightEvent::Absorbed) {
            throughput_ *= std::exchange(exitShare_, 1.0f);  // a split walk's end (splitWalk)
            addMediumEmission(throughput_ * flight.properties.emission);
            return Step::End;
        }
        // An exact flight's point also scores absorption's emission (media/exact_tracking.h).
        if (flight.event == media::FlightEvent::Scattered && !isBlack(flight.absorbedThroughput) &&
            !isBlack(flight.properties.emission))
            addMediumEmission(throughputBefore * flight.absorbedThroughput * flight.properties.emission);
        if (flight.event == media::FlightEvent::Scattered) return scatterInMedium(flight, medium, depth);
        if (guidedWalk_) rng_ = pathRng_;  // the walk reached its boundary: the path's slots again
        return Step::Reached;
    }

    // A free flight whose events take one dimension of the sample (stratified under Sobol) and whose
    // exponential steps draw from an independent stream, so that the decisions after it keep their
    // dimensions whatever the number of tentative collisions (media/free_flight.h). Without it the
    // slots after the first medium segment differed between a pixel's samples, and Sobol sampling
    // rendered the Cycles peer's smoke with 0.92 of independent sampling's error per sample
    // (bench/results/2026-12-06-smoke-variance.md).
    media::FreeFlight freeFlight(const media::Medium& medium, const media::MediumRay& ray) {
        const float uEvent = rng_->next();
        SampleStream steps = rng_->independentStream();
        return media::sampleFreeFlight(medium, ray, hero_, uEvent, steps);
    }

    // Emission of the medium, f / p_h of the path that ends absorbed at a medium point: no other
    // strategy finds such a path, so it takes the spectral weight of its own density alone.
    void addMediumEmission(const RGB& weighted) {
        const RGB emitted = weighted / media::channelAverage(mis_.rU);
        radiance_ += emitted;
        if (lightPaths_.active()) lightPaths_.reach(PathEvent{EventType::Object}, emitted, out_);
    }

    // EXACT FLIGHTS (integrators/path_tracer.h): whether the flight through `medium` at `depth` is
    // drawn by regular tracking (media/exact_tracking.h). Only in the scene's volume with exact
    // extinction, outside interiors and guided walks, where the equiangular strategy (whose
    // weights read ratio-tracked densities) does not sample the stretch.
    //   Why the weights still sum to one. Where every flight and the competing shadow rays are
    // exact (exactEverywhere_), a path's densities are classical: an escaped flight has density
    // P_c = T_c (no null points), the light strategy draws the same path with the prefix's density
    // times lightPdf (its shadow ray's T_c is in its contribution, not its density). With the
    // prefix's ratios rU, phase sampling's contribution beta phase/pdf (T_c/T_h) Le is weighted by
    // 1 / avg(rU T_c/T_h + (rU / pdf)(1 / T_h) lightPdf) (rL = rU / pdf times the flight's
    // lightPdfRatio 1/T_h), i.e. it scores beta phase T_c Le / avg(rU (pdf T_c + lightPdf)); the
    // light sample scores beta phase T_c Le / avg(rU (lightPdf + T_c pdf)) (MisState::lightSample
    // with tr = (T_c, 1)). The two share one denominator, the sum over both strategies of their
    // densities of the path, so their weights are the balance heuristic's and add up to one in
    // every channel. Where only the camera ray's flight is exact (level 1), no strategy competes
    // with it (a camera ray's emitter is unique), and the vertices after it are tracked as before.
    bool exactFlight(const media::Medium& medium, int depth, bool equiangular) const {
        if (!kMedia || exactFlights_ == 0 || guidedWalk_ || inside_.depth() > 0 || equiangular) return false;
        return exactSceneVolume(medium) && (depth == 0 || exactEverywhere_);
    }

    // Whether `medium` is the scene's volume and its extinction is exact (exactFlight, exactShadow).
    bool exactSceneVolume(const media::Medium& medium) const {
        return &medium == scene_.medium() && medium.hasExactExtinction();
    }

    // Whether the shadow ray through `medium` takes exact transmittance (EXACT FLIGHTS): where the
    // flights through it are exact and phase or BSDF sampling competes with it, or, at level 3, to
    // delta lights too.
    bool exactShadow(const media::Medium& medium, bool onlyStrategy) const {
        return kMedia && exactEverywhere_ && (!onlyStrategy || exactFlights_ >= 3) && exactSceneVolume(medium);
    }

    // Whether the equiangular strategy samples the stretch of the ray through the medium the path
    // is in: in the scene's volumes (not a material's interior), where a scattering would still
    // sample a light (depth below maxDepth), in a scene with a light that has a position.
    bool equiangularApplies(int depth) const {
        return kMedia && equiangularLights_.any() && haveLights_ && !guidedWalk_ && inside_.depth() == 0 &&
               depth < maxDepth_;
    }

    // The equiangular strategy on `segment` (integrators/equiangular_strategy.h): a light, a
    // distance drawn about it, the transmittance to that point by ratio tracking, and next-event
    // estimation of the light from there, weighted against the free flight's two strategies.
    // Draws four numbers, then those of its ratio tracking.
    void sampleEquiangular(const media::Medium& medium, const MediumSegment& segment) {
        const float uLight = rng_->next(), uDistance = rng_->next();
        const Vec2f uPoint = rng_->next2D();
        const std::optional<EquiangularChoice> choice = equiangularLights_.choose(scene_, segment, uLight);
        if (!choice || !scene_.lightReaches(choice->light, 0)) return;
        const float t = choice->distance.sample(uDistance);
        const float distancePdf = choice->probability * choice->distance.pdf(t);
        if (!(distancePdf > 0.0f)) return;
        const Vec3f p = segment.origin + segment.direction * t;
        const media::MediumProperties m = medium.at(p);
        ++counters_.mediumCollisions;
        if (isBlack(m.sigmaS)) return;  // empty space within the segment: no transmittance to estimate
        SampleStream tracking = rng_->independentStream();
        const media::TransmittanceEstimate toPoint =
            media::ratioTrackingTransmittance(medium, {segment.origin, segment.direction, t}, hero_, tracking);
        counters_.mediumCollisions += std::uint64_t(toPoint.collisions);
        if (isBlack(toPoint.throughput)) return;
        std::optional<render::LightSample> ls = scene_.lightAt(choice->light, ray_.time).sample(p, uPoint);
        if (!ls || ls->pdf <= 0.0f || isBlack(ls->Li)) return;
        const Vec3f wo = -segment.direction;
        const float phase = media::HenyeyGreenstein(m.g).p(wo, ls->wi);
        ++counters_.shadow;
        const render::ShadowTest shadow = scene_.shadowTest(choice->light, p, ls->wi, ls->distance, ray_.time);
        if (shadow == render::ShadowTest::Blocked) return;
        const bool onlyStrategy = ls->delta || shadow == render::ShadowTest::PassedThrough;
        const media::TransmittanceEstimate toLight =
            shadowTransmittance(medium, {p, ls->wi, ls->distance}, onlyStrategy);
        // Densities over the hero's density of this strategy, per channel (equiangular_strategy.h).
        const RGB freeFlightPdf = mis_.rU * toPoint.throughput * m.sigmaS;
        const RGB equiangularPdf = mis_.rU * toPoint.pdfRatio * distancePdf;
        const float treePdf = scene_.lightProbability(p, Vec3f(0.0f), choice->light);
        const RGB lightStrategies = toLight.pdfRatio * ls->pdf * (equiangularPdf + freeFlightPdf * treePdf);
        const RGB phaseStrategy = onlyStrategy ? RGB(0.0f) : freeFlightPdf * phase * toLight.throughput;
        const RGB contribution = throughput_ * toPoint.throughput * m.sigmaS * (phase * ls->Li) * toLight.throughput /
                                 media::channelAverage(lightStrategies + phaseStrategy);
        radiance_ += contribution;
        if (lightPaths_.active())
            lightPaths_.connect(VertexEvents(volumeEvent(false)), lightEvents_[choice->light], contribution, out_);
    }

    // The transmittance of a shadow ray through `medium`, its lookups counted: ray marching where no
    // strategy is weighted against the connection (`onlyStrategy`: a delta light, light that passed
    // surfaces), else ratio tracking, whose null points the MIS weight needs (media/transmittance.h).
    // Its numbers come from an independent stream, as the free flight's steps do (freeFlight).
    // The free flight's and the equiangular strategy's light samples both take it, so the two
    // strategies' weights read the same shadow-ray densities.
    media::TransmittanceEstimate shadowTransmittance(const media::Medium& medium, const media::MediumRay& ray,
                                                     bool onlyStrategy) {
        if (exactShadow(medium, onlyStrategy)) {
            const media::TransmittanceEstimate exact = media::exactTransmittance(medium, ray);
            counters_.exactCells += std::uint64_t(exact.collisions);
            ++counters_.exactFlights;
            return exact;
        }
        SampleStream tracking = rng_->independentStream();
        const media::TransmittanceEstimate tr = media::estimateTransmittance(
            onlyStrategy ? media::TransmittanceMethod::RayMarching : media::TransmittanceMethod::RatioTracking, medium,
            ray, hero_, tracking);
        counters_.mediumCollisions += std::uint64_t(tr.collisions);
        return tr;
    }

    // The equiangular strategy's density of light `index` and of the medium vertex the path is at
    // (or left last), per unit length (times the light's own density of its point, it is the
    // strategy's equiangularPdf of MisState); 0 where the strategy does not apply.
    float equiangularDistancePdf(int index) const {
        if (!kMedia || !equiangularVertex_) return 0.0f;
        return equiangularLights_.pdf(scene_, equiangularVertex_->segment, index, equiangularVertex_->t);
    }

    // A guided walk's step draws its length first, and its ray is traced only that far: no surface
    // is shaded unless the walk leaves (media/guided_walk.h, THE COST OF A STEP). The entry's step
    // is traced on to the far side, for backward guiding.
    void startWalkStep() {
        walkLength_ = guidedWalk_->sampleLength(walkStep_, rng_->next());
        if (!walkStep_.first) ray_.tMax = walkLength_;
    }

    // The hit of a guided walk's entry step (startWalkStep), traced on to the far side, whose
    // distance guides the walk backwards (media/guided_walk.h): shaded only when the step reaches it.
    // A step that collides before it needs no hit (its flight then has no boundary within its
    // length, which is all the flight reads of it), and the far side's shading showed in profiles.
    std::optional<SurfaceHit> entryStepHit() {
        const render::TracedHit far = scene_.trace(ray_);
        if (far.met()) guidedWalk_->sawFarSide(ray_.direction, far.t);
        if (walkLength_ < far.t) return std::nullopt;
        return scene_.shade(far, ray_);
    }

    // A scattering in a medium: next-event estimation, then phase sampling.
    Step scatterInMedium(const media::FreeFlight& flight, const media::Medium& medium, int& depth) {
        const bool walking = inside_.depth() > 0;  // inside a material's interior (russian_roulette.h)
        if (walking ? ++interiorScatterings_ > kMaxInteriorScatterings : depth >= maxDepth_) return Step::End;
        const Vec3f wo = -ray_.direction;
        const media::HenyeyGreenstein phase(flight.properties.g);
        const VertexEvents event(volumeEvent(inside_.inSubsurface()));
        // Inside a material's interior no light is sampled: the closed surface around the
        // point blocks every shadow ray but those to lights inside it, which phase sampling
        // still finds, then weighted as the only strategy (as after a delta lobe).
        const bool lightSampled = haveLights_ && !walking;
        const LightNumbers u = lightNumbers(lightSampled);
        sampleLight(
            lightSampled, u.light, u.point, flight.p, Vec3f(0.0f), 0,
            [&](const Vec3f&) { return std::pair(flight.p, &medium); },
            [&](const Vec3f& wi) {
                float p = phase.p(wo, wi);
                return std::pair(RGB(p), p);
            },
            [&](const Vec3f&) { return event; });
        media::PhaseSample ps;
        if (guidedWalk_) {  // the step's phase value and density weigh its flight (media/guided_walk.h)
            // Under a hero the step's channel is the walk's: its number's dimension is taken, not computed.
            float uChannel = 0.0f;
            if (guidedWalk_->hasHero())
                rng_->skip();
            else
                uChannel = rng_->next();
            const int channel = guidedWalk_->stepChannel(uChannel);
            const float uStrategy = rng_->next();
            walkStep_ = guidedWalk_->sampleStep(flight.p, wo, channel, uStrategy, rng_->next2D());
            ps = {walkStep_.wi, 1.0f, 1.0f};
        } else {
            ps = phase.sample(wo, rng_->next2D());
        }
        if (ps.pdf <= 0.0f) return Step::End;
        // A guided step's value and density are its flight's (ps.p = ps.pdf = 1): the throughput and
        // the MIS ratios would be multiplied and divided by 1, which leaves them as they are, bit for bit.
        if (!guidedWalk_) throughput_ *= ps.p / ps.pdf;
        if (!continueInMedium(throughput_, etaScale_, depth, walking, *rng_)) return Step::End;
        lightPaths_.scatter(event);
        if (guidedWalk_)
            mis_.scatteredWithDensityOne();
        else
            mis_.scattered(ps.pdf);
        specularBounce_ = walking;  // no light strategy at this vertex
        previousPoint_ = flight.p;
        previousNormal_ = Vec3f(0.0f);
        previousLinkGroup_ = 0;
        continueRay(flight.p, ps.wi);
        depth -= walking;  // not a bounce
        return Step::Next;
    }

    // A surface vertex (or, `exiting`, the exit of a diffusion step): its emission, then
    // next-event estimation and BSDF sampling. At the exit of a walk split N ways (splitWalk), what
    // every walk of the entry estimates there, the emission its ray reaches and the light sample,
    // takes this walk's share 1/N; what follows the exit is this walk's alone, at full weight.
    Step atSurface(const SurfaceHit& hit, bool exiting, int depth) {
        const Vec3f wo = exiting ? -hit.shadingNormal : -ray_.direction;  // an exit is seen from inside
        if (depth == 0) recordFirstHit(out_, hit, wo, camera_);
        const RGB throughputOnward = throughput_;
        throughput_ *= std::exchange(exitShare_, 1.0f);
        // Emission reached by this ray: light shapes and emissive surfaces.
        if (!exiting && hit.light >= 0) {
            const RGB le = emittedAtHit(scene_, hit, wo);
            if (!isBlack(le)) addEmitted(le, hit.light, LightHit{hit.point, hit.geometricNormal}, depth);
        }
        equiangularVertex_.reset();  // a surface vertex: the strategy of a medium's does not apply
        mis_.rE = RGB(0.0f);
        if (hit.lightShape || depth >= maxDepth_) return Step::End;
        arena_.reset();
        // WALKS AFTER DIFFUSE (path_tracer.h): diffuseAncestor_ is only ever set without walksAfterDiffuse_.
        const bool asDiffuse =
            diffuseAncestor_ && !exiting && hit.material.subsurface > 0.0f && (!kMedia || inside_.depth() == 0);
        const SurfaceVertex v =
            surfaceVertex(hit, wo,
                          exiting     ? render::subsurfaceExitBsdf(hit.material, arena_)
                          : asDiffuse ? render::materialBsdf(hit.material, arena_, render::SubsurfaceShare::Diffuse)
                          : hit.bsdf  ? *hit.bsdf  // made with the scene (render/material_tables.h)
                                      : render::materialBsdf(hit.material, arena_));
        // Both samples' numbers are drawn in the stream's order (the light's, then the BSDF's), and
        // the BSDF is sampled before the light's shadow ray is traced: the two are independent, so
        // the BSDF sample's chain of divisions and square roots overlaps next-event estimation in
        // the processor's out-of-order window instead of waiting for it to end
        // (bench/results/2026-12-06-cornell-cpu-s20.md).
        const LightNumbers u = lightNumbers(haveLights_ && v.connectable);
        const float uLobe = v.flags == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng_->next();
        const std::optional<render::BsdfSample> bs = v.bsdf.sample(v.woLocal, uLobe, rng_->next2D());
        sampleLightAt(v, u.light, u.point);
        throughput_ = throughputOnward;
        if (endsAtExit_) return Step::End;
        return continueFrom(v, bs, depth);
    }

    // Next-event estimation at a surface: one light, chosen by the light tree for the vertex's
    // point and normal; the shadow ray leaves a transmissive surface on the light's side, in the
    // medium on that side.
    void sampleLightAt(const SurfaceVertex& v, float uLight, Vec2f uPoint) {
        const Frame& frame = v.surface.frame;
        const Vec3f& ng = v.surface.geometricNormal;
        auto shadowFrom = [&](const Vec3f& wi) {
            return std::pair(v.transmissive ? spawnOrigin(v.hit.point, ng, wi) : v.lightFrom,
                             kMedia ? inside_.after(v.hit, v.wo, wi).medium() : nullptr);
        };
        sampleLight(
            haveLights_ && v.connectable, uLight, uPoint, v.lightFrom, v.lightNormal, v.hit.linkGroup, shadowFrom,
            [&](const Vec3f& wi) {
                Vec3f wiLocal = frame.toLocal(wi);
                if (!sidesAgree(v.wo, wi, ng, v.woLocal.z, wiLocal.z)) return std::pair(RGB(0.0f), 0.0f);
                const auto [f, pdf] = v.bsdf.fAndPdf(v.woLocal, wiLocal);
                return std::pair(f * std::abs(wiLocal.z), pdf);
            },
            [&](const Vec3f& wi) { return joinedEvents(v.bsdf, v.woLocal, frame.toLocal(wi)); });
    }

    // Continues the path along `bs`, the BSDF's sample at v (a plain Lambertian has one lobe: no
    // lobe number drawn for it).
    Step continueFrom(const SurfaceVertex& v, const std::optional<render::BsdfSample>& bs, int depth) {
        const Vec3f& ng = v.surface.geometricNormal;
        bool entered = false;  // a guided walk starts here
        if (!bs) return Step::End;
        Vec3f wi = v.surface.frame.toWorld(bs->wi);
        if (!sidesAgree(v.wo, wi, ng, v.woLocal.z, bs->wi.z))
            return Step::End;  // the shading frame disagrees with the surface
        throughput_ *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        etaScale_ *= bs->eta * bs->eta;
        const bool diffuseSample = !walksAfterDiffuse_ && !bs->specular && !diffuseAncestor_ && [&] {
            const render::LobeSplit k = v.bsdf.fByKind(v.woLocal, bs->wi);
            return maxComponent(k.diffuse) > maxComponent(k.glossy);
        }();
        if (!continuePath(throughput_, etaScale_, depth, *rng_)) return Step::End;
        if (lightPaths_.active()) lightPaths_.scatter(sampledEvents(v.bsdf, v.woLocal, *bs));
        // Where the next ray leaves: spawnOrigin(point, ng, wi), which for a reflection off a surface
        // that is not transmissive (wi on ng's side, wo's) is the point lights are sampled from,
        // offsetRayOrigin(point, ng), already computed (surfaceVertex).
        const Vec3f origin = !v.transmissive && dot(wi, ng) > 0.0f ? v.lightFrom : spawnOrigin(v.hit.point, ng, wi);

        mis_.scattered(bs->pdf);
        if constexpr (kMedia) {
            const DiffusionStep step =
                stepThroughDiffusion(scene_, v.hit, v.wo, wi, throughput_, diffusionExit_, *rng_, counters_);
            if (step == DiffusionStep::Lost) return Step::End;
            if (step == DiffusionStep::Exited) {
                lightPaths_.scatter(VertexEvents(volumeEvent(true)));
                return Step::Next;
            }
            const int depthBefore = inside_.depth();
            inside_.cross(v.hit, v.wo, wi);
            entered = followGuidedWalk(v.hit, depthBefore, origin, wi);
        }
        // A diffuse bounce that leaves the path outside every interior (not a walk's entry).
        if (diffuseSample && (!kMedia || inside_.depth() == 0)) diffuseAncestor_ = true;
        specularBounce_ = bs->specular;
        previousPoint_ = v.lightFrom;
        previousNormal_ = v.lightNormal;
        previousLinkGroup_ = v.hit.linkGroup;
        continueRay(origin, wi);
        if (entered && depth == 0 && walksPerEntry_ > 1) splitWalk(depth);
        return Step::Next;
    }

    // The path's next ray, from `origin` along `direction`, at the same time in the shutter: set
    // member by member, not made whole and copied in (whose 16-byte loads of a record just
    // written in 4- and 8-byte stores wait for the stores to retire).
    void continueRay(const Vec3f& origin, const Vec3f& direction) {
        ray_.origin = origin;
        ray_.direction = direction;
        ray_.tMin = 0.0f;
        ray_.tMax = std::numeric_limits<float>::infinity();
        ray_.fromCamera = false;
    }

    // The other N - 1 walks of an entry the camera ray made into a guided interior
    // (PathTracer::subsurfaceWalks_ = N): each a copy of this path from the entry, its throughput
    // times 1/N, drawing from an independent stream (this walk's Sobol slots stay those of an
    // unsplit path), that ends at its exit after the light sample there. Only this walk goes on past
    // its exit, so the path stays one path. Entries deeper in the path are not split: they cost as
    // much and their light is already averaged over the vertices before them
    // (bench/results/2026-12-06-subsurface-4-s18.md).
    void splitWalk(int depth) {
        const float share = 1.0f / float(walksPerEntry_);
        for (int i = 1; i < walksPerEntry_; ++i) {
            PathWalk other(*this);
            SampleStream stream = pathRng_->independentStream();
            other.pathRng_ = &stream;
            other.walkRng_ = stream.fork();
            other.rng_ = &other.walkRng_;
            other.throughput_ *= share;
            other.radiance_ = RGB(0.0f);
            other.out_.clearLightPaths(lightPaths_.layers());
            other.endsAtExit_ = true;
            // With a hero, the entry's walks take stratified heroes: u, u + 1/N, ... (mod 1).
            const double uHero = guidedWalk_->heroSample() + double(i) / walksPerEntry_;
            other.guidedWalk_->chooseHero(float(uHero - std::floor(uHero)));
            other.walkStep_ = other.guidedWalk_->firstStep(ray_.origin, ray_.direction,
                                                           other.guidedWalk_->stepChannel(other.rng_->next()));
            const FilmSample split = other.run(depth + 1);
            radiance_ += split.radiance;
            for (std::size_t layer = 0; layer < lightPaths_.layers(); ++layer)
                out_.addLightPath(layer, split.lightPath(layer));
        }
        exitShare_ = share;
    }

    // After a surface sent the path from `origin` along wi (the medium stack was `depthBefore`
    // deep): a guided walk starts when the path entered a guided subsurface interior and no
    // volume shares it, ends when the path left or went deeper, and otherwise (a reflection back
    // inside) goes on from there with a step whose direction the surface chose. Whether one started.
    // SLOTS OF A WALK: a walk draws from its own stream, forked from the path's where it starts
    // (SampleStream::fork), and the path's stream takes the numbers again when a step reaches the
    // boundary; so the exit's light sample and BSDF sample and every bounce after them keep the same
    // Sobol slots in every sample of a pixel, whatever the walk's length (before, each step took
    // seven slots of the path's: the decisions after a walk landed on slots that depended on its
    // length, stratified only among the samples whose walks had as many steps), while the walk's
    // k-th step still takes the same slots of its fork in every sample that forks at the same
    // dimension (a camera ray's entry). As Cycles' walk draws from its own decorrelated state.
    // Measured: bench/results/2026-12-06-walk-slots-s22.md.
    bool followGuidedWalk(const SurfaceHit& hit, int depthBefore, const Vec3f& origin, const Vec3f& wi) {
        if (inside_.depth() != depthBefore) guidedWalk_.reset();
        const bool starts = inside_.depth() > depthBefore && inside_.inSubsurface() && !scene_.medium() &&
                            hit.material.subsurfaceMethod == render::SubsurfaceMethod::RandomWalkGuided;
        if (!guidedWalk_ && !starts) return false;
        const float uChannel = rng_->next();  // with a hero, it draws the hero when the walk starts
        if (starts)
            guidedWalk_.emplace(hit.point, hit.geometricNormal, inside_.medium()->at(hit.point), walkChannels_,
                                uChannel);
        walkStep_ = guidedWalk_->firstStep(origin, wi, guidedWalk_->stepChannel(uChannel));
        if (starts) walkRng_ = pathRng_->fork();
        rng_ = &walkRng_;
        return starts;
    }

    // The numbers of sampleLight (the light's choice, its point), in the stream's order: computed
    // when it samples a light (`used`), else only their dimensions taken (SampleStream::skip), as at
    // every step of a guided walk.
    struct LightNumbers {
        float light = 0.0f;
        Vec2f point{0.0f};
    };
    LightNumbers lightNumbers(bool used) {
        LightNumbers u;
        if (used) {
            u.light = rng_->next();
            u.point = rng_->next2D();
        } else {
            rng_->skip();
            rng_->skip2D();
        }
        return u;
    }

    // Next-event estimation from `from` (with `fromNormal` for the light tree), on geometry of link
    // group `linkGroup` (render/light_links.h; 0 in a medium): one light, its
    // shadow ray (from shadowFrom(wi), a point and the medium the ray starts in) through the
    // surfaces and the medium, weighted against the
    // scattering strategy; scatter(wi) gives the BSDF or phase value (cosine included) and its density,
    // and vertexEvents(wi) the vertex's events for the light path expressions.
    // Its random numbers, uLight (the light's choice) and uPoint (its point), are the caller's
    // lightNumbers(enabled): their dimensions are taken even when it is not `enabled`, so that every
    // vertex uses as many.
    template <class ShadowFrom, class Scatter, class Events>
    void sampleLight(bool enabled, float uLight, Vec2f uPoint, const Vec3f& from, const Vec3f& fromNormal,
                     int linkGroup, ShadowFrom&& shadowFrom, Scatter&& scatter, Events&& vertexEvents) {
        if (!enabled) return;
        render::LightChoice choice = scene_.chooseLight(from, fromNormal, uLight);
        if (choice.light < 0 || choice.probability <= 0.0f) return;
        if (!scene_.lightReaches(choice.light, linkGroup)) return;  // linked away: chosen, contributes nothing
        std::optional<render::LightSample> ls = scene_.lightAt(choice.light, ray_.time).sample(from, uPoint);
        if (!ls || ls->pdf <= 0.0f || isBlack(ls->Li)) return;
        auto [f, scatterPdf] = scatter(ls->wi);
        if (isBlack(f)) return;
        ++counters_.shadow;
        const auto [shadowOrigin, shadowMedium] = shadowFrom(ls->wi);
        const render::ShadowTest shadow =
            scene_.shadowTest(choice.light, shadowOrigin, ls->wi, ls->distance, ray_.time);
        if (shadow == render::ShadowTest::Blocked) return;
        // Light that passed surfaces (render/shadow_rays.cpp) no BSDF-sampled ray finds: weight 1.
        const bool onlyStrategy = ls->delta || shadow == render::ShadowTest::PassedThrough;
        media::TransmittanceEstimate tr;
        if (kMedia && shadowMedium) {
            tr = shadowTransmittance(*shadowMedium, {shadowOrigin, ls->wi, ls->distance}, onlyStrategy);
        }
        const RGB contribution =
            throughput_ * f * ls->Li *
            mis_.lightSample(choice.probability * ls->pdf, onlyStrategy ? 0.0f : scatterPdf, tr, kMedia && shadowMedium,
                             equiangularDistancePdf(choice.light) * ls->pdf);
        radiance_ += contribution;
        if (lightPaths_.active())
            lightPaths_.connect(vertexEvents(ls->wi), lightEvents_[choice.light], contribution, out_);
    }

    // Emission `le` of light `index` reached by the ray (at `lh` on its shape, if it has one),
    // weighted against the light strategy unless only this path could have found it.
    void addEmitted(const RGB& le, int index, const LightHit& lh, int depth) {
        if (!scene_.lightReaches(index, previousLinkGroup_)) return;  // group 0 for camera rays: every light
        const bool unique = depth == 0 || specularBounce_;
        // The light strategy's density of the point, and the equiangular strategy's (0 unless the
        // path left a medium vertex), both with the light's own density of its point.
        float lightPdf = 0.0f, equiangularPdf = 0.0f;
        if (!unique) {
            const float pointPdf = scene_.lightAt(index, ray_.time).pdf(previousPoint_, ray_.direction, lh);
            lightPdf = scene_.lightProbability(previousPoint_, previousNormal_, index) * pointPdf;
            const float distancePdf = equiangularDistancePdf(index);
            if (distancePdf > 0.0f) equiangularPdf = distancePdf * pointPdf;
        }
        float weight = mis_.emitter(lightPdf, equiangularPdf, unique);
        radiance_ += throughput_ * le * weight;
        if (lightPaths_.active()) lightPaths_.reach(lightEvents_[index], throughput_ * le * weight, out_);
    }

    const LightEvents& lightEvents_;
    const EquiangularLights& equiangularLights_;
    const int maxDepth_;
    const int walksPerEntry_;                 // guided walks per entry of the camera ray (splitWalk)
    const media::WalkChannels walkChannels_;  // how a guided walk's steps choose their channel
    const bool walksAfterDiffuse_;            // false: subsurface after a diffuse bounce is diffuse (SubsurfaceShare)
    const int exactFlights_;                  // the "exact-flights" level (EXACT FLIGHTS)
    const bool exactEverywhere_;              // level 2 or 3 in a scene where the equiangular strategy samples no light
    const render::RenderScene& scene_;
    const render::Camera& camera_;
    SampleStream* rng_;      // the stream drawn from: the path's, or in a guided walk the walk's
    SampleStream* pathRng_;  // the path's own: rng_ when not in a guided walk
    SampleStream walkRng_;   // the guided walk's (SLOTS OF A WALK, followGuidedWalk)
    RenderCounters& counters_;
    FilmSample out_;
    RGB radiance_{0.0f}, throughput_{1.0f};
    Ray ray_;
    MediumStack inside_;  // the media the path is in
    MisState mis_;        // spectral: trace<true> renders media-less scenes as trace<false> does
    const int hero_;
    bool specularBounce_ = false;   // `ray_` left a delta lobe: no light strategy could have found it
    bool diffuseAncestor_ = false;  // a diffuse bounce earlier on the path (only tracked without walksAfterDiffuse_)
    float etaScale_ = 1.0f;         // product of eta^2 over the refractions so far (Russian roulette)
    // A copy of the path (splitWalk) starts with an empty arena: a vertex's BSDF lives only there.
    struct PathArena : render::BsdfArena {
        PathArena() = default;
        PathArena(const PathArena&) : render::BsdfArena() {}
    };
    PathArena arena_;
    Vec3f previousPoint_, previousNormal_{0.0f};
    int previousLinkGroup_ = 0;  // of the geometry the ray left (render/light_links.h); 0: lit by every light
    const bool haveLights_;
    LightPathTracker lightPaths_;
    int interiorScatterings_ = 0;
    float exitShare_ = 1.0f;                       // this walk's share of the light at its exit (atSurface, splitWalk)
    bool endsAtExit_ = false;                      // one of a split entry's other walks (splitWalk)
    std::optional<SurfaceHit> diffusionExit_;      // where diffusion subsurface scattering brings the path out
    std::optional<media::GuidedWalk> guidedWalk_;  // in a guided subsurface interior (followGuidedWalk)
    std::optional<EquiangularVertex> equiangularVertex_;  // the medium vertex last drawn, where the strategy applies
    media::WalkStep walkStep_;                            // its next step
    float walkLength_ = 0.0f;                             // and that step's length (startWalkStep)
};

}  // namespace

template <bool kMedia>
FilmSample PathTracer::trace(const LightEvents& lightEvents, const EquiangularLights& equiangularLights,
                             const render::RenderScene& scene, const render::Camera& camera, const Ray& cameraRay,
                             SampleStream& rng, RenderCounters& counters) const {
    const std::span<const LightPathAov> aovs =
        aovs_ ? std::span<const LightPathAov>(*aovs_) : std::span<const LightPathAov>();
    return PathWalk<kMedia>(lightEvents, equiangularLights, aovs, maxDepth_, subsurfaceWalks_, walkChannels_,
                            walksAfterDiffuse_, exactFlights_, scene, camera, cameraRay, rng, counters)
        .run();
}

template FilmSample PathTracer::trace<true>(const LightEvents&, const EquiangularLights&, const render::RenderScene&,
                                            const render::Camera&, const Ray&, SampleStream&, RenderCounters&) const;
template FilmSample PathTracer::trace<false>(const LightEvents&, const EquiangularLights&, const render::RenderScene&,
                                             const render::Camera&, const Ray&, SampleStream&, RenderCounters&) const;

}  // namespace fluence::integrators
