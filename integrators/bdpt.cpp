#include "integrators/bdpt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/sampling.h"
#include "integrators/bdpt_events.h"
#include "integrators/bdpt_mis.h"
#include "integrators/bdpt_vertex.h"
#include "integrators/emission.h"
#include "integrators/first_hit.h"
#include "integrators/path_events.h"
#include "integrators/russian_roulette.h"
#include "integrators/surface_frame.h"
#include "media/free_flight.h"
#include "media/ratio_tracking.h"

namespace fluence::integrators {

using render::Ray;
using render::RenderScene;
using render::SurfaceHit;
using namespace bdpt;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// A ray from the camera towards a light vertex stops this fraction of the way short of it, so as
// not to hit the vertex's own surface (as RenderScene::occluded shortens shadow rays).
constexpr float kLookShortening = 1e-4f;

// One scattering of a subpath at v: the direction, the throughput factor, and the densities
// forwards (from v.wo to wi) and backwards (1, 1 through a delta lobe). A light subpath carries
// importance (render/bsdf.h, TRANSPORT MODE), with the shading-normal correction of its cosine. In
// a medium, the phase function (its own adjoint).
struct Bounce {
    Vec3f wi;
    RGB weight;
    float pdf = 0.0f, pdfReverse = 0.0f;
    bool delta = false;
    float eta = 1.0f;  // as render::BsdfSample::eta
};
std::optional<Bounce> scatter(const Shading& sh, const Vertex& v, render::Transport mode, SampleStream& rng) {
    if (!sh.bsdf()) {
        const media::PhaseSample ps = sh.phase().sample(v.wo, rng.next2D());
        if (!(ps.pdf > 0.0f)) return std::nullopt;
        return Bounce{ps.wi, RGB(ps.p / ps.pdf), ps.pdf, sh.phase().pdf(ps.wi, v.wo)};
    }
    const render::Bsdf& bsdf = *sh.bsdf();
    const Frame& frame = sh.surface().frame;
    const Vec3f woLocal = frame.toLocal(v.wo);
    const float uLobe = bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
    std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, rng.next2D(), mode);
    if (!bs || !(bs->pdf > 0.0f)) return std::nullopt;
    Vec3f wi = frame.toWorld(bs->wi);
    if (!sidesAgree(v.wo, wi, sh.surface().geometricNormal, woLocal.z, bs->wi.z)) return std::nullopt;
    const float cosine = mode == render::Transport::Radiance ? std::abs(bs->wi.z) : sh.importanceCosines(v.wo, wi);
    RGB weight = bs->f * (cosine / bs->pdf);
    if (bs->specular) return Bounce{wi, weight, 1.0f, 1.0f, true, bs->eta};
    return Bounce{wi, weight, bs->pdf, bsdf.pdf(bs->wi, woLocal), false, bs->eta};
}

// The ray leaving v along wi.
Ray spawn(const Vertex& v, const Vec3f& wi) { return Ray{v.leaving(wi), wi, 0.0f, kInfinity, v.hit.time}; }

// 1 in the channels where c is positive, else 0.
RGB positive(const RGB& c) { return RGB(c.x > 0.0f ? 1.0f : 0.0f, c.y > 0.0f ? 1.0f : 0.0f, c.z > 0.0f ? 1.0f : 0.0f); }

// A stretch of a subpath through `medium` (nullptr: empty space) along `ray` up to tEnd: the free
// flight (delta tracking, hero channel `hero`), and the edge it makes up to the next vertex (which
// ends at flight.t), for the MIS weights (bdpt_mis.h, EdgeMedia).
struct Stretch {
    media::FreeFlight flight;
    EdgeMedia edge;
};
Stretch fly(const media::Medium* medium, const Ray& ray, float tEnd, int hero, SampleStream& rng) {
    Stretch s;
    s.flight.t = tEnd;
    if (!medium) return s;
    s.flight = media::sampleFreeFlight(*medium, {ray.origin, ray.direction, tEnd}, hero, rng);
    s.edge = {majorantDepth(medium, ray.origin, ray.direction, s.flight.t), positive(s.flight.pdfRatio),
              positive(s.flight.lightPdfRatio)};
    return s;
}

// A join's shadow segment through `medium`: the transmittance by ratio tracking, and its edge.
struct Crossing {
    media::TransmittanceEstimate tr;
    EdgeMedia edge;
};
Crossing cross(const media::Medium* medium, const media::MediumRay& segment, int hero, SampleStream& rng) {
    Crossing c;
    if (!medium) return c;
    c.tr = media::ratioTrackingTransmittance(*medium, segment, hero, rng);
    c.edge = {majorantDepth(medium, segment.origin, segment.direction, segment.tMax), positive(c.tr.throughput),
              positive(c.tr.pdfRatio)};
    return c;
}

// The medium vertex where a subpath in `media` scatters (flight.p), arriving along `direction`.
Vertex mediumVertex(const media::FreeFlight& flight, const Ray& ray, const RGB& beta, const MediumStack& media) {
    Vertex v{SurfaceHit{}, -ray.direction, beta, media};
    v.hit.t = flight.t;
    v.hit.time = ray.time;
    v.hit.point = flight.p;
    v.hit.geometricNormal = v.hit.shadingNormal = Vec3f(0.0f);
    v.inMedium = true;
    v.walking = media.depth() > 0;
    v.g = flight.properties.g;
    v.sigmaS = flight.properties.sigmaS;
    return v;
}

// Its densities as x_i of a path, reached over `edge`.
VertexDensity densityOf(const Vertex& v, float fromLight, float fromCamera, bool delta, const EdgeMedia& edge) {
    return {fromLight, fromCamera, delta, !v.walking, v.sigmaS, edge};
}

// The per-render state (integrators/integrator.h).
struct BdptState final : RenderState {
    SplatFilm* splats = nullptr;  // light tracing's (t = 1); null: t = 1 is left out
    std::string lightTracingOff;  // why it is left out ("" when it is not)
    // Over emitting lights, by power; index -> light, and light -> its probability (0: none).
    DiscreteDistribution emitterChoice;
    std::vector<int> emitters;
    std::vector<float> emitterProbability;
    // The light path expression AOVs (none: empty) and the events of the scene's lights.
    std::span<const LightPathAov> aovs;
    LightEvents lightEvents;
    std::string summary() const override { return lightTracingOff; }
};

struct LightSubpath {
    LightOrigin origin;
    std::vector<Vertex> vertices;  // y_1, y_2, ...
    // With light path expression AOVs, the events of each vertex left towards the next one
    // (bdpt_events.h): those of y_1 ... y_{n-1}, and of y_n when its subpath went on past it.
    std::vector<VertexEvents> events;
};

// x_0 ... x_{s-1}: the densities of the light origin and the first s - 1 light subpath vertices,
// replacing x's contents (the join or the splat appends the rest).
void setLightDensities(std::vector<VertexDensity>& x, const LightSubpath& light, int s) {
    x.clear();
    x.push_back({light.origin.fromLight, light.origin.fromCamera, false});
    for (int j = 0; j < s - 1; ++j) {
        const Vertex& lv = light.vertices[j];
        x.push_back(densityOf(lv, lv.fromOwn, lv.fromOther, lv.delta, lv.edge));
    }
}

// The camera subpath so far: z_1 ... z_m (z_0, the pinhole, enters no weight: t = 1 is weighted
// through z_1's density and StrategyPath::lightTracing, bdpt_mis.h).
using CameraSubpath = std::vector<Vertex>;

// The densities of x_{k-m} ... x_k = z_m ... z_1, z_0, appended to x. The edge into z_m is the
// join's (filled by the caller); the edge into z_j, j < m, is the one z_{j+1} was reached over.
void appendCamera(std::vector<VertexDensity>& x, const CameraSubpath& z) {
    for (std::size_t j = z.size(); j-- > 0;)
        x.push_back(
            densityOf(z[j], z[j].fromOther, z[j].fromOwn, z[j].delta, j + 1 < z.size() ? z[j + 1].edge : EdgeMedia{}));
    x.push_back({1.0f, 1.0f, false, true, RGB(1.0f), z.empty() ? EdgeMedia{} : z.front().edge});
}

// The light subpath for one sample: an emitting light chosen by power, a point and direction on
// it, then adjoint BSDF and phase sampling through the media it starts in (mediaAt) and crosses,
// with hero channel `hero` (-1: the scene has no media), at `time` in the shutter interval (the camera
// ray's). Empty (origin.light < 0) when no light emits.
LightSubpath traceLightSubpath(const RenderScene& scene, const std::vector<int>& emitters,
                               const DiscreteDistribution& choice, const std::vector<float>& probability,
                               int maxBounces, int hero, float time, bool withEvents, SampleStream& rng,
                               RenderCounters& counters, render::BsdfArena& arena) {
    LightSubpath path;
    const float uChoice = rng.next();
    const Vec2f uPosition = rng.next2D(), uDirection = rng.next2D();
    if (emitters.empty()) return path;
    const int index = emitters[choice.sample(uChoice)];
    std::optional<render::EmissionSample> es =
        scene.lightAt(index, time).sampleEmission(uPosition, uDirection, scene.bounds());
    if (!es || !(es->density.position > 0.0f) || !(es->density.direction > 0.0f) || isBlack(es->Le)) return path;
    path.origin = originAt(scene, index, es->point, es->normal, es->direction, es->delta, probability[index], time);
    RGB beta = es->Le * (es->density.cosine / (probability[index] * es->density.position * es->density.direction));
    const bool onSurface = !path.origin.atInfinity && !path.origin.delta;
    Ray ray{onSurface ? spawnOrigin(es->point, es->normal, es->direction) : es->point, es->direction, 0.0f, kInfinity,
            time};
    MediumStack media =
        hero >= 0 && !path.origin.atInfinity ? mediaAt(scene, ray.origin, ray.direction, counters) : MediumStack(scene);
    std::optional<Bounce> last;  // how the previous vertex was left
    int bounces = 0, interiorScatterings = 0;
    for (;;) {
        ++counters.bounce;
        std::optional<SurfaceHit> hit = scene.intersect(ray);
        const media::Medium* medium = media.medium();
        Stretch stretch = fly(medium, ray, hit ? hit->t : kInfinity, std::max(hero, 0), rng);
        beta *= stretch.flight.throughput;
        const media::FlightEvent event = stretch.flight.event;
        if (event == media::FlightEvent::Absorbed) break;
        if (event == media::FlightEvent::Escaped && (!hit || hit->lightShape)) break;
        Vertex v = event == media::FlightEvent::Scattered ? mediumVertex(stretch.flight, ray, beta, media)
                                                          : Vertex{*hit, -ray.direction, beta, media};
        // The light's first segment lands only on geometry it is linked to (render/light_links.h).
        if (!last && !scene.lightReaches(index, v.hit.linkGroup)) break;
        if (v.walking ? ++interiorScatterings > kMaxInteriorScatterings : bounces >= maxBounces) break;
        v.bounces = bounces += !v.walking;
        v.edge = stretch.edge;
        if (!last) {
            v.fromOwn = emittedTowards(scene, path.origin, v);
            // Measured from the point, as a camera subpath leaving it for the light would.
            if (path.origin.atInfinity)
                v.edge.majorantDepth = majorantDepth(medium, v.point(), -ray.direction, kInfinity);
        } else {
            v.fromOwn = last->delta ? 1.0f : toArea(last->pdf, path.vertices.back().point(), v);
        }
        arena.reset();
        const Shading sh(v, arena);
        v.transmissive = sh.transmissive();
        last = scatter(sh, v, render::Transport::Importance, rng);
        if (last) {
            v.delta = last->delta;
            if (withEvents) path.events.push_back(scatteringEvents(sh, v, last->wi, v.wo, last->delta));
            // The previous vertex's density as a camera subpath would draw it, through this one.
            if (path.vertices.empty())
                path.origin.fromCamera = last->delta ? 1.0f : cameraReaches(path.origin, last->pdfReverse, v.point());
            else {
                Vertex& before = path.vertices.back();
                before.fromOther = last->delta ? 1.0f : toArea(last->pdfReverse, v.point(), before);
            }
        }
        path.vertices.push_back(v);
        if (!last) break;
        beta *= last->weight;
        if (!continueInMedium(beta, 1.0f, bounces - 1, v.walking, rng)) break;
        if (!v.inMedium) media = media.after(v.hit, v.wo, last->wi);
        ray = spawn(v, last->wi);
    }
    return path;
}

// The shadow segment joining a to b (`dir`, unit, from a to b), each left on its side, or nothing
// when a surface or a light's shape blocks it (both subpaths end at a light's shape, so a join
// through one is a path neither could make; -1: no light's own shape is stepped over).
std::optional<media::MediumRay> joinSegment(const RenderScene& scene, const Vertex& a, const Vertex& b,
                                            const Vec3f& dir, RenderCounters& counters) {
    ++counters.shadow;
    const Vec3f from = a.leaving(dir), to = b.leaving(-dir);
    const Vec3f d = to - from;
    const float length = std::sqrt(lengthSquared(d));
    if (!(length > 0.0f) || scene.occluded(from, d / length, length, a.hit.time) ||
        scene.meetsOtherLightShape(-1, from, d / length, length, a.hit.time))
        return std::nullopt;
    return media::MediumRay{from, d / length, length};
}

// Light path expression AOVs of t = 1 paths: the layers each path C y_{s-1} ... y_1 L matches, which
// it adds to the splat film's layers where it adds to the beauty.
class SplatLayers {
public:
    explicit SplatLayers(const BdptState& state) : state_(state), tracker_(state.aovs) {}
    // The path through y = light.vertices[i], joined to the camera along toCamera by `sh`, adds
    // `value` at `raster`.
    void add(const LightSubpath& light, std::size_t i, const Shading& sh, const Vec3f& toCamera, const Vec2f& raster,
             const RGB& value) {
        if (!tracker_.active()) return;
        const Vertex& y = light.vertices[i];
        const VertexEvents joined = scatteringEvents(sh, y, toCamera, y.wo, false);
        towardsLight({&joined, 1}, std::span(light.events).first(i), path_);
        layers_.clearLightPaths(state_.aovs.size());
        tracker_.join(path_, state_.lightEvents[light.origin.light], value, layers_);
        for (std::size_t l = 0; l < state_.aovs.size(); ++l)
            state_.splats->addToLayer(int(l), raster.x, raster.y, layers_.lightPath(l));
    }

private:
    const BdptState& state_;
    const LightPathTracker tracker_;  // at the camera
    std::vector<VertexEvents> path_;
    FilmSample layers_;
};

// t = 1 (bdpt.h): each light vertex y_{s-1} (s >= 2) joined to the pinhole, its light splatted
// into the pixel it lands on (and its light path layers'), weighted against the path's other
// strategies.
void splatToCamera(const BdptState& state, const RenderScene& scene, const render::Camera& camera,
                   const LightSubpath& light, int hero, SampleStream& rng, RenderCounters& counters,
                   render::BsdfArena& arena) {
    SplatFilm& splats = *state.splats;
    SplatLayers layers(state);
    const media::Medium* cameraMedium = MediumStack(scene).medium();  // the camera is outside every closed surface
    std::vector<VertexDensity> x;
    for (std::size_t i = 0; i < light.vertices.size(); ++i) {
        const Vertex& y = light.vertices[i];
        const int s = static_cast<int>(i) + 2;
        // The aperture point it joins, drawn as camera rays draw theirs (render/camera.h, Importance).
        const Vec2f aperture = camera.lens().isPinhole() ? Vec2f(0.0f) : camera.lens().sampleAperture(rng.next2D());
        if (y.walking) continue;
        const std::optional<render::Camera::Connection> c = camera.connect(y.point(), aperture);
        if (!c) continue;
        arena.reset();
        const Shading sh(y, arena);
        if (!sh.connectable()) continue;
        const Scattered toCamera = sh.evaluate(y.wo, c->direction, render::Transport::Importance);
        const RGB contribution = y.beta * toCamera.f * (sh.importanceCosines(y.wo, c->direction) * c->importance);
        if (isBlack(contribution)) continue;
        // Visible as a camera ray sees it: from the near plane on, hidden by surfaces and by lights'
        // shapes (which camera rays stop at, and RenderScene::occluded passes through).
        ++counters.shadow;
        const Ray look{c->lensPoint, -c->direction, c->nearDistance, c->distance * (1.0f - kLookShortening),
                       y.hit.time};
        if (!(look.tMax > look.tMin) || scene.intersect(look)) continue;
        // Media fill the whole way to the pinhole, as for the camera subpath's first flight.
        const Crossing crossing =
            cross(cameraMedium, {y.leaving(c->direction), c->direction, c->distance}, std::max(hero, 0), rng);
        if (isBlack(crossing.tr.throughput)) continue;
        setLightDensities(x, light, s);
        x[s - 1].fromCamera = toArea(c->density, c->lensPoint, y);
        x[s - 1].delta = false;
        const float pdfBack = toCamera.pdfReverse;  // y_{s-2} drawn from the camera side
        x[s - 2].fromCamera = s == 2 ? cameraReaches(light.origin, pdfBack, y.point())
                                     : toArea(pdfBack, y.point(), light.vertices[s - 3]);
        x.push_back({1.0f, 1.0f, false, true, RGB(1.0f), crossing.edge});  // the camera
        const Vec3f toX2 = s >= 3 ? -light.vertices[1].wo : c->direction;
        const StrategyPath path{x, neeDensity(scene, light.origin, light.vertices[0], toX2), !light.origin.delta, hero,
                                true};
        const RGB value = contribution * crossing.tr.throughput * misWeight(path, s);
        if (splats.add(c->raster.x, c->raster.y, value))
            layers.add(light, i, sh, c->direction, c->raster, value);
        else
            ++counters.nonFiniteSamples;
    }
}

}  // namespace

std::unique_ptr<RenderState> Bdpt::prepare(const RenderScene& scene, const render::Camera& camera, std::uint64_t,
                                           SplatFilm* splats) const {
    auto state = std::make_unique<BdptState>();
    state->splats = splats && camera.at(0.0f).hasImportance() ? splats : nullptr;
    if (aovs_ && !aovs_->empty()) {
        state->aovs = *aovs_;
        state->lightEvents = LightEvents(scene);
    }
    const std::string why = !splats ? "the film is a window of the image (a tile)" : "an orthographic camera";
    state->lightTracingOff =
        state->splats ? "" : "light tracing (t = 1) off: " + why + "; point-light caustics seen directly are missed";
    std::vector<double> weights;
    // Lights at infinity emit over the scene's bounds, which leave volumes out (bdpt.h, LEFT OUT).
    const bool volumes = scene.medium() != nullptr;
    for (std::size_t i = 0; i < scene.lightCount(); ++i)
        if (scene.light(i).hasEmissionSampling() && !(volumes && scene.light(i).atInfinity())) {
            state->emitters.push_back(static_cast<int>(i));
            weights.push_back(std::max(0.0f, scene.light(i).power(scene.bounds())));
        }
    state->emitterProbability.assign(scene.lightCount(), 0.0f);
    if (state->emitters.empty()) return state;
    double total = 0.0;
    for (double w : weights) total += w;
    if (!(total > 0.0)) weights.assign(weights.size(), 1.0);
    state->emitterChoice = DiscreteDistribution(weights);
    for (std::size_t k = 0; k < state->emitters.size(); ++k)
        state->emitterProbability[state->emitters[k]] = state->emitterChoice.pmf(k);
    return state;
}

namespace {

// The camera subpath of one sample, vertex by vertex, and at each vertex z_{t-1} the strategies
// that end there: s = 0 (it is on a light), s = 1 (next-event estimation), s >= 2 (joins to the
// light subpath), each weighted against the path's other strategies.
class CameraWalk {
public:
    CameraWalk(const BdptState& state, int maxDepth, const LightSubpath& light, int hero, const RenderScene& scene,
               const render::Camera& camera, SampleStream& rng, RenderCounters& counters)
        : state_(state),
          maxDepth_(maxDepth),
          light_(light),
          hero_(hero),
          tracked_(std::max(hero, 0)),
          scene_(scene),
          camera_(camera),
          rng_(rng),
          counters_(counters),
          lightPaths_(state.aovs) {}

    FilmSample run(const Ray& cameraRay) {
        out_.clearLightPaths(state_.aovs.size());
        Ray ray = cameraRay;
        for (int depth = 0;; ++depth) {
            const std::optional<Vertex> next = arrive(ray, depth);
            if (!next) break;
            arena_.reset();
            const Shading sh(*next, arena_);
            z_.push_back(*next);
            z_.back().transmissive = sh.transmissive();
            const Vertex& zt = z_.back();  // z_{t-1}, t = z_.size() + 1
            const bool joinable = sh.connectable() && !zt.walking;
            // s = 1: next-event estimation, exactly as `path` samples it (its numbers drawn at every vertex).
            const float uLight = rng_.next();
            const Vec2f uPoint = rng_.next2D();
            if (joinable) sampleLight(sh, uLight, uPoint);
            for (int s = 2; joinable && s <= static_cast<int>(light_.vertices.size()) + 1; ++s)
                if (!joinLightVertex(sh, s)) break;
            if (!extend(sh, ray, depth)) break;
        }
        out_.radiance = radiance_;
        return out_;
    }

private:
    // The ray's next vertex z_{t-1}, its densities set, and the light it found on the way (s = 0);
    // none where the camera subpath ends.
    std::optional<Vertex> arrive(const Ray& ray, int depth) {
        ++(depth == 0 ? counters_.camera : counters_.bounce);
        std::optional<SurfaceHit> hit = scene_.intersect(ray);
        const float lastPdf = last_ ? last_->pdf : 0.0f;
        const bool lastDelta = last_ && last_->delta;
        const media::Medium* medium = media_.medium();
        Stretch stretch = fly(medium, ray, hit ? hit->t : kInfinity, tracked_, rng_);
        const media::FreeFlight& flight = stretch.flight;
        beta_ *= flight.throughput;
        pdfRatio_ *= flight.pdfRatio;
        if (depth == 0 && flight.event != media::FlightEvent::Escaped)
            recordFirstVolumeEvent(out_, flight.p, flight.properties.sigmaS,
                                   flight.properties.sigmaA + flight.properties.sigmaS, camera_);
        if (flight.event == media::FlightEvent::Absorbed) {
            // Emission in a medium: found by the camera subpath alone (bdpt.h).
            const RGB emitted = beta_ * flight.properties.emission / media::channelAverage(pdfRatio_);
            radiance_ += emitted;
            lightPaths_.reach(PathEvent{EventType::Object}, emitted, out_);
            return std::nullopt;
        }
        const Vec3f start = z_.empty() ? ray.origin : z_.back().point();
        // Light reaching the vertex the ray left counts where that vertex is linked to it (camera: every light).
        const int fromLinkGroup = z_.empty() ? 0 : z_.back().hit.linkGroup;
        if (flight.event == media::FlightEvent::Escaped && !hit) {
            forEachLightAtInfinity(scene_, ray.direction, ray.time, depth == 0, [&](int index, const RGB& le) {
                if (scene_.lightReaches(index, fromLinkGroup))
                    reachLight(index, beta_ * le *
                                          hitLightWeight(index, Vec3f(0.0f), -ray.direction, -ray.direction, lastPdf,
                                                         lastDelta, stretch.edge, ray.time));
            });
            return std::nullopt;
        }
        Vertex v = flight.event == media::FlightEvent::Scattered ? mediumVertex(flight, ray, beta_, media_)
                                                                 : Vertex{*hit, -ray.direction, beta_, media_};
        v.edge = stretch.edge;
        if (!z_.empty()) {
            v.fromOwn = lastDelta ? 1.0f : toArea(lastPdf, start, v);
        } else if (state_.splats) {  // z_1: drawn by the camera with its density over the whole image (bdpt_mis.h)
            // (from the aperture point the ray left, render/camera.h)
            const std::optional<render::Camera::Connection> c =
                camera_.connect(v.point(), camera_.apertureOf(ray.origin));
            cameraJoins_ = c.has_value();
            if (c) v.fromOwn = toArea(c->density, c->lensPoint, v);
        }
        if (!v.inMedium) {
            if (depth == 0) recordFirstHit(out_, *hit, v.wo, camera_);
            if (hit->light >= 0 && scene_.lightReaches(hit->light, fromLinkGroup)) {
                const RGB le = emittedAtHit(scene_, *hit, v.wo);
                if (!isBlack(le))
                    reachLight(hit->light, beta_ * le *
                                               hitLightWeight(hit->light, hit->point, hit->geometricNormal, v.wo,
                                                              lastPdf, lastDelta, v.edge, hit->time));
            }
            if (hit->lightShape || depth >= maxDepth_) return std::nullopt;
        } else if (v.walking ? ++interiorScatterings_ > kMaxInteriorScatterings : depth >= maxDepth_) {
            return std::nullopt;
        }
        v.bounces = depth + !v.walking;
        return v;
    }

    // s = 0: the camera subpath reaches light `index`, which adds `value` (MIS-weighted).
    void reachLight(int index, const RGB& value) {
        radiance_ += value;
        if (lightPaths_.active()) lightPaths_.reach(state_.lightEvents[index], value, out_);
    }

    // The MIS weight of strategy s for the path whose densities x_ holds.
    float weight(float neeOrigin, bool hittable, int s) const {
        return misWeight(StrategyPath{x_, neeOrigin, hittable, hero_, cameraJoins_}, s);
    }

    // s = 0: the camera subpath reaches light `index` over `edge`, leaving it from `point` along
    // `direction` (towards z_.back()), having drawn its last direction with density `pdf` (`delta`),
    // at `time`.
    float hitLightWeight(int index, const Vec3f& point, const Vec3f& normal, const Vec3f& direction, float pdf,
                         bool delta, const EdgeMedia& edge, float time) {
        LightOrigin x0 =
            originAt(scene_, index, point, normal, direction, false, state_.emitterProbability[index], time);
        x_.clear();
        if (z_.empty()) {  // seen by the camera: the only strategy (with media, still weighted over heroes)
            x_.push_back({x0.fromLight, 1.0f, false});
            x_.push_back({1.0f, 1.0f, false, true, RGB(1.0f), edge});
            return hero_ < 0 ? 1.0f : weight(0.0f, true, 0);
        }
        const Vertex& x1 = z_.back();
        x_.push_back({x0.fromLight, delta ? 1.0f : cameraReaches(x0, pdf, x1.point()), false});
        appendCamera(x_, z_);
        x_[1].fromLight = emittedTowards(scene_, x0, x1);
        x_[1].edge = edge;
        return weight(neeDensity(scene_, x0, x1, x1.wo), true, 0);
    }

    // The densities of z_{t-2} as drawn through z_{t-1} from direction `in` (for a join), at x_[at].
    void setAfterJoin(const Shading& sh, std::size_t at, const Vec3f& in) {
        const std::size_t m = z_.size();
        if (m < 2) return;
        const Vertex& zt = z_.back();
        x_[at].fromLight = toArea(sh.evaluate(zt.wo, in).pdfReverse, zt.point(), z_[m - 2]);
    }

    // s = 1: next-event estimation at z_{t-1}, exactly as `path` samples it.
    void sampleLight(const Shading& sh, float uLight, const Vec2f& uPoint) {
        const Vertex& zt = z_.back();
        auto [from, normal] = gatherPoint(zt, zt.wo);
        render::LightChoice choice = scene_.chooseLight(from, normal, uLight);
        std::optional<render::LightSample> ls;
        if (choice.light >= 0 && choice.probability > 0.0f && scene_.lightReaches(choice.light, zt.hit.linkGroup))
            ls = scene_.lightAt(choice.light, zt.hit.time).sample(from, uPoint);
        if (!ls || !(ls->pdf > 0.0f) || isBlack(ls->Li)) return;
        const Scattered toLight = sh.evaluate(zt.wo, ls->wi);
        const RGB& f = toLight.f;
        const float pdfCamera = toLight.pdf;
        const Vec3f shadowFrom = zt.transmissive ? zt.leaving(ls->wi) : from;
        if (isBlack(f)) return;
        ++counters_.shadow;
        const render::ShadowTest shadow =
            scene_.shadowTest(choice.light, shadowFrom, ls->wi, ls->distance, zt.hit.time);
        if (shadow == render::ShadowTest::Blocked) return;
        const Crossing crossing = cross(zt.mediumTowards(ls->wi), {shadowFrom, ls->wi, ls->distance}, tracked_, rng_);
        const Vec3f point = from + ls->wi * ls->distance;
        LightOrigin x0 = originAt(scene_, choice.light, point, Vec3f(0.0f), -ls->wi, ls->delta,
                                  state_.emitterProbability[choice.light], zt.hit.time);
        float nee = choice.probability *
                    (ls->delta || x0.atInfinity ? ls->pdf : ls->pdf * x0.cosine / (ls->distance * ls->distance));
        x_.clear();
        x_.push_back({x0.fromLight, cameraReaches(x0, pdfCamera, zt.point()), false});
        appendCamera(x_, z_);
        x_[1] = densityOf(zt, emittedTowards(scene_, x0, zt), zt.fromOwn, false, crossing.edge);
        setAfterJoin(sh, 2, ls->wi);
        const RGB value = zt.beta * f * ls->Li * crossing.tr.throughput *
                          (sh.cosine(ls->wi) / (choice.probability * ls->pdf) *
                           // Light that passed surfaces (render/shadow_rays.cpp) only this strategy finds.
                           (shadow == render::ShadowTest::PassedThrough ? 1.0f : weight(nee, !ls->delta, 1)));
        radiance_ += value;
        if (lightPaths_.active())
            lightPaths_.connect(scatteringEvents(sh, zt, zt.wo, ls->wi, false), state_.lightEvents[choice.light], value,
                                out_);
    }

    // s >= 2: y_{s-1} joined to z_{t-1}. False once the joins are over (the path too long).
    bool joinLightVertex(const Shading& sh, int s) {
        const Vertex& zt = z_.back();
        const Vertex& y = light_.vertices[s - 2];
        if (y.bounces + zt.bounces > maxDepth_) return false;
        if (y.walking) return true;
        const Vec3f d = y.point() - zt.point();
        const float dist2 = lengthSquared(d);
        if (!(dist2 > 0.0f)) return true;
        const Vec3f dir = d / std::sqrt(dist2);
        const Scattered atZ = sh.evaluate(zt.wo, dir);
        const RGB& fz = atZ.f;
        const float pdfCamera = atZ.pdf;
        if (isBlack(fz)) return true;
        joinArena_.reset();
        const Shading shy(y, joinArena_);
        if (!shy.connectable()) return true;
        const Scattered atY = shy.evaluate(y.wo, -dir, render::Transport::Importance);
        if (isBlack(atY.f)) return true;
        const RGB contribution =
            y.beta * atY.f * shy.importanceCosines(y.wo, -dir) * fz * zt.beta * (sh.cosine(dir) / dist2);
        if (isBlack(contribution)) return true;
        const std::optional<media::MediumRay> segment = joinSegment(scene_, zt, y, dir, counters_);
        if (!segment) return true;
        const Crossing crossing = cross(zt.mediumTowards(dir), *segment, tracked_, rng_);
        if (isBlack(crossing.tr.throughput)) return true;
        setLightDensities(x_, light_, s);
        x_[s - 1].fromCamera = toArea(pdfCamera, zt.point(), y);
        x_[s - 1].delta = false;
        x_[s - 2].fromCamera = s == 2 ? cameraReaches(light_.origin, atY.pdfReverse, y.point())
                                      : toArea(atY.pdfReverse, y.point(), light_.vertices[s - 3]);
        appendCamera(x_, z_);
        x_[s] = densityOf(zt, toArea(atY.pdf, y.point(), zt), zt.fromOwn, false, crossing.edge);
        setAfterJoin(sh, s + 1, dir);
        const Vertex& y1 = light_.vertices[0];
        const Vec3f toX2 = s >= 3 ? -light_.vertices[1].wo : -dir;
        const RGB value = contribution * crossing.tr.throughput *
                          weight(neeDensity(scene_, light_.origin, y1, toX2), !light_.origin.delta, s);
        radiance_ += value;
        if (lightPaths_.active()) {
            const VertexEvents joined[] = {scatteringEvents(sh, zt, zt.wo, dir, false),
                                           scatteringEvents(shy, y, -dir, y.wo, false)};
            towardsLight(joined, std::span(light_.events).first(std::size_t(s - 2)), joinPath_);
            lightPaths_.join(joinPath_, state_.lightEvents[light_.origin.light], value, out_);
        }
        return true;
    }

    // Continues the camera subpath from z_{t-1}: the next ray, or false where it ends.
    bool extend(const Shading& sh, Ray& ray, int& depth) {
        const Vertex& zt = z_.back();
        const std::size_t m = z_.size();
        last_ = scatter(sh, zt, render::Transport::Radiance, rng_);
        if (!last_) return false;
        if (m >= 2) z_[m - 2].fromOther = last_->delta ? 1.0f : toArea(last_->pdfReverse, zt.point(), z_[m - 2]);
        z_.back().delta = last_->delta;
        if (lightPaths_.active()) lightPaths_.scatter(scatteringEvents(sh, zt, zt.wo, last_->wi, last_->delta));
        beta_ *= last_->weight;
        etaScale_ *= last_->eta * last_->eta;
        if (!continueInMedium(beta_, etaScale_, depth, zt.walking, rng_)) return false;
        if (!zt.inMedium) media_ = media_.after(zt.hit, zt.wo, last_->wi);
        depth -= zt.walking;  // an interior scattering is not a bounce
        ray = spawn(zt, last_->wi);
        return true;
    }

    const BdptState& state_;
    const int maxDepth_;
    const LightSubpath& light_;
    const int hero_, tracked_;
    const RenderScene& scene_;
    const render::Camera& camera_;
    SampleStream& rng_;
    RenderCounters& counters_;
    render::BsdfArena arena_, joinArena_;
    FilmSample out_;
    RGB radiance_{0.0f};
    // Whether t = 1 can draw the paths through the camera's first vertex z_1 (the camera reaches it
    // by a connection: before the far plane and past the near one, where a medium vertex may lie).
    bool cameraJoins_ = false;
    CameraSubpath z_;
    std::vector<VertexDensity> x_;  // the densities of the path being weighted, x_0 first
    RGB beta_{1.0f},
        pdfRatio_{1.0f};         // pdfRatio_: the camera subpath's p_c / p_h (media/tracking.h), for media's emission
    MediumStack media_{scene_};  // the media the camera subpath is in (the camera outside every closed surface)
    float etaScale_ = 1.0f;
    int interiorScatterings_ = 0;
    std::optional<Bounce> last_;  // how the previous vertex was left
    // The light path expression AOVs: the camera subpath's events so far, and a join's events
    // towards the light (bdpt_events.h).
    LightPathTracker lightPaths_;
    std::vector<VertexEvents> joinPath_;
};

}  // namespace

FilmSample Bdpt::sample(const RenderState& renderState, const RenderScene& scene, const render::Camera& camera,
                        const Ray& cameraRay, SampleStream& rng, RenderCounters& counters) const {
    const BdptState& state = static_cast<const BdptState&>(renderState);
    const bool lightTracing = state.splats != nullptr;
    render::BsdfArena arena, joinArena;
    // One hero channel for both subpaths (bdpt_mis.h, SPECTRAL MIS); none without media.
    const int hero = scene.hasMedia() ? media::sampleHeroChannel(rng.next()) : -1;
    // With light tracing, a light subpath may reach maxDepth vertices (t = 1 joins the last to the
    // camera); without, maxDepth - 1 (every other strategy holds a camera vertex).
    const LightSubpath light = traceLightSubpath(scene, state.emitters, state.emitterChoice, state.emitterProbability,
                                                 lightTracing ? maxDepth_ : maxDepth_ - 1, hero, cameraRay.time,
                                                 !state.aovs.empty(), rng, counters, arena);
    // Both subpaths meet the camera where it is at the sample's time.
    std::optional<render::Camera> moved;
    const render::Camera& still = camera.moves() ? moved.emplace(camera.at(cameraRay.time)) : camera;
    if (lightTracing) splatToCamera(state, scene, still, light, hero, rng, counters, joinArena);
    return CameraWalk(state, maxDepth_, light, hero, scene, still, rng, counters).run(cameraRay);
}

}  // namespace fluence::integrators
