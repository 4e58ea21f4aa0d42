#include "render/lights/cylinder_light.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"
#include "core/sampling.h"

namespace fluence::render {

Cylinder cylinderOf(const LightDesc& d) {
    const Matrix4& t = d.transform;
    Cylinder c;
    c.centre = Vec3f(t.transformPoint({0.0, 0.0, 0.0}));
    Vec3d x = t.transformVector({1.0, 0.0, 0.0});
    c.axis = normalize(Vec3f(x));
    c.length = d.length * static_cast<float>(length(x));
    double sectionScale = length(cross(t.transformVector({0.0, 1.0, 0.0}), t.transformVector({0.0, 0.0, 1.0})));
    c.radius = d.radius * static_cast<float>(std::sqrt(sectionScale));
    float area = 2.0f * kPi * c.radius * c.length;
    c.radiance = d.normalize && area > 0.0f ? d.radiance / area : d.radiance;
    if (d.shaping) c.shaping = LightShaping(*d.shaping, normalize(Vec3f(t.transformVector({0.0, 0.0, -1.0}))), t);
    return c;
}

void segmentBounds(const Vec3f& centre, const Vec3f& axis, float length, float radius, Vec3f& lo, Vec3f& hi) {
    Vec3f a = centre - axis * (0.5f * length), b = centre + axis * (0.5f * length);
    Vec3f across =
        Vec3f(std::sqrt(std::max(0.0f, 1.0f - axis.x * axis.x)), std::sqrt(std::max(0.0f, 1.0f - axis.y * axis.y)),
              std::sqrt(std::max(0.0f, 1.0f - axis.z * axis.z))) *
        radius;
    lo = vmin(a, b) - across;
    hi = vmax(a, b) + across;
}

CylinderLight::CylinderLight(const LightDesc& d) : Light(d.name) {
    Cylinder c = cylinderOf(d);
    centre_ = c.centre;
    frame_ = Frame::fromNormal(c.axis);
    radius_ = c.radius;
    length_ = c.length;
    radiance_ = c.radiance;
    shaping_ = c.shaping;
}

float CylinderLight::halfAngleAcross(const Vec3f& p) const {
    Vec3f local = frame_.toLocal(p - centre_);
    float h = std::hypot(local.x, local.y);
    return h > radius_ && length_ > 0.0f ? std::asin(radius_ / h) : 0.0f;
}

// In the plane across the axis, p sees the circle of the cross-section under +-psiMax around the
// direction to the axis. A direction psi in it meets the circle at 2-D distance
// rho = h cos(psi) - sqrt(r^2 - h^2 sin^2(psi)), at a point of the visible arc. With psi and the
// position along the axis uniform, the area density is cos2 / (2 psiMax length rho) (cos2 the
// cosine at the surface within the plane; dpsi = r cos2 / rho dphi), the surface cosine in 3-D is
// rho cos2 / d, and the solid-angle density d^2 / cos times the area density is
// d^3 / (2 psiMax length rho^2): bounded, with no 1/cos blow-up at the silhouette.
std::optional<LightSample> CylinderLight::sample(const Vec3f& p, Vec2f u) const {
    float psiMax = halfAngleAcross(p);
    if (psiMax <= 0.0f) return std::nullopt;
    Vec3f local = frame_.toLocal(p - centre_);
    float h = std::hypot(local.x, local.y);
    float psi = psiMax * (2.0f * u.x - 1.0f);
    float heading = std::atan2(-local.y, -local.x) + psi;
    float sinPsi = std::sin(psi);
    float rho = h * std::cos(psi) - std::sqrt(std::max(0.0f, radius_ * radius_ - h * h * sinPsi * sinPsi));
    float x = local.x + rho * std::cos(heading), y = local.y + rho * std::sin(heading);
    Vec3f q = centre_ + frame_.s * x + frame_.t * y + frame_.n * (length_ * (u.y - 0.5f));
    Vec3f d = q - p;
    float dist = fluence::length(d);
    Vec3f wi = d / dist;
    if (!(rho > 0.0f) || dot(frame_.s * x + frame_.t * y, wi) >= 0.0f) return std::nullopt;
    float pdf = dist * dist * dist / (2.0f * psiMax * length_ * rho * rho);
    FLUENCE_DCHECK(isUnit(wi) && isValidDensity(pdf));
    return LightSample{radiance_ * shaping_.factor(-wi), wi, dist, pdf, false};
}

float CylinderLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    float psiMax = halfAngleAcross(p);
    if (psiMax <= 0.0f || dot(hit.normal, wi) >= 0.0f) return 0.0f;
    Vec3f d = hit.point - p;
    float dist2 = lengthSquared(d), along = dot(d, frame_.n);
    float rho2 = dist2 - along * along;
    return rho2 > 0.0f ? dist2 * std::sqrt(dist2) / (2.0f * psiMax * length_ * rho2) : 0.0f;
}

RGB CylinderLight::emitted(const LightHit& hit, const Vec3f& wo) const {
    return dot(hit.normal, wo) > 0.0f ? radiance_ * shaping_.factor(wo) : RGB(0.0f);
}

float CylinderLight::unshapedPower() const { return luminance(radiance_) * 2.0f * kPi * radius_ * length_ * kPi; }

float CylinderLight::power(const SceneBounds&) const { return unshapedPower() * shaping_.powerFraction(false); }

void CylinderLight::shapeBounds(Vec3f& lo, Vec3f& hi) const {
    segmentBounds(centre_, frame_.n, length_, radius_, lo, hi);
}

std::optional<LightBounds> CylinderLight::bounds() const {
    LightBounds b;
    shapeBounds(b.lo, b.hi);
    b.phi = unshapedPower();
    return shaping_.narrow(b, false);
}

std::optional<ShapeHit> CylinderLight::intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const {
    // |o_perp + t d_perp|^2 = r^2 in the plane across the axis; then |o_along + t d_along| <= length / 2.
    Vec3d oLocal(frame_.toLocal(o - centre_)), dLocal(frame_.toLocal(d));
    double a = dLocal.x * dLocal.x + dLocal.y * dLocal.y;
    double b = oLocal.x * dLocal.x + oLocal.y * dLocal.y;
    double c = oLocal.x * oLocal.x + oLocal.y * oLocal.y - double(radius_) * radius_;
    double disc = b * b - a * c;
    if (a == 0.0 || disc < 0.0) return std::nullopt;
    // Roots of a t^2 + 2 b t + c, computed without cancellation.
    double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    for (double t : {std::min(t0, t1), std::max(t0, t1)}) {
        if (!(t > tMin && t < tMax) || std::abs(oLocal.z + t * dLocal.z) > 0.5 * length_) continue;
        Vec3f normal = normalize(frame_.s * float(oLocal.x + t * dLocal.x) + frame_.t * float(oLocal.y + t * dLocal.y));
        return ShapeHit{static_cast<float>(t), normal};
    }
    return std::nullopt;
}

}  // namespace fluence::render
