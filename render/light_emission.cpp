// Emission sampling (Light::sampleEmission and emissionDensity, render/light.h) for the lights
// that offer it, kept apart from their next-event samplers: light subpaths (integrators/bdpt.h)
// start here. Cylinder and line lights offer none (a light subpath never starts on them).
//
//   rect, disk     a point by area (a textured rect by its texels' luminance, as sample() does),
//                  a direction cosine-weighted about the emitting normal;
//   triangle       a point by area, a side with probability 1/2 (it emits from both), a
//                  cosine-weighted direction on that side: direction density |cos| / (2 pi);
//   sphere         a point uniformly over the sphere, a cosine-weighted direction outwards;
//   point          a direction uniformly over the sphere (shaping only weights it);
//   distant, dome  a direction by the light's own sampler (towards the light, reversed), and a
//                  point uniformly on the disk of the scene's bounding radius, facing that
//                  direction, a radius beyond the scene's centre (pbrt's infinite-light emission).
// Radiance comes from emitted() / escaped() (shaping and textures included).
#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"
#include "render/area_lights.h"
#include "render/infinite_lights.h"
#include "render/sphere_light.h"

namespace fluence::render {

namespace {

// A cosine-weighted direction about the unit normal n.
Vec3f cosineAbout(const Vec3f& n, Vec2f u) { return normalize(Frame::fromNormal(n).toWorld(sampleCosineHemisphere(u))); }

// Emission from a surface point with unit emitting normal n, drawn with area density `areaPdf`.
EmissionSample fromSurface(const Vec3f& point, const Vec3f& n, float areaPdf, Vec2f uDirection) {
    Vec3f direction = cosineAbout(n, uDirection);
    float cosine = std::max(0.0f, dot(n, direction));
    return {point, direction, n, RGB(0.0f), {areaPdf, cosineHemispherePdf(cosine), cosine}};
}

EmissionDensity surfaceDensity(const Vec3f& n, float areaPdf, const Vec3f& direction) {
    float cosine = dot(n, direction);
    return cosine > 0.0f ? EmissionDensity{areaPdf, cosineHemispherePdf(cosine), cosine} : EmissionDensity{};
}

// Emission of a light at infinity along `direction` (towards the scene) drawn with solid-angle
// density `directionPdf`: a point on the disk of the scene's bounding radius facing it.
EmissionSample fromInfinity(const Vec3f& direction, float directionPdf, const RGB& Le, Vec2f uPosition,
                            const SceneBounds& scene) {
    const float r = scene.radius;
    Vec2f d = sampleUniformDisk(uPosition);
    Frame frame = Frame::fromNormal(direction);
    Vec3f point = scene.centre - direction * r + (frame.s * d.x + frame.t * d.y) * r;
    return {point, direction, direction, Le, {1.0f / (kPi * r * r), directionPdf, 1.0f}};
}

}  // namespace

std::optional<EmissionSample> RectLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds&) const {
    if (area_ == 0.0f) return std::nullopt;
    const auto [uv, areaPdf] = samplePoint(uPosition);
    EmissionSample e = fromSurface(pointAt(uv), normal_, areaPdf, uDirection);
    e.Le = radianceAt(uv, e.direction);
    return e;
}

EmissionDensity RectLight::emissionDensity(const Vec3f& point, const Vec3f& direction, const SceneBounds&) const {
    if (area_ == 0.0f) return {};
    float areaPdf = (distribution_ ? distribution_->pdf(textureCoordinates(point)) : 1.0f) / area_;
    return surfaceDensity(normal_, areaPdf, direction);
}

std::optional<EmissionSample> DiskLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds&) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f s = sampleUniformDisk(uPosition);
    EmissionSample e = fromSurface(centre_ + (frame_.s * s.x + frame_.t * s.y) * radius_, frame_.n, 1.0f / area_, uDirection);
    e.Le = radiance_ * shaping_.factor(e.direction);
    return e;
}

EmissionDensity DiskLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds&) const {
    return area_ > 0.0f ? surfaceDensity(frame_.n, 1.0f / area_, direction) : EmissionDensity{};
}

std::optional<EmissionSample> TriangleLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds&) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f b = sampleUniformTriangle(uPosition);
    const bool back = uDirection.x < 0.5f;  // the side, and uDirection.x rescaled to [0, 1) again
    uDirection.x = back ? 2.0f * uDirection.x : 2.0f * uDirection.x - 1.0f;
    EmissionSample e = fromSurface(p0_ * b.x + p1_ * b.y + p2_ * (1.0f - b.x - b.y), back ? -normal_ : normal_,
                                   1.0f / area_, uDirection);
    e.density.direction *= 0.5f;
    e.Le = radiance_;
    return e;
}

EmissionDensity TriangleLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds&) const {
    if (area_ == 0.0f) return {};
    float cosine = std::abs(dot(normal_, direction));
    return {1.0f / area_, 0.5f * cosineHemispherePdf(cosine), cosine};
}

std::optional<EmissionSample> SphereLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds&) const {
    if (radius_ <= 0.0f) return std::nullopt;
    Vec3f n = sampleUniformSphere(uPosition);
    EmissionSample e = fromSurface(centre_ + n * radius_, n, 1.0f / (4.0f * kPi * radius_ * radius_), uDirection);
    e.Le = radiance_ * shaping_.factor(e.direction);
    return e;
}

EmissionDensity SphereLight::emissionDensity(const Vec3f& point, const Vec3f& direction, const SceneBounds&) const {
    if (radius_ <= 0.0f) return {};
    return surfaceDensity(normalize(point - centre_), 1.0f / (4.0f * kPi * radius_ * radius_), direction);
}

std::optional<EmissionSample> PointLight::sampleEmission(Vec2f, Vec2f uDirection, const SceneBounds&) const {
    Vec3f direction = sampleUniformSphere(uDirection);
    return EmissionSample{position_, direction, direction, intensity_ * shaping_.factor(direction), {1.0f, kUniformSpherePdf, 1.0f}, true};
}

EmissionDensity PointLight::emissionDensity(const Vec3f&, const Vec3f&, const SceneBounds&) const {
    return {1.0f, kUniformSpherePdf, 1.0f};
}

std::optional<EmissionSample> DistantLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds& scene) const {
    std::optional<LightSample> s = sample(scene.centre, uDirection);
    if (!s) return std::nullopt;
    EmissionSample e = fromInfinity(-s->wi, s->pdf, s->Li, uPosition, scene);
    e.delta = s->delta;
    return e;
}

EmissionDensity DistantLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds& scene) const {
    return {1.0f / (kPi * scene.radius * scene.radius), isDelta() ? 1.0f : pdf(scene.centre, -direction, {}), 1.0f};
}

std::optional<EmissionSample> DomeLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds& scene) const {
    std::optional<LightSample> s = sample(scene.centre, uDirection);
    if (!s) return std::nullopt;
    return fromInfinity(-s->wi, s->pdf, s->Li, uPosition, scene);
}

EmissionDensity DomeLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds& scene) const {
    return {1.0f / (kPi * scene.radius * scene.radius), pdf(scene.centre, -direction, {}), 1.0f};
}

}  // namespace fluence::render
