#include "integrators/bdpt_vertex.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

namespace fluence::integrators::bdpt {

using render::RenderScene;

float toArea(float pdf, const Vec3f& from, const Vertex& to) {
    Vec3f d = to.point() - from;
    float d2 = lengthSquared(d);
    return d2 > 0.0f ? pdf * to.cosine(d / std::sqrt(d2)) / d2 : 0.0f;
}

Shading::Shading(const Vertex& v, render::BsdfArena& arena)
    : bsdf_(v.inMedium ? nullptr : &render::materialBsdf(v.hit.material, arena)),
      surface_(v.inMedium ? SurfaceFrame{} : shadingFrame(v.hit, v.wo, transmissive())),
      phase_(v.g) {}

Scattered Shading::evaluate(const Vec3f& wo, const Vec3f& wi, render::Transport mode) const {
    if (!bsdf_) {  // Henyey-Greenstein: its own adjoint, its value its density
        const float forward = phase_.p(wo, wi), reverse = phase_.p(wi, wo);
        return {RGB(mode == render::Transport::Radiance ? forward : reverse), forward, reverse};
    }
    Vec3f woLocal = surface_.frame.toLocal(wo), wiLocal = surface_.frame.toLocal(wi);
    if (!sidesAgree(wo, wi, surface_.geometricNormal, woLocal.z, wiLocal.z)) return {};
    return {bsdf_->f(woLocal, wiLocal, mode), bsdf_->pdf(woLocal, wiLocal), bsdf_->pdf(wiLocal, woLocal)};
}

float Shading::importanceCosines(const Vec3f& wo, const Vec3f& wi) const {
    if (!bsdf_) return 1.0f;
    return adjointShadingCosine(wo, wi, surface_.frame.n, surface_.geometricNormal);
}

std::pair<Vec3f, Vec3f> gatherPoint(const Vertex& x1, const Vec3f& toX2) {
    if (x1.transmissive || x1.inMedium) return {x1.point(), Vec3f(0.0f)};
    Vec3f ng = dot(x1.hit.geometricNormal, toX2) < 0.0f ? -x1.hit.geometricNormal : x1.hit.geometricNormal;
    return {render::offsetRayOrigin(x1.point(), ng), ng};
}

float neeDensity(const RenderScene& scene, const LightOrigin& x0, const Vertex& x1, const Vec3f& toX2) {
    auto [from, normal] = gatherPoint(x1, toX2);
    float choice = scene.lightProbability(from, normal, x0.light);
    if (x0.delta) return choice;
    const render::LightAtTime light = scene.lightAt(x0.light, x0.time);
    if (x0.atInfinity) return choice * light.pdf(from, -x0.direction, {});
    Vec3f d = x0.point - from;
    float d2 = lengthSquared(d);
    return d2 > 0.0f ? choice * light.pdf(from, d / std::sqrt(d2), {x0.point, x0.normal}) * x0.cosine / d2 : 0.0f;
}

LightOrigin originAt(const RenderScene& scene, int light, const Vec3f& point, const Vec3f& normal,
                     const Vec3f& direction, bool delta, float choice, float time) {
    render::EmissionDensity density = scene.lightAt(light, time).emissionDensity(point, direction, scene.bounds());
    LightOrigin o{light, point, normal, direction, scene.light(light).atInfinity(), delta, density.cosine, time};
    o.fromLight = choice * (o.atInfinity ? density.direction : density.position);
    return o;
}

float emittedTowards(const RenderScene& scene, const LightOrigin& x0, const Vertex& x1) {
    render::EmissionDensity density =
        scene.lightAt(x0.light, x0.time).emissionDensity(x0.point, x0.direction, scene.bounds());
    if (x0.atInfinity) return density.position * x1.cosine(x0.direction);
    return toArea(density.direction, x0.point, x1);
}

float cameraReaches(const LightOrigin& x0, float pdf, const Vec3f& p1) {
    if (x0.delta) return 0.0f;
    if (x0.atInfinity) return pdf;
    float d2 = lengthSquared(x0.point - p1);
    return d2 > 0.0f ? pdf * x0.cosine / d2 : 0.0f;
}

RGB majorantDepth(const media::Medium* medium, const Vec3f& from, const Vec3f& direction, float length) {
    RGB depth(0.0f);
    if (!medium) return depth;
    medium->majorants(from, direction, 0.0f, length, [&](const media::MajorantSegment& segment) {
        const float stretch = std::min(segment.tMax, length) - std::max(segment.tMin, 0.0f);
        if (stretch > 0.0f) depth += segment.sigmaMaj * stretch;
        return true;
    });
    return depth;
}

MediumStack mediaAt(const RenderScene& scene, const Vec3f& point, const Vec3f& direction, RenderCounters& counters) {
    std::vector<int> entered, holding;  // interiors crossed inwards (not yet out again), and those that hold the point
    render::Ray ray{point, direction, 0.0f, std::numeric_limits<float>::infinity()};
    for (int i = 0; i < kMaxProbeSurfaces; ++i) {
        ++counters.bounce;
        std::optional<render::SurfaceHit> hit = scene.intersect(ray);
        if (!hit) break;
        if (hit->interior >= 0) {
            if (dot(direction, hit->geometricNormal) < 0.0f)
                entered.push_back(hit->interior);
            else if (auto it = std::find(entered.rbegin(), entered.rend(), hit->interior); it != entered.rend())
                entered.erase(std::next(it).base());
            else
                holding.push_back(hit->interior);
        }
        ray.origin = spawnOrigin(hit->point, hit->geometricNormal, direction);
    }
    MediumStack media(scene);
    render::SurfaceHit boundary;  // entered against its normal (medium_stack.h)
    boundary.geometricNormal = Vec3f(0.0f, 0.0f, 1.0f);
    for (auto it = holding.rbegin(); it != holding.rend(); ++it) {  // outermost first
        boundary.interior = *it;
        media = media.after(boundary, boundary.geometricNormal, -boundary.geometricNormal);
    }
    return media;
}

}  // namespace fluence::integrators::bdpt
