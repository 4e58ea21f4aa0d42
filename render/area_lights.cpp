#include "render/area_lights.h"

#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"

namespace fluence::render {

namespace {

// Solid-angle density of a uniformly area-sampled point seen from distance^2 at cosine cosLight.
float areaToSolidAngle(float areaPdf, float distanceSquared, float cosLight) {
    return cosLight > 0.0f ? areaPdf * distanceSquared / cosLight : 0.0f;
}

}  // namespace

RectLight::RectLight(const LightDesc& d) : name_(d.name), radiance_(d.radiance) {
    const Matrix4& t = d.transform;
    corner_ = Vec3f(t.transformPoint({-0.5 * d.width, -0.5 * d.height, 0.0}));
    edgeU_ = Vec3f(t.transformVector({double(d.width), 0.0, 0.0}));
    edgeV_ = Vec3f(t.transformVector({0.0, double(d.height), 0.0}));
    normal_ = normalize(Vec3f(t.transformNormal({0.0, 0.0, -1.0})));
    area_ = length(cross(edgeU_, edgeV_));
    if (d.normalize && area_ > 0.0f) radiance_ /= area_;
}

std::array<Vec3f, 4> RectLight::corners() const {
    return {corner_, corner_ + edgeU_, corner_ + edgeU_ + edgeV_, corner_ + edgeV_};
}

std::optional<LightSample> RectLight::sample(const Vec3f& p, Vec2f u) const {
    Vec3f q = corner_ + edgeU_ * u.x + edgeV_ * u.y;
    Vec3f d = q - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f || area_ == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    float cosLight = -dot(normal_, wi);
    if (cosLight <= 0.0f) return std::nullopt;
    return LightSample{radiance_, wi, dist, areaToSolidAngle(1.0f / area_, dist2, cosLight), false};
}

float RectLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    return area_ > 0.0f ? areaToSolidAngle(1.0f / area_, lengthSquared(hit.point - p), -dot(normal_, wi)) : 0.0f;
}

RGB RectLight::emitted(const LightHit&, const Vec3f& wo) const {
    return dot(normal_, wo) > 0.0f ? radiance_ : RGB(0.0f);
}

float RectLight::power(const SceneBounds&) const { return luminance(radiance_) * area_ * kPi; }

SphereLight::SphereLight(const LightDesc& d) : name_(d.name), radiance_(d.radiance) {
    centre_ = Vec3f(d.transform.transformPoint({0, 0, 0}));
    radius_ = d.radius * static_cast<float>(std::cbrt(std::abs(d.transform.determinant3x3())));
    float area = 4.0f * kPi * radius_ * radius_;
    if (d.normalize && area > 0.0f) radiance_ /= area;
}

namespace {

// 1 - cos(theta_max) of the cone a sphere of radius r subtends at distance^2 d2, computed without
// cancellation for small cones.
double coneOneMinusCos(double r, double d2) {
    double sin2 = r * r / d2;
    return sin2 / (1.0 + std::sqrt(std::max(0.0, 1.0 - sin2)));
}

}  // namespace

std::optional<LightSample> SphereLight::sample(const Vec3f& p, Vec2f u) const {
    Vec3f toCentre = centre_ - p;
    double d2 = lengthSquared(Vec3d(toCentre));
    if (d2 <= double(radius_) * radius_) return std::nullopt;  // inside: the sphere emits outwards
    double oneMinusCosMax = coneOneMinusCos(radius_, d2);
    double cosTheta = 1.0 - u.x * oneMinusCosMax;
    double sinTheta = std::sqrt(std::max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
    double phi = 2.0 * M_PI * u.y;
    double dist = std::sqrt(d2);
    Frame frame = Frame::fromNormal(Vec3f(Vec3d(toCentre) / dist));
    Vec3f wi = normalize(frame.toWorld(
        Vec3f(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta))));
    // Distance to the near intersection of the ray with the sphere.
    double b = dot(Vec3d(toCentre), Vec3d(wi));
    double disc = double(radius_) * radius_ - (d2 - b * b);
    float t = static_cast<float>(b - std::sqrt(std::max(0.0, disc)));
    return LightSample{radiance_, wi, t, static_cast<float>(1.0 / (2.0 * M_PI * oneMinusCosMax)), false};
}

float SphereLight::pdf(const Vec3f& p, const Vec3f&, const LightHit&) const {
    double d2 = lengthSquared(Vec3d(centre_ - p));
    if (d2 <= double(radius_) * radius_) return 0.0f;
    return static_cast<float>(1.0 / (2.0 * M_PI * coneOneMinusCos(radius_, d2)));
}

RGB SphereLight::emitted(const LightHit&, const Vec3f&) const { return radiance_; }

float SphereLight::power(const SceneBounds&) const {
    return luminance(radiance_) * 4.0f * kPi * radius_ * radius_ * kPi;
}

TriangleLight::TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2,
                             const RGB& radiance)
    : name_(std::move(meshName)), p0_(p0), p1_(p1), p2_(p2), radiance_(radiance) {
    Vec3f n = cross(p1 - p0, p2 - p0);
    area_ = 0.5f * length(n);
    normal_ = area_ > 0.0f ? normalize(n) : Vec3f(0, 0, 1);
}

std::optional<LightSample> TriangleLight::sample(const Vec3f& p, Vec2f u) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f b = sampleUniformTriangle(u);
    Vec3f q = p0_ * b.x + p1_ * b.y + p2_ * (1.0f - b.x - b.y);
    Vec3f d = q - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    float pdf = areaToSolidAngle(1.0f / area_, dist2, std::abs(dot(normal_, wi)));
    if (pdf == 0.0f) return std::nullopt;
    return LightSample{radiance_, wi, dist, pdf, false};
}

float TriangleLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    return area_ > 0.0f ? areaToSolidAngle(1.0f / area_, lengthSquared(hit.point - p), std::abs(dot(normal_, wi)))
                        : 0.0f;
}

float TriangleLight::power(const SceneBounds&) const { return luminance(radiance_) * area_ * 2.0f * kPi; }

}  // namespace fluence::render
