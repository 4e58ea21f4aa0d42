#include "render/lights/point_light.h"

#include <cmath>

#include "core/sampling.h"
#include "render/lights/sphere_light.h"

namespace fluence::render {

PointLight::PointLight(const LightDesc& d) : Light(d.name), shaping_(sphereLightShaping(d)) {
    position_ = Vec3f(d.transform.transformPoint({0, 0, 0}));
    float radius = sphereLightRadius(d);
    intensity_ = d.normalize ? d.radiance / 4.0f : d.radiance * (kPi * radius * radius);
}

std::optional<LightSample> PointLight::sample(const Vec3f& p, Vec2f) const {
    Vec3f d = position_ - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    return LightSample{intensity_ * shaping_.factor(-wi) / dist2, wi, dist, 1.0f, true};
}

float PointLight::unshapedPower() const { return luminance(intensity_) * 4.0f * kPi; }

float PointLight::power(const SceneBounds&) const { return unshapedPower() * shaping_.powerFraction(false); }

std::optional<LightBounds> PointLight::bounds() const {
    LightBounds b;
    b.lo = b.hi = position_;
    b.phi = unshapedPower();
    return shaping_.narrow(b, false);
}

std::optional<EmissionSample> PointLight::sampleEmission(Vec2f, Vec2f uDirection, const SceneBounds&) const {
    if (shaping_.samplesDirections()) {
        auto s = shaping_.sampleDirection(uDirection);
        if (!s) return std::nullopt;
        return EmissionSample{
            position_, s->direction, s->direction, intensity_ * shaping_.factor(s->direction), {1.0f, s->pdf, 1.0f},
            true};
    }
    Vec3f direction = sampleUniformSphere(uDirection);
    return EmissionSample{
        position_, direction, direction, intensity_ * shaping_.factor(direction), {1.0f, kUniformSpherePdf, 1.0f},
        true};
}

EmissionDensity PointLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds&) const {
    return {1.0f, shaping_.samplesDirections() ? shaping_.directionPdf(direction) : kUniformSpherePdf, 1.0f};
}

}  // namespace fluence::render
