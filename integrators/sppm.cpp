#include "integrators/sppm.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "integrators/emission.h"
#include "integrators/first_hit.h"
#include "integrators/medium_stack.h"
#include "integrators/path_events.h"
#include "integrators/photon_light_paths.h"
#include "integrators/photon_map.h"
#include "integrators/russian_roulette.h"
#include "integrators/surface_frame.h"
#include "media/free_flight.h"
#include "media/phase.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

using render::Ray;

namespace {

constexpr std::uint64_t kPhotonStreamTag = 0x70686f746f6e73ull;  // keeps photon streams apart from the camera's
constexpr int kPathsPerChunk = 4096;                             // photon paths traced as one task

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr unsigned kNonDelta = render::kBsdfDiffuse | render::kBsdfGlossy;

// The photons one map's paths leave: on surfaces and in media; with light path expression AOVs,
// each one's histories (integrators/photon_light_paths.h), in the same order.
struct PhotonDeposits {
    std::vector<Photon> surface, volume;
    PhotonHistoryTable surfaceHistories, volumeHistories;

    void depositOnSurface(const Photon& photon, const PhotonLightPaths& lightPaths) {
        deposit(surface, surfaceHistories, photon, lightPaths);
    }
    void depositInVolume(const Photon& photon, const PhotonLightPaths& lightPaths) {
        deposit(volume, volumeHistories, photon, lightPaths);
    }

private:
    static void deposit(std::vector<Photon>& photons, PhotonHistoryTable& histories, const Photon& photon,
                        const PhotonLightPaths& lightPaths) {
        photons.push_back(photon);
        if (lightPaths.active()) histories.add(lightPaths.histories());
    }
};

// Whether the eye can enter the interior behind a surface with these BSDF flags: eye paths
// follow delta lobes only, so through a delta transmission (see "Media" in sppm.h).
bool eyeCanEnter(unsigned flags) { return (flags & render::kBsdfSpecular) && (flags & render::kBsdfTransmission); }

// The first segment of a photon path leaving `light`, whose light passes surfaces
// (render/shadow_rays.cpp): every surface it reaches receives the photon, of `flux`, and the path
// goes on from one of them, chosen uniformly, which is returned with `spread` set to their number.
// Surfaces the light does not light (render/light_links.h) receive nothing.
// The photons on the others are deposited here (on non-delta surfaces).
std::optional<render::SurfaceHit> passSurfaces(const render::RenderScene& scene, int light, const Ray& ray,
                                               const RGB& flux, SampleStream& rng, render::BsdfArena& arena,
                                               PhotonDeposits& deposits, const PhotonLightPaths& lightPaths,
                                               float& spread) {
    std::vector<render::SurfaceHit> reached = scene.surfacesReached(light, ray);
    std::erase_if(reached, [&](const render::SurfaceHit& hit) { return !scene.lightReaches(light, hit.linkGroup); });
    const float uChosen = rng.next();
    if (reached.empty()) return std::nullopt;
    const std::size_t chosen = std::min(reached.size() - 1, std::size_t(uChosen * float(reached.size())));
    for (std::size_t i = 0; i < reached.size(); ++i) {
        arena.reset();
        if (i != chosen && (render::materialBsdf(reached[i].material, arena).flags() & kNonDelta))
            deposits.depositOnSurface({reached[i].point, -ray.direction, flux}, lightPaths);
    }
    spread = float(reached.size());
    return std::move(reached[chosen]);
}

// Traces one photon path with the stream `rng`, appending a surface photon at each surface vertex
// with a diffuse or glossy lobe and a volume photon at each scattering in a medium. `scale`
// divides the emitted flux among the map's paths. With `aovs`, each photon's histories too.
void tracePhotonPath(const render::RenderScene& scene, int maxDepth, float scale, std::span<const LightPathAov> aovs,
                     const LightEvents& lightEvents, SampleStream& rng, PhotonDeposits& deposits, std::uint64_t& rays) {
    const float uLight = rng.next();
    const Vec2f uPoint = rng.next2D(), uDirection = rng.next2D();
    const std::size_t index = scene.lightSelection().sample(uLight);
    // Each photon path at its own time in the shutter (its stream's own dimension), the light where
    // it is then: gathered by camera paths of every time, the photons blur what moves.
    const float time = rng.shutterTime();
    std::optional<render::EmissionSample> emitted =
        scene.lightAt(index, time).sampleEmission(uPoint, uDirection, scene.bounds());
    if (!emitted) return;
    const render::EmissionDensity& density = emitted->density;
    const float pdf = density.position * density.direction * scene.lightSelection().pmf(index);
    if (!(pdf > 0.0f) || isBlack(emitted->Le)) return;
    PhotonLightPaths lightPaths(aovs, aovs.empty() ? PathEvent{EventType::Light} : lightEvents[int(index)]);
    // The photon's flux is beta / channelAverage(pdfRatio): f / p_h and p_c / p_h of its path so
    // far, in the hero form of media/tracking.h (both stay 1 where there are no media).
    RGB beta = emitted->Le * (density.cosine * scale / pdf), pdfRatio(1.0f);
    auto flux = [&] { return beta / media::channelAverage(pdfRatio); };
    const int hero = scene.hasMedia() ? media::sampleHeroChannel(rng.next()) : 0;
    MediumStack inside(scene);
    std::array<bool, MediumStack::kDepth + 1> keepVolumePhotons{};  // per interior depth (index 0: unused)
    int interiorScatterings = 0;
    Ray ray{render::offsetRayOrigin(emitted->point, emitted->normal), emitted->direction, 0.0f, kInfinity, time};
    render::BsdfArena arena;
    float spread = 1.0f;  // the number of surfaces the first segment deposited on, the path going on from one
    for (int depth = 0; depth < maxDepth; ++depth) {
        ++rays;
        std::optional<render::SurfaceHit> hit =
            depth == 0 && scene.lightPassesSurfaces(int(index)) && !inside.medium()
                ? passSurfaces(scene, int(index), ray, flux(), rng, arena, deposits, lightPaths, spread)
                : scene.intersect(ray);
        if (const media::Medium* medium = inside.medium()) {
            const media::FreeFlight flight =
                media::sampleFreeFlight(*medium, {ray.origin, ray.direction, hit ? hit->t : kInfinity}, hero, rng);
            beta *= flight.throughput;
            pdfRatio *= flight.pdfRatio;
            if (flight.event == media::FlightEvent::Absorbed) return;
            if (flight.event == media::FlightEvent::Scattered) {
                const bool walking = inside.depth() > 0;
                if (!walking || keepVolumePhotons[std::size_t(inside.depth())])
                    deposits.depositInVolume({flight.p, -ray.direction, flux()}, lightPaths);
                lightPaths.scatter(VertexEvents(volumeEvent(inside.inSubsurface())));
                if (walking && ++interiorScatterings > kMaxInteriorScatterings) return;
                const media::PhaseSample ps =
                    media::HenyeyGreenstein(flight.properties.g).sample(-ray.direction, rng.next2D());
                if (ps.pdf <= 0.0f) return;
                beta *= ps.p / ps.pdf;  // 1: the flux is unchanged, so the photon survives any roulette
                ray = Ray{flight.p, ps.wi, 0.0f, kInfinity, ray.time};
                depth -= walking;  // not a bounce (integrators/russian_roulette.h)
                continue;
            }
        }
        if (!hit || hit->lightShape) return;
        // The first segment's light lands only on geometry the light is linked to (render/light_links.h).
        if (depth == 0 && !scene.lightReaches(int(index), hit->linkGroup)) return;
        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const Vec3f wo = -ray.direction;
        const SurfaceFrame surface = shadingFrame(*hit, wo, (bsdf.flags() & render::kBsdfTransmission) != 0);
        const Vec3f woLocal = surface.frame.toLocal(wo);
        const RGB power = flux();
        if (bsdf.flags() & kNonDelta) deposits.depositOnSurface({hit->point, wo, power}, lightPaths);
        beta *= std::exchange(spread, 1.0f);

        const float uLobe = rng.next();
        const Vec2f u = rng.next2D();
        const float uSurvive = rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, u, render::Transport::Importance);
        if (!bs) return;
        const Vec3f wi = surface.frame.toWorld(bs->wi);
        if (!sidesAgree(wo, wi, surface.geometricNormal, woLocal.z, bs->wi.z)) return;
        const RGB next =
            beta * bs->f * (adjointShadingCosine(wo, wi, surface.frame.n, surface.geometricNormal) / bs->pdf);
        const float survive =
            std::min(1.0f, maxComponent(next / media::channelAverage(pdfRatio)) / maxComponent(power));
        if (!(uSurvive < survive)) return;
        beta = next / survive;
        // Read from the camera, the photon goes on towards it along wi (the adjoint BSDF's split).
        lightPaths.scatter(surfaceEvents(bsdf, bs->wi, woLocal, bs->specular));
        const MediumStack after = inside.after(*hit, wo, wi);
        if (after.depth() > inside.depth()) keepVolumePhotons[std::size_t(after.depth())] = eyeCanEnter(bsdf.flags());
        inside = after;
        ray = Ray{spawnOrigin(hit->point, surface.geometricNormal, wi), wi, 0.0f, kInfinity, ray.time};
    }
}

// The photons of map `sampleIndex`, paths [first, last).
PhotonDeposits tracePhotonPaths(const render::RenderScene& scene, int maxDepth, std::span<const LightPathAov> aovs,
                                const LightEvents& lightEvents, std::uint64_t seed, std::uint64_t sampleIndex,
                                int first, int last, int paths, std::uint64_t& rays) {
    PhotonDeposits deposits;
    for (int path = first; path < last; ++path) {
        SampleStream rng(mix64(seed ^ kPhotonStreamTag), std::uint64_t(path), sampleIndex);
        tracePhotonPath(scene, maxDepth, 1.0f / float(paths), aovs, lightEvents, rng, deposits, rays);
    }
    return deposits;
}

// The kernels' normalisations: the disc's area, the ball's volume.
float surfaceKernelArea(float r) { return kPi * r * r; }
float volumeKernelVolume(float r) { return 4.0f / 3.0f * kPi * r * r * r; }

// The radiance leaving the hit towards wo that map's photons estimate; gathered(position,
// woLocal, wiLocal, term) is called with each photon's term of the sum (before the kernel's
// normalisation), position its place in the map.
template <class Gathered>
RGB estimateRadiance(const PhotonMap& map, const render::Bsdf& bsdf, const SurfaceFrame& surface, const Vec3f& point,
                     const Vec3f& wo, Gathered&& gathered) {
    const Vec3f woLocal = surface.frame.toLocal(wo);
    RGB sum(0.0f);
    map.forEachWithin(point, [&](const Photon& photon, std::uint32_t position) {
        const Vec3f wiLocal = surface.frame.toLocal(photon.wi);
        if (sidesAgree(wo, photon.wi, surface.geometricNormal, woLocal.z, wiLocal.z)) {
            const RGB term = bsdf.f(woLocal, wiLocal) * photon.power;
            sum += term;
            gathered(position, woLocal, wiLocal, term);
        }
    });
    return sum / surfaceKernelArea(map.radius());
}

// sigmaS L_s(p, wo), the radiance scattered towards wo per unit length at p, that the volume
// photons estimate (see "Media" in sppm.h); gathered(position, term) as for estimateRadiance.
template <class Gathered>
RGB estimateInScattering(const PhotonMap& map, const media::HenyeyGreenstein& phase, const Vec3f& p, const Vec3f& wo,
                         Gathered&& gathered) {
    RGB sum(0.0f);
    map.forEachWithin(p, [&](const Photon& photon, std::uint32_t position) {
        const RGB term = photon.power * phase.p(wo, photon.wi);
        sum += term;
        gathered(position, term);
    });
    return sum / volumeKernelVolume(map.radius());
}

// The per-render state (integrators/integrator.h): what prepare() and beginSamples() compute.
struct SppmState final : RenderState {
    LightEvents lightEvents;  // with light path expression AOVs
    float initialRadius = 0.0f;
    int photonPathsPerMap = 0;  // SppmSettings::photonPathsPerMap, for the summary
    int firstSample = 0;
    struct SampleMaps {
        PhotonMap surface, volume;
        PhotonHistoryTable surfaceHistories, volumeHistories;  // with light path expression AOVs
    };
    std::vector<SampleMaps> maps;  // sample indices [firstSample, firstSample + size)
    std::uint64_t mapsBuilt = 0, photonsStored = 0, volumePhotonsStored = 0, photonRays = 0, mostBytes = 0;
    std::size_t silentLights = 0;  // lights without emission sampling
    // Photon maps, photons and rays, the radii, the peak memory.
    std::string summary() const override;
};

// The light path expression layers' terms of one gather: per expression, the sum of the terms of
// the photons it accepts, each photon's term shared as its histories and the gather vertex's
// kinds share it (integrators/photon_light_paths.h).
class GatheredLayers {
public:
    GatheredLayers(const LightPathTracker& eye, const PhotonMap& map, const PhotonHistoryTable& histories)
        : eye_(eye), map_(map), histories_(histories) {}

    // The photon at `position` in the map, gathered at `vertex`, adds `term` to the beauty's sum.
    void add(const VertexEvents& vertex, std::uint32_t position, const RGB& term) {
        const std::uint32_t photon = map_.indexAt(position);
        eye_.gather(
            vertex, [&](int aov, int state) { return histories_.accepted(photon, aov, state); },
            [&](int aov, const RGB& fraction) { sums_[std::size_t(aov)] += term * fraction; });
    }
    const RGB& sum(std::size_t aov) const { return sums_[aov]; }

private:
    const LightPathTracker& eye_;
    const PhotonMap& map_;
    const PhotonHistoryTable& histories_;
    std::array<RGB, kMaxLightPathLayers> sums_{};
};

}  // namespace

Sppm::Sppm(const IntegratorSettings& settings, const SppmSettings& sppm)
    : maxDepth_(settings.maxDepth), settings_(sppm), aovs_(settings.lightPathAovs) {
    for (const LightPathAov& aov : aovs())
        if (std::string problem = photonLightPathProblem(aov.expression); !problem.empty())
            throw std::invalid_argument("light path expression AOV " + aov.name + ": " + problem);
}

float Sppm::radius(float initialRadius, std::uint64_t sampleIndex, int dimensions) {
    double rd = std::pow(double(initialRadius), dimensions);
    for (std::uint64_t j = 1; j <= sampleIndex; ++j) rd *= (double(j) + kAlpha) / (double(j) + 1.0);
    return float(std::pow(rd, 1.0 / dimensions));
}

std::unique_ptr<RenderState> Sppm::prepare(const render::RenderScene& scene, const render::Camera& camera,
                                           std::uint64_t, SplatFilm*) const {
    auto state = std::make_unique<SppmState>();
    state->initialRadius = settings_.initialRadius > 0.0f
                               ? settings_.initialRadius
                               : kInitialRadiusPixels / camera.pixelsPerUnitAt(scene.bounds().centre);
    state->photonPathsPerMap = settings_.photonPathsPerMap;
    if (!aovs().empty()) state->lightEvents = LightEvents(scene);
    for (std::size_t i = 0; i < scene.lightCount(); ++i) state->silentLights += !scene.light(i).hasEmissionSampling();
    return state;
}

void Sppm::beginSamples(RenderState& renderState, const render::RenderScene& scene, const render::Camera&,
                        std::uint64_t seed, int firstSample, int count) const {
    SppmState& state = static_cast<SppmState&>(renderState);
    state.maps.clear();  // the previous pass's samples are done
    state.firstSample = firstSample;
    const int paths = scene.lightSelection().empty() ? 0 : settings_.photonPathsPerMap;
    const int chunks = (paths + kPathsPerChunk - 1) / kPathsPerChunk;
    std::vector<PhotonDeposits> chunkPhotons(std::size_t(count) * chunks);
    std::vector<std::uint64_t> chunkRays(chunkPhotons.size(), 0);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, chunkPhotons.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t task = r.begin(); task != r.end(); ++task) {
                const int map = int(task / chunks), chunk = int(task % chunks);
                const int first = chunk * kPathsPerChunk, last = std::min(paths, first + kPathsPerChunk);
                chunkPhotons[task] =
                    tracePhotonPaths(scene, maxDepth_, aovs(), state.lightEvents, seed,
                                     std::uint64_t(firstSample + map), first, last, paths, chunkRays[task]);
            }
        });
    for (int map = 0; map < count; ++map) {
        PhotonDeposits photons;
        for (int chunk = 0; chunk < chunks; ++chunk) {
            PhotonDeposits& part = chunkPhotons[std::size_t(map) * chunks + chunk];
            photons.surface.insert(photons.surface.end(), part.surface.begin(), part.surface.end());
            photons.volume.insert(photons.volume.end(), part.volume.begin(), part.volume.end());
            photons.surfaceHistories.append(part.surfaceHistories);
            photons.volumeHistories.append(part.volumeHistories);
            part = {};
            state.photonRays += chunkRays[std::size_t(map) * chunks + chunk];
        }
        state.photonsStored += photons.surface.size();
        state.volumePhotonsStored += photons.volume.size();
        const std::uint64_t sampleIndex = std::uint64_t(firstSample + map);
        const bool keepIndices = !aovs().empty();
        state.maps.push_back(
            {PhotonMap(std::move(photons.surface), radius(state.initialRadius, sampleIndex, 2), keepIndices),
             PhotonMap(std::move(photons.volume), radius(state.initialRadius, sampleIndex, 3), keepIndices),
             std::move(photons.surfaceHistories), std::move(photons.volumeHistories)});
    }
    std::uint64_t bytes = 0;
    for (const SppmState::SampleMaps& maps : state.maps)
        bytes +=
            maps.surface.bytes() + maps.volume.bytes() + maps.surfaceHistories.bytes() + maps.volumeHistories.bytes();
    state.mostBytes = std::max(state.mostBytes, bytes);
    state.mapsBuilt += std::uint64_t(count);
}

std::string SppmState::summary() const {
    if (mapsBuilt == 0) return "";
    const std::uint64_t last = mapsBuilt - 1;
    char volume[160] = "";
    if (volumePhotonsStored > 0)
        std::snprintf(volume, sizeof volume, " and %.0f in media; volume radius %.4g -> %.4g",
                      double(volumePhotonsStored) / double(mapsBuilt), double(initialRadius),
                      double(Sppm::radius(initialRadius, last, 3)));
    char line[480];
    std::snprintf(line, sizeof line,
                  "sppm: %llu photon maps of %d paths, %.0f photons each on average on surfaces%s, %llu photon rays; "
                  "radius %.4g -> %.4g; photon maps peaked at %.1f MB%s",
                  static_cast<unsigned long long>(mapsBuilt), photonPathsPerMap,
                  double(photonsStored) / double(mapsBuilt), volume, static_cast<unsigned long long>(photonRays),
                  double(initialRadius), double(Sppm::radius(initialRadius, last, 2)), double(mostBytes) / 1e6,
                  silentLights ? "; cylinder and line lights emit no photons" : "");
    return line;
}

FilmSample Sppm::sample(const RenderState& renderState, const render::RenderScene& scene, const render::Camera& camera,
                        const Ray& cameraRay, SampleStream& rng, RenderCounters& counters) const {
    const SppmState& state = static_cast<const SppmState&>(renderState);
    FilmSample out;
    // The eye path's f / p_h and p_c / p_h (media/tracking.h): its estimates are divided by
    // channelAverage(pdfRatio), which stays 1 where there are no media.
    RGB radiance(0.0f), throughput(1.0f), pdfRatio(1.0f);
    float etaScale = 1.0f;
    Ray ray = cameraRay;
    MediumStack inside(scene);
    const int hero = scene.hasMedia() ? media::sampleHeroChannel(rng.next()) : 0;
    render::BsdfArena arena;
    const SppmState::SampleMaps& maps = state.maps[rng.sampleIndex() - std::uint64_t(state.firstSample)];
    // Adds an estimate to the beauty and returns what it added.
    auto add = [&](const RGB& estimate) {
        const RGB added = throughput * estimate / media::channelAverage(pdfRatio);
        radiance += added;
        return added;
    };
    LightPathTracker lightPaths(aovs());
    if (lightPaths.active()) out.clearLightPaths(aovs().size());
    // Adds a gather's layers, each sum normalised by the kernel's `size` as the beauty's estimate is.
    auto addLayers = [&](const GatheredLayers& layers, float size) {
        for (std::size_t aov = 0; aov < aovs().size(); ++aov)
            out.addLightPath(aov, throughput * (layers.sum(aov) / size) / media::channelAverage(pdfRatio));
    };
    int fromLinkGroup = 0;  // of the geometry `ray` left (render/light_links.h); camera rays see every light
    for (int depth = 0;; ++depth) {
        ++(depth == 0 ? counters.camera : counters.bounce);
        std::optional<render::SurfaceHit> hit = scene.intersect(ray);
        if (const media::Medium* medium = inside.medium()) {
            const media::FreeFlight flight =
                media::sampleFreeFlight(*medium, {ray.origin, ray.direction, hit ? hit->t : kInfinity}, hero, rng);
            throughput *= flight.throughput;
            pdfRatio *= flight.pdfRatio;
            if (depth == 0 && flight.event != media::FlightEvent::Escaped)
                recordFirstVolumeEvent(out, flight.p, flight.properties.sigmaS,
                                       flight.properties.sigmaA + flight.properties.sigmaS, camera);
            if (flight.event == media::FlightEvent::Absorbed) {
                lightPaths.reach(PathEvent{EventType::Object}, add(flight.properties.emission), out);
                break;
            }
            if (flight.event == media::FlightEvent::Scattered) {
                // throughput holds sigmaS (media/free_flight.h), the estimate too: one is divided out.
                const RGB sigmaS = flight.properties.sigmaS;
                RGB perSigmaS(0.0f);
                for (int c = 0; c < 3; ++c) perSigmaS[c] = sigmaS[c] > 0.0f ? throughput[c] / sigmaS[c] : 0.0f;
                throughput = perSigmaS;
                GatheredLayers layers(lightPaths, maps.volume, maps.volumeHistories);
                const VertexEvents event(volumeEvent(inside.inSubsurface()));
                add(estimateInScattering(maps.volume, media::HenyeyGreenstein(flight.properties.g), flight.p,
                                         -ray.direction, [&](std::uint32_t position, const RGB& term) {
                                             if (lightPaths.active()) layers.add(event, position, term);
                                         }));
                if (lightPaths.active()) addLayers(layers, volumeKernelVolume(maps.volume.radius()));
                break;
            }
        }
        if (!hit) {
            forEachLightAtInfinity(scene, ray.direction, ray.time, depth == 0, [&](int index, const RGB& le) {
                if (!scene.lightReaches(index, fromLinkGroup)) return;
                const RGB added = add(le);
                if (lightPaths.active()) lightPaths.reach(state.lightEvents[index], added, out);
            });
            break;
        }
        const Vec3f wo = -ray.direction;
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);
        if (hit->light >= 0 && scene.lightReaches(hit->light, fromLinkGroup)) {
            const RGB added = add(emittedAtHit(scene, *hit, wo));
            if (lightPaths.active()) lightPaths.reach(state.lightEvents[hit->light], added, out);
        }
        if (hit->lightShape || depth >= maxDepth_) break;

        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const SurfaceFrame surface = shadingFrame(*hit, wo, (bsdf.flags() & render::kBsdfTransmission) != 0);
        if (bsdf.flags() & kNonDelta) {
            GatheredLayers layers(lightPaths, maps.surface, maps.surfaceHistories);
            add(estimateRadiance(
                maps.surface, bsdf, surface, hit->point, wo,
                [&](std::uint32_t position, const Vec3f& woLocal, const Vec3f& wiLocal, const RGB& term) {
                    if (lightPaths.active()) layers.add(joinedEvents(bsdf, woLocal, wiLocal), position, term);
                }));
            if (lightPaths.active()) addLayers(layers, surfaceKernelArea(maps.surface.radius()));
        }
        if (!(bsdf.flags() & render::kBsdfSpecular)) break;

        // Through a delta lobe only: the estimate above covers every other.
        const Vec3f woLocal = surface.frame.toLocal(wo);
        const float uLobe = rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, rng.next2D());
        if (!bs || !bs->specular) break;
        const Vec3f wi = surface.frame.toWorld(bs->wi);
        if (!sidesAgree(wo, wi, surface.geometricNormal, woLocal.z, bs->wi.z)) break;
        throughput *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
        etaScale *= bs->eta * bs->eta;
        if (!continuePath(throughput, etaScale, depth, rng)) break;
        lightPaths.scatter(sampledEvents(bsdf, woLocal, *bs));
        inside = inside.after(*hit, wo, wi);
        fromLinkGroup = hit->linkGroup;
        ray = Ray{spawnOrigin(hit->point, surface.geometricNormal, wi), wi, 0.0f, kInfinity, ray.time};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
