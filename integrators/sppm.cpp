#include "integrators/sppm.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "integrators/first_hit.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::integrators {

using render::Ray;

namespace {

constexpr std::uint64_t kPhotonStreamTag = 0x70686f746f6e73ull;  // keeps photon streams apart from the camera's
constexpr int kPathsPerChunk = 4096;                              // photon paths traced as one task

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr unsigned kNonDelta = render::kBsdfDiffuse | render::kBsdfGlossy;

// Veach's correction (1997, eq. 5.19) of the adjoint BSDF for shading normals, times |wi.ns|:
// the cosine factor of a photon leaving along wi having arrived from wo (both world, away from
// the surface).
float adjointCosine(const Vec3f& wo, const Vec3f& wi, const Vec3f& ns, const Vec3f& ng) {
    const float woNg = std::abs(dot(wo, ng));
    return woNg > 0.0f ? std::abs(dot(wo, ns)) * std::abs(dot(wi, ng)) / woNg : 0.0f;
}

// Traces one photon path with the stream `rng`, appending a photon at each vertex with a diffuse
// or glossy lobe. `scale` divides the emitted flux among the map's paths.
void tracePhotonPath(const render::RenderScene& scene, int maxDepth, float scale, SampleStream& rng,
                     std::vector<Photon>& photons, std::uint64_t& rays) {
    const float uLight = rng.next();
    const Vec2f uPoint = rng.next2D(), uDirection = rng.next2D();
    const std::size_t index = scene.lightSelection().sample(uLight);
    std::optional<render::EmissionSample> emitted = scene.light(index).sampleEmission(uPoint, uDirection, scene.bounds());
    if (!emitted) return;
    const render::EmissionDensity& density = emitted->density;
    const float pdf = density.position * density.direction * scene.lightSelection().pmf(index);
    if (!(pdf > 0.0f) || isBlack(emitted->Le)) return;
    RGB power = emitted->Le * (density.cosine * scale / pdf);
    Ray ray{render::offsetRayOrigin(emitted->point, emitted->normal), emitted->direction, 0.0f, kInfinity};
    render::BsdfArena arena;
    for (int depth = 0; depth < maxDepth; ++depth) {
        ++rays;
        std::optional<render::SurfaceHit> hit = scene.intersect(ray);
        if (!hit || hit->lightShape) return;
        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const Vec3f wo = -ray.direction;
        const SurfaceFrame surface = shadingFrame(*hit, wo, (bsdf.flags() & render::kBsdfTransmission) != 0);
        const Vec3f woLocal = surface.frame.toLocal(wo);
        if (bsdf.flags() & kNonDelta) photons.push_back({hit->point, wo, power});

        const float uLobe = rng.next();
        const Vec2f u = rng.next2D();
        const float uSurvive = rng.next();
        std::optional<render::BsdfSample> bs = bsdf.sample(woLocal, uLobe, u);
        if (!bs) return;
        const Vec3f wi = surface.frame.toWorld(bs->wi);
        if (!sidesAgree(wo, wi, surface.geometricNormal, woLocal.z, bs->wi.z)) return;
        const RGB next = power * bs->f *
                         (bs->eta * bs->eta * adjointCosine(wo, wi, surface.frame.n, surface.geometricNormal) / bs->pdf);
        const float survive = std::min(1.0f, maxComponent(next) / maxComponent(power));
        if (!(uSurvive < survive)) return;
        power = next / survive;
        ray = Ray{spawnOrigin(hit->point, surface.geometricNormal, wi), wi, 0.0f, kInfinity};
    }
}

// The photons of map `sampleIndex`, paths [first, last).
std::vector<Photon> tracePhotonPaths(const render::RenderScene& scene, int maxDepth, std::uint64_t seed,
                                     std::uint64_t sampleIndex, int first, int last, int paths, std::uint64_t& rays) {
    std::vector<Photon> photons;
    for (int path = first; path < last; ++path) {
        SampleStream rng(mix64(seed ^ kPhotonStreamTag), std::uint64_t(path), sampleIndex);
        tracePhotonPath(scene, maxDepth, 1.0f / float(paths), rng, photons, rays);
    }
    return photons;
}

// The radiance leaving the hit towards wo that map's photons estimate.
RGB estimateRadiance(const PhotonMap& map, const render::Bsdf& bsdf, const SurfaceFrame& surface, const Vec3f& point,
                     const Vec3f& wo) {
    const Vec3f woLocal = surface.frame.toLocal(wo);
    RGB sum(0.0f);
    map.forEachWithin(point, [&](const Photon& photon) {
        const Vec3f wiLocal = surface.frame.toLocal(photon.wi);
        if (sidesAgree(wo, photon.wi, surface.geometricNormal, woLocal.z, wiLocal.z))
            sum += bsdf.f(woLocal, wiLocal) * photon.power;
    });
    return sum / (kPi * map.radius() * map.radius());
}

}  // namespace

float Sppm::radius(float initialRadius, std::uint64_t sampleIndex) {
    double r2 = double(initialRadius) * initialRadius;
    for (std::uint64_t j = 1; j <= sampleIndex; ++j) r2 *= (double(j) + kAlpha) / (double(j) + 1.0);
    return float(std::sqrt(r2));
}

void Sppm::prepare(const render::RenderScene& scene, const render::Camera& camera, std::uint64_t) const {
    initialRadius_ = settings_.initialRadius > 0.0f ? settings_.initialRadius
                                                    : kInitialRadiusPixels / camera.pixelsPerUnitAt(scene.bounds().centre);
    maps_.clear();
    mapsBuilt_ = photonsStored_ = photonRays_ = mostBytes_ = 0;
    silentLights_ = 0;
    for (std::size_t i = 0; i < scene.lightCount(); ++i) silentLights_ += !scene.light(i).hasEmissionSampling();
}

void Sppm::beginSamples(const render::RenderScene& scene, const render::Camera&, std::uint64_t seed, int firstSample,
                        int count) const {
    maps_.clear();  // the previous pass's samples are done
    firstSample_ = firstSample;
    const int paths = scene.lightSelection().empty() ? 0 : settings_.photonPathsPerMap;
    const int chunks = (paths + kPathsPerChunk - 1) / kPathsPerChunk;
    std::vector<std::vector<Photon>> chunkPhotons(std::size_t(count) * chunks);
    std::vector<std::uint64_t> chunkRays(chunkPhotons.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunkPhotons.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t task = r.begin(); task != r.end(); ++task) {
            const int map = int(task / chunks), chunk = int(task % chunks);
            const int first = chunk * kPathsPerChunk, last = std::min(paths, first + kPathsPerChunk);
            chunkPhotons[task] = tracePhotonPaths(scene, maxDepth_, seed, std::uint64_t(firstSample + map), first, last,
                                                  paths, chunkRays[task]);
        }
    });
    for (int map = 0; map < count; ++map) {
        std::vector<Photon> photons;
        for (int chunk = 0; chunk < chunks; ++chunk) {
            std::vector<Photon>& part = chunkPhotons[std::size_t(map) * chunks + chunk];
            photons.insert(photons.end(), part.begin(), part.end());
            part = {};
            photonRays_ += chunkRays[std::size_t(map) * chunks + chunk];
        }
        photonsStored_ += photons.size();
        maps_.emplace_back(std::move(photons), radius(initialRadius_, std::uint64_t(firstSample + map)));
    }
    std::uint64_t bytes = 0;
    for (const PhotonMap& map : maps_) bytes += map.bytes();
    mostBytes_ = std::max(mostBytes_, bytes);
    mapsBuilt_ += std::uint64_t(count);
}

std::string Sppm::summary() const {
    if (mapsBuilt_ == 0) return "";
    const std::uint64_t last = mapsBuilt_ - 1;
    char line[320];
    std::snprintf(line, sizeof line,
                  "sppm: %llu photon maps of %d paths, %.0f photons each on average, %llu photon rays; radius %.4g -> %.4g; "
                  "photon maps peaked at %.1f MB%s",
                  static_cast<unsigned long long>(mapsBuilt_), settings_.photonPathsPerMap,
                  double(photonsStored_) / double(mapsBuilt_), static_cast<unsigned long long>(photonRays_),
                  double(initialRadius_), double(radius(initialRadius_, last)), double(mostBytes_) / 1e6,
                  silentLights_ ? "; cylinder and line lights emit no photons" : "");
    return line;
}

FilmSample Sppm::sample(const render::RenderScene& scene, const render::Camera& camera, const Ray& cameraRay,
                        SampleStream& rng, RenderCounters& counters) const {
    FilmSample out;
    RGB radiance(0.0f), throughput(1.0f);
    float etaScale = 1.0f;
    Ray ray = cameraRay;
    render::BsdfArena arena;
    const PhotonMap& map = maps_[rng.sampleIndex() - std::uint64_t(firstSample_)];
    for (int depth = 0;; ++depth) {
        ++(depth == 0 ? counters.camera : counters.bounce);
        std::optional<render::SurfaceHit> hit = scene.intersect(ray);
        if (!hit) {
            for (int index : scene.lightsAtInfinity()) radiance += throughput * scene.light(index).escaped(ray.direction);
            break;
        }
        const Vec3f wo = -ray.direction;
        if (depth == 0) recordFirstHit(out, *hit, wo, camera);
        if (hit->light >= 0)
            radiance += throughput * (hit->lightShape ? scene.light(hit->light).emitted({hit->point, hit->geometricNormal}, wo)
                                                      : hit->emission);
        if (hit->lightShape || depth >= maxDepth_) break;

        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        const SurfaceFrame surface = shadingFrame(*hit, wo, (bsdf.flags() & render::kBsdfTransmission) != 0);
        if (bsdf.flags() & kNonDelta) radiance += throughput * estimateRadiance(map, bsdf, surface, hit->point, wo);
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
        ray = Ray{spawnOrigin(hit->point, surface.geometricNormal, wi), wi, 0.0f, kInfinity};
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
