#include "render/lights/disk_light.h"

#include <algorithm>
#include <cmath>

#include "render/lights/surface_sampling.h"

namespace fluence::render {

DiskLight::DiskLight(const LightDesc& d) : Light(d.name), radiance_(d.radiance) {
    const Matrix4& t = d.transform;
    centre_ = Vec3f(t.transformPoint({0.0, 0.0, 0.0}));
    frame_ = Frame::fromNormal(normalize(Vec3f(t.transformNormal({0.0, 0.0, -1.0}))));
    double areaScale = length(cross(t.transformVector({1.0, 0.0, 0.0}), t.transformVector({0.0, 1.0, 0.0})));
    radius_ = static_cast<float>(d.radius * std::sqrt(areaScale));
    area_ = kPi * radius_ * radius_;
    if (d.normalize && area_ > 0.0f) radiance_ /= area_;
    if (d.shaping) shaping_ = LightShaping(*d.shaping, frame_.n, d.transform);
}

std::optional<LightSample> DiskLight::sample(const Vec3f& p, Vec2f u) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f s = sampleUniformDisk(u);
    Vec3f q = centre_ + (frame_.s * s.x + frame_.t * s.y) * radius_;
    Vec3f d = q - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    float cosLight = -dot(frame_.n, wi);
    if (cosLight <= 0.0f) return std::nullopt;
    return surfaceSample(radiance_ * shaping_.factor(-wi), wi, dist, areaToSolidAngle(1.0f / area_, dist2, cosLight));
}

float DiskLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    return area_ > 0.0f ? areaToSolidAngle(1.0f / area_, lengthSquared(hit.point - p), -dot(frame_.n, wi)) : 0.0f;
}

RGB DiskLight::emitted(const LightHit&, const Vec3f& wo) const {
    return dot(frame_.n, wo) > 0.0f ? radiance_ * shaping_.factor(wo) : RGB(0.0f);
}

float DiskLight::unshapedPower() const { return luminance(radiance_) * area_ * kPi; }

float DiskLight::power(const SceneBounds&) const { return unshapedPower() * shaping_.powerFraction(true); }

void DiskLight::shapeBounds(Vec3f& lo, Vec3f& hi) const {
    // A disk reaches r * sqrt(1 - n_i^2) from its centre along axis i.
    const Vec3f& n = frame_.n;
    Vec3f extent = Vec3f(std::sqrt(std::max(0.0f, 1.0f - n.x * n.x)), std::sqrt(std::max(0.0f, 1.0f - n.y * n.y)),
                         std::sqrt(std::max(0.0f, 1.0f - n.z * n.z))) *
                   radius_;
    lo = centre_ - extent;
    hi = centre_ + extent;
}

std::optional<LightBounds> DiskLight::bounds() const {
    LightBounds b;
    shapeBounds(b.lo, b.hi);
    b.phi = unshapedPower();
    b.axis = frame_.n;
    b.cosThetaO = 1.0f;
    return shaping_.narrow(b, true);
}

std::optional<ShapeHit> DiskLight::intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const {
    if (!meetsFront(d, frame_.n)) return std::nullopt;  // seen from behind (or edge on): rays pass through
    float denom = dot(d, frame_.n);
    float t = dot(centre_ - o, frame_.n) / denom;
    if (!(t > tMin && t < tMax) || lengthSquared(o + d * t - centre_) > radius_ * radius_) return std::nullopt;
    return ShapeHit{t, frame_.n};
}

std::optional<EmissionSample> DiskLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds&) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f s = sampleUniformDisk(uPosition);
    EmissionSample e =
        fromSurface(centre_ + (frame_.s * s.x + frame_.t * s.y) * radius_, frame_.n, 1.0f / area_, uDirection);
    e.Le = radiance_ * shaping_.factor(e.direction);
    return e;
}

EmissionDensity DiskLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds&) const {
    return area_ > 0.0f ? surfaceDensity(frame_.n, 1.0f / area_, direction) : EmissionDensity{};
}

}  // namespace fluence::render
