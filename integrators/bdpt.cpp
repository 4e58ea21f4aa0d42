#include "integrators/bdpt.h"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/frame.h"
#include "integrators/bdpt_mis.h"
#include "integrators/bdpt_vertex.h"
#include "integrators/first_hit.h"

namespace fluence::integrators {

using render::Ray;
using render::RenderScene;
using render::SurfaceHit;
using namespace bdpt;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// One scattering of a subpath at v: the direction, the throughput factor, and the densities
// forwards (from v.wo to wi) and backwards (1, 1 through a delta lobe). `importance`: a light
// subpath, which carries the adjoint BSDF.
struct Scattering {
    Vec3f wi;
    RGB weight;
    float pdf = 0.0f, pdfReverse = 0.0f;
    bool delta = false;
    float eta = 1.0f;  // as render::BsdfSample::eta
};
std::optional<Scattering> scatter(const Shading& sh, const Vertex& v, bool importance, SampleStream& rng) {
    const Vec3f woLocal = sh.surface.frame.toLocal(v.wo);
    const float uLobe = sh.bsdf.flags() == (render::kBsdfReflection | render::kBsdfDiffuse) ? 0.0f : rng.next();
    std::optional<render::BsdfSample> bs = sh.bsdf.sample(woLocal, uLobe, rng.next2D());
    if (!bs || !(bs->pdf > 0.0f)) return std::nullopt;
    Vec3f wi = sh.surface.frame.toWorld(bs->wi);
    if (!sidesAgree(v.wo, wi, sh.surface.geometricNormal, woLocal.z, bs->wi.z)) return std::nullopt;
    // A light subpath carries the adjoint f(wi, wo): evaluated where it is a function (no BSDF is
    // assumed reciprocal), and for a delta lobe from the generalised reciprocity of render/bsdf.h,
    // f(wi, wo) = f(wo, wi) eta^2.
    RGB weight = !importance  ? bs->f * (std::abs(bs->wi.z) / bs->pdf)
                 : bs->specular ? bs->f * (bs->eta * bs->eta * sh.importanceCosines(v.wo, wi) / bs->pdf)
                                : sh.bsdf.f(bs->wi, woLocal) * (sh.importanceCosines(v.wo, wi) / bs->pdf);
    if (bs->specular) return Scattering{wi, weight, 1.0f, 1.0f, true, bs->eta};
    return Scattering{wi, weight, bs->pdf, sh.bsdf.pdf(bs->wi, woLocal), false, bs->eta};
}

// The ray leaving v along wi.
Ray spawn(const Vertex& v, const Shading& sh, const Vec3f& wi) {
    return Ray{spawnOrigin(v.hit.point, sh.surface.geometricNormal, wi), wi, 0.0f, kInfinity};
}

struct LightSubpath {
    LightOrigin origin;
    std::vector<Vertex> vertices;  // y_1, y_2, ...
};

// The camera subpath so far: z_1 ... z_m (z_0, the camera, enters no weight: t >= 2 always).
using CameraSubpath = std::vector<Vertex>;

// The densities of x_1 ... x_m = z_m ... z_1 and of z_0, appended to x.
void appendCamera(std::vector<VertexDensity>& x, const CameraSubpath& z) {
    for (auto it = z.rbegin(); it != z.rend(); ++it) x.push_back({it->fromOther, it->fromOwn, it->delta});
    x.push_back({1.0f, 1.0f, false});
}

// The light subpath for one sample: an emitting light chosen by power, a point and direction on
// it, then adjoint BSDF sampling. Empty (origin.light < 0) when no light emits.
LightSubpath traceLightSubpath(const RenderScene& scene, const std::vector<int>& emitters, const DiscreteDistribution& choice,
                               const std::vector<float>& probability, int maxVertices, SampleStream& rng,
                               RenderCounters& counters, render::BsdfArena& arena) {
    LightSubpath path;
    const float uChoice = rng.next();
    const Vec2f uPosition = rng.next2D(), uDirection = rng.next2D();
    if (emitters.empty()) return path;
    const int index = emitters[choice.sample(uChoice)];
    std::optional<render::EmissionSample> es = scene.light(index).sampleEmission(uPosition, uDirection, scene.bounds());
    if (!es || !(es->density.position > 0.0f) || !(es->density.direction > 0.0f) || isBlack(es->Le)) return path;
    path.origin = originAt(scene, index, es->point, es->normal, es->direction, es->delta, probability[index]);
    RGB beta = es->Le * (es->density.cosine / (probability[index] * es->density.position * es->density.direction));
    const bool onSurface = !path.origin.atInfinity && !path.origin.delta;
    Ray ray{onSurface ? spawnOrigin(es->point, es->normal, es->direction) : es->point, es->direction, 0.0f, kInfinity};
    std::optional<Scattering> last;  // how the previous vertex was left
    while (static_cast<int>(path.vertices.size()) < maxVertices) {
        ++counters.bounce;
        std::optional<SurfaceHit> hit = scene.intersect(ray);
        if (!hit || hit->lightShape) break;
        Vertex v{*hit, -ray.direction, beta};
        if (!last) v.fromOwn = emittedTowards(scene, path.origin, hit->point, hit->geometricNormal);
        else v.fromOwn = last->delta ? 1.0f : toArea(last->pdf, path.vertices.back().hit.point, hit->point, hit->geometricNormal);
        arena.reset();
        const Shading sh(v, arena);
        v.transmissive = sh.transmissive();
        last = scatter(sh, v, true, rng);
        if (last) {
            v.delta = last->delta;
            // The previous vertex's density as a camera subpath would draw it, through this one.
            if (path.vertices.empty()) path.origin.fromCamera = last->delta ? 1.0f : cameraReaches(path.origin, last->pdfReverse, hit->point);
            else {
                Vertex& before = path.vertices.back();
                before.fromOther = last->delta ? 1.0f : toArea(last->pdfReverse, hit->point, before.hit.point, before.hit.geometricNormal);
            }
        }
        path.vertices.push_back(v);
        if (!last) break;
        beta *= last->weight;
        if (!continuePath(beta, 1.0f, static_cast<int>(path.vertices.size()) - 1, rng)) break;
        ray = spawn(path.vertices.back(), sh, last->wi);
    }
    return path;
}

// Whether the segment between two surface points, each left on the side `dir` (from a to b)
// says, is free of surfaces.
bool visible(const RenderScene& scene, const Vertex& a, const Vertex& b, const Vec3f& dir, RenderCounters& counters) {
    ++counters.shadow;
    Vec3f from = spawnOrigin(a.hit.point, a.hit.geometricNormal, dir), to = spawnOrigin(b.hit.point, b.hit.geometricNormal, -dir);
    Vec3f d = to - from;
    float length = std::sqrt(lengthSquared(d));
    return length > 0.0f && !scene.occluded(from, d / length, length);
}

}  // namespace

void Bdpt::prepare(const RenderScene& scene, const render::Camera&, std::uint64_t) const {
    if (scene.hasMedia())
        throw std::invalid_argument(
            "the bdpt integrator does not support participating media or subsurface scattering (the scene has "
            "volumes or material interiors); render it with --integrator path");
    std::vector<double> weights;
    emitters_.clear();
    for (std::size_t i = 0; i < scene.lightCount(); ++i)
        if (scene.light(i).hasEmissionSampling()) {
            emitters_.push_back(static_cast<int>(i));
            weights.push_back(std::max(0.0f, scene.light(i).power(scene.bounds())));
        }
    emitterProbability_.assign(scene.lightCount(), 0.0f);
    emitterChoice_ = DiscreteDistribution();
    if (emitters_.empty()) return;
    double total = 0.0;
    for (double w : weights) total += w;
    if (!(total > 0.0)) weights.assign(weights.size(), 1.0);
    emitterChoice_ = DiscreteDistribution(weights);
    for (std::size_t k = 0; k < emitters_.size(); ++k) emitterProbability_[emitters_[k]] = emitterChoice_.pmf(k);
}

FilmSample Bdpt::sample(const RenderScene& scene, const render::Camera& camera, const Ray& cameraRay, SampleStream& rng,
                        RenderCounters& counters) const {
    FilmSample out;
    RGB radiance(0.0f);
    render::BsdfArena arena, joinArena;
    const LightSubpath light =
        traceLightSubpath(scene, emitters_, emitterChoice_, emitterProbability_, maxDepth_ - 1, rng, counters, arena);

    CameraSubpath z;
    std::vector<VertexDensity> x;  // the densities of the path being weighted, x_0 first
    auto weight = [&](float neeOrigin, bool hittable, int s) {
        return misWeight(StrategyPath{x, neeOrigin, hittable}, s);
    };

    // s = 0: the camera subpath reaches light `index`, leaving it from `point` along `direction`
    // (towards z.back()), having drawn its last direction with density `pdf` (`delta`).
    auto hitLightWeight = [&](int index, const Vec3f& point, const Vec3f& normal, const Vec3f& direction, float pdf,
                              bool delta) {
        if (z.empty()) return 1.0f;  // seen by the camera: the only strategy
        const Vertex& x1 = z.back();
        LightOrigin x0 = originAt(scene, index, point, normal, direction, false, emitterProbability_[index]);
        x.clear();
        x.push_back({x0.fromLight, delta ? 1.0f : cameraReaches(x0, pdf, x1.hit.point), false});
        appendCamera(x, z);
        x[1].fromLight = emittedTowards(scene, x0, x1.hit.point, x1.hit.geometricNormal);
        return weight(neeDensity(scene, x0, x1, x1.wo), true, 0);
    };

    RGB beta(1.0f);
    Ray ray = cameraRay;
    float etaScale = 1.0f;
    std::optional<Scattering> last;  // how the previous vertex was left
    for (int depth = 0;; ++depth) {
        ++(depth == 0 ? counters.camera : counters.bounce);
        std::optional<SurfaceHit> hit = scene.intersect(ray);
        const float lastPdf = last ? last->pdf : 0.0f;
        const bool lastDelta = last && last->delta;
        if (!hit) {
            for (int index : scene.lightsAtInfinity()) {
                RGB le = scene.light(index).escaped(ray.direction);
                if (!isBlack(le))
                    radiance += beta * le * hitLightWeight(index, Vec3f(0.0f), -ray.direction, -ray.direction, lastPdf, lastDelta);
            }
            break;
        }
        Vertex v{*hit, -ray.direction, beta};
        if (!z.empty()) v.fromOwn = lastDelta ? 1.0f : toArea(lastPdf, z.back().hit.point, hit->point, hit->geometricNormal);
        if (depth == 0) recordFirstHit(out, *hit, v.wo, camera);
        if (hit->light >= 0) {
            RGB le = hit->lightShape ? scene.light(hit->light).emitted({hit->point, hit->geometricNormal}, v.wo) : hit->emission;
            if (!isBlack(le))
                radiance += beta * le * hitLightWeight(hit->light, hit->point, hit->geometricNormal, v.wo, lastPdf, lastDelta);
        }
        if (hit->lightShape || depth >= maxDepth_) break;

        arena.reset();
        const Shading sh(v, arena);
        v.transmissive = sh.transmissive();
        z.push_back(v);
        const Vertex& zt = z.back();  // z_{t-1}, t = z.size() + 1
        const int m = static_cast<int>(z.size());
        const Vec3f& ns = sh.surface.frame.n;

        // The densities of z_{t-2} as drawn through zt from direction `in` (for the join).
        auto setAfterJoin = [&](std::size_t at, const Vec3f& in) {
            if (m < 2) return;
            x[at].fromLight = toArea(sh.evaluate(in, zt.wo).second, zt.hit.point, z[m - 2].hit.point, z[m - 2].hit.geometricNormal);
        };

        // s = 1: next-event estimation, exactly as `path` samples it.
        const float uLight = rng.next();
        const Vec2f uPoint = rng.next2D();
        if (sh.connectable()) {
            auto [from, normal] = gatherPoint(zt, zt.wo);
            render::LightChoice choice = scene.chooseLight(from, normal, uLight);
            std::optional<render::LightSample> ls;
            if (choice.light >= 0 && choice.probability > 0.0f) ls = scene.light(choice.light).sample(from, uPoint);
            if (ls && ls->pdf > 0.0f && !isBlack(ls->Li)) {
                auto [f, pdfCamera] = sh.evaluate(zt.wo, ls->wi);
                const Vec3f shadowFrom = zt.transmissive ? spawnOrigin(zt.hit.point, sh.surface.geometricNormal, ls->wi) : from;
                if (!isBlack(f) && (++counters.shadow, !scene.occluded(shadowFrom, ls->wi, ls->distance))) {
                    const Vec3f point = from + ls->wi * ls->distance;
                    LightOrigin x0 = originAt(scene, choice.light, point, Vec3f(0.0f), -ls->wi, ls->delta,
                                              emitterProbability_[choice.light]);
                    float nee = choice.probability *
                                (ls->delta || x0.atInfinity ? ls->pdf : ls->pdf * x0.cosine / (ls->distance * ls->distance));
                    x.clear();
                    x.push_back({x0.fromLight, cameraReaches(x0, pdfCamera, zt.hit.point), false});
                    appendCamera(x, z);
                    x[1] = {emittedTowards(scene, x0, zt.hit.point, zt.hit.geometricNormal), zt.fromOwn, false};
                    setAfterJoin(2, ls->wi);
                    radiance += zt.beta * f * ls->Li *
                                (std::abs(dot(ls->wi, ns)) / (choice.probability * ls->pdf) * weight(nee, !ls->delta, 1));
                }
            }
        }

        // s >= 2: join y_{s-1} to zt.
        for (int s = 2; sh.connectable() && s <= static_cast<int>(light.vertices.size()) + 1 && s + m - 1 <= maxDepth_; ++s) {
            const Vertex& y = light.vertices[s - 2];
            const Vec3f d = y.hit.point - zt.hit.point;
            const float dist2 = lengthSquared(d);
            if (!(dist2 > 0.0f)) continue;
            const Vec3f dir = d / std::sqrt(dist2);
            auto [fz, pdfCamera] = sh.evaluate(zt.wo, dir);
            if (isBlack(fz)) continue;
            joinArena.reset();
            const Shading shy(y, joinArena);
            if (!shy.connectable()) continue;
            auto [fy, pdfBack] = shy.evaluate(-dir, y.wo);  // f(wi, wo): the adjoint; and y_{s-2} drawn from the camera side
            if (isBlack(fy)) continue;
            const RGB contribution = y.beta * fy * shy.importanceCosines(y.wo, -dir) * fz * zt.beta *
                                     (std::abs(dot(dir, ns)) / dist2);
            if (isBlack(contribution) || !visible(scene, zt, y, dir, counters)) continue;
            x.clear();
            x.push_back({light.origin.fromLight, light.origin.fromCamera, false});
            for (int j = 0; j < s - 1; ++j) {
                const Vertex& lv = light.vertices[j];
                x.push_back({lv.fromOwn, lv.fromOther, lv.delta});
            }
            x[s - 1].fromCamera = toArea(pdfCamera, zt.hit.point, y.hit.point, y.hit.geometricNormal);
            x[s - 1].delta = false;
            x[s - 2].fromCamera = s == 2 ? cameraReaches(light.origin, pdfBack, y.hit.point)
                                         : toArea(pdfBack, y.hit.point, light.vertices[s - 3].hit.point,
                                                  light.vertices[s - 3].hit.geometricNormal);
            appendCamera(x, z);
            x[s] = {toArea(shy.evaluate(y.wo, -dir).second, y.hit.point, zt.hit.point, zt.hit.geometricNormal), zt.fromOwn, false};
            setAfterJoin(s + 1, dir);
            const Vertex& y1 = light.vertices[0];
            const Vec3f toX2 = s >= 3 ? -light.vertices[1].wo : -dir;
            radiance += contribution * weight(neeDensity(scene, light.origin, y1, toX2), !light.origin.delta, s);
        }

        // Continue the camera subpath.
        last = scatter(sh, zt, false, rng);
        if (!last) break;
        if (m >= 2) z[m - 2].fromOther = last->delta ? 1.0f : toArea(last->pdfReverse, zt.hit.point, z[m - 2].hit.point,
                                                                      z[m - 2].hit.geometricNormal);
        z.back().delta = last->delta;
        beta *= last->weight;
        etaScale *= last->eta * last->eta;
        if (!continuePath(beta, etaScale, depth, rng)) break;
        ray = spawn(z.back(), sh, last->wi);
    }
    out.radiance = radiance;
    return out;
}

}  // namespace fluence::integrators
