#include "integrators/bdpt_vertex.h"

#include <cmath>

namespace fluence::integrators::bdpt {

using render::RenderScene;

float toArea(float pdf, const Vec3f& from, const Vec3f& to, const Vec3f& normal) {
    Vec3f d = to - from;
    float d2 = lengthSquared(d);
    return d2 > 0.0f ? pdf * std::abs(dot(normal, d)) / (d2 * std::sqrt(d2)) : 0.0f;
}

std::pair<Vec3f, Vec3f> gatherPoint(const Vertex& x1, const Vec3f& toX2) {
    if (x1.transmissive) return {x1.hit.point, Vec3f(0.0f)};
    Vec3f ng = dot(x1.hit.geometricNormal, toX2) < 0.0f ? -x1.hit.geometricNormal : x1.hit.geometricNormal;
    return {render::offsetRayOrigin(x1.hit.point, ng), ng};
}

float neeDensity(const RenderScene& scene, const LightOrigin& x0, const Vertex& x1, const Vec3f& toX2) {
    auto [from, normal] = gatherPoint(x1, toX2);
    float choice = scene.lightProbability(from, normal, x0.light);
    if (x0.delta) return choice;
    const render::Light& light = scene.light(x0.light);
    if (x0.atInfinity) return choice * light.pdf(from, -x0.direction, {});
    Vec3f d = x0.point - from;
    float d2 = lengthSquared(d);
    return d2 > 0.0f ? choice * light.pdf(from, d / std::sqrt(d2), {x0.point, x0.normal}) * x0.cosine / d2 : 0.0f;
}

LightOrigin originAt(const RenderScene& scene, int light, const Vec3f& point, const Vec3f& normal, const Vec3f& direction,
                     bool delta, float choice) {
    const render::Light& l = scene.light(light);
    render::EmissionDensity density = l.emissionDensity(point, direction, scene.bounds());
    LightOrigin o{light, point, normal, direction, l.atInfinity(), delta, density.cosine};
    o.fromLight = choice * (o.atInfinity ? density.direction : density.position);
    return o;
}

float emittedTowards(const RenderScene& scene, const LightOrigin& x0, const Vec3f& p1, const Vec3f& n1) {
    render::EmissionDensity density = scene.light(x0.light).emissionDensity(x0.point, x0.direction, scene.bounds());
    if (x0.atInfinity) return density.position * std::abs(dot(n1, x0.direction));
    return toArea(density.direction, x0.point, p1, n1);
}

float cameraReaches(const LightOrigin& x0, float pdf, const Vec3f& p1) {
    if (x0.delta) return 0.0f;
    if (x0.atInfinity) return pdf;
    float d2 = lengthSquared(x0.point - p1);
    return d2 > 0.0f ? pdf * x0.cosine / d2 : 0.0f;
}

}  // namespace fluence::integrators::bdpt
