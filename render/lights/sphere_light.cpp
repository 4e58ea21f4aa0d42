#include "render/lights/sphere_light.h"

#include <cmath>

#include "core/check.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "render/lights/surface_sampling.h"

namespace fluence::render {

float sphereLightRadius(const LightDesc& d) {
    return d.radius * static_cast<float>(std::cbrt(std::abs(d.transform.determinant3x3())));
}

LightShaping sphereLightShaping(const LightDesc& d) {
    return d.shaping
               ? LightShaping(*d.shaping, normalize(Vec3f(d.transform.transformVector({0.0, 0.0, -1.0}))), d.transform)
               : LightShaping();
}

namespace {

// The sphere's radiance: the authored one, divided by the world-space area when normalized.
RGB sphereRadiance(const LightDesc& d, float radius) {
    float area = 4.0f * kPi * radius * radius;
    return d.normalize && area > 0.0f ? d.radiance / area : d.radiance;
}

// 1 - cos(theta_max) of the cone a sphere of radius r subtends at distance^2 d2, computed without
// cancellation for small cones.
double coneOneMinusCos(double r, double d2) {
    double sin2 = r * r / d2;
    return sin2 / (1.0 + std::sqrt(std::max(0.0, 1.0 - sin2)));
}

}  // namespace

SphereLight::SphereLight(const LightDesc& d) : Light(d.name), shaping_(sphereLightShaping(d)) {
    centre_ = Vec3f(d.transform.transformPoint({0, 0, 0}));
    radius_ = sphereLightRadius(d);
    radiance_ = sphereRadiance(d, radius_);
}

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
    Vec3f wi = normalize(
        frame.toWorld(Vec3f(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta))));
    // Distance to the near intersection of the ray with the sphere.
    double b = dot(Vec3d(toCentre), Vec3d(wi));
    double disc = double(radius_) * radius_ - (d2 - b * b);
    float t = static_cast<float>(b - std::sqrt(std::max(0.0, disc)));
    FLUENCE_DCHECK(isUnit(wi) && oneMinusCosMax >= 0.0);
    return LightSample{radiance_ * shaping_.factor(-wi), wi, t, static_cast<float>(1.0 / (2.0 * M_PI * oneMinusCosMax)),
                       false};
}

float SphereLight::pdf(const Vec3f& p, const Vec3f&, const LightHit&) const {
    double d2 = lengthSquared(Vec3d(centre_ - p));
    if (d2 <= double(radius_) * radius_) return 0.0f;
    return static_cast<float>(1.0 / (2.0 * M_PI * coneOneMinusCos(radius_, d2)));
}

RGB SphereLight::emitted(const LightHit&, const Vec3f& wo) const { return radiance_ * shaping_.factor(wo); }

float SphereLight::unshapedPower() const { return luminance(radiance_) * 4.0f * kPi * radius_ * radius_ * kPi; }

float SphereLight::power(const SceneBounds&) const { return unshapedPower() * shaping_.powerFraction(false); }

std::optional<LightBounds> SphereLight::bounds() const {
    LightBounds b;
    b.lo = centre_ - Vec3f(radius_);
    b.hi = centre_ + Vec3f(radius_);
    b.phi = unshapedPower();
    return shaping_.narrow(b, false);
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

}  // namespace fluence::render
