#include "render/lights/distant_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/check.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "render/lights/emission_at_infinity.h"

namespace fluence::render {

DistantLight::DistantLight(const LightDesc& d) : InfiniteLight(d.name), value_(d.radiance) {
    towardsLight_ = normalize(Vec3f(d.transform.transformVector({0.0, 0.0, 1.0})));
    double halfAngle = std::clamp(double(d.angleDegrees), 0.0, 359.999) * 0.5 * std::numbers::pi / 180.0;
    oneMinusCosMax_ = halfAngle > 0.0 ? 2.0 * std::sin(0.5 * halfAngle) * std::sin(0.5 * halfAngle) : 0.0;
    if (!isDelta() && d.normalize) {
        // UsdLux's sizeFactor: pi sin^2(theta_max), the irradiance a uniform disk of radiance 1
        // gives a surface facing it, up to a hemisphere; (2 - sin^2(theta_max)) pi beyond.
        double sin2 = std::sin(halfAngle) * std::sin(halfAngle);
        value_ /= static_cast<float>(std::numbers::pi * (halfAngle <= std::numbers::pi / 2 ? sin2 : 2.0 - sin2));
    }
}

std::optional<LightSample> DistantLight::sample(const Vec3f&, Vec2f u) const {
    if (isDelta()) return LightSample{value_, towardsLight_, std::numeric_limits<float>::infinity(), 1.0f, true};
    double cosTheta = 1.0 - u.x * oneMinusCosMax_;
    double sinTheta = std::sqrt(std::max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
    double phi = 2.0 * std::numbers::pi * u.y;
    FLUENCE_DCHECK(isUnit(towardsLight_) && oneMinusCosMax_ > 0.0);
    Vec3f wi = normalize(
        Frame::fromNormal(towardsLight_)
            .toWorld(Vec3f(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta))));
    return LightSample{value_, wi, std::numeric_limits<float>::infinity(),
                       static_cast<float>(1.0 / (2.0 * std::numbers::pi * oneMinusCosMax_)), false};
}

float DistantLight::pdf(const Vec3f&, const Vec3f& wi, const LightHit&) const {
    if (isDelta() || 1.0 - double(dot(wi, towardsLight_)) > oneMinusCosMax_) return 0.0f;
    return static_cast<float>(1.0 / (2.0 * std::numbers::pi * oneMinusCosMax_));
}

RGB DistantLight::escaped(const Vec3f& direction) const {
    if (isDelta() || 1.0 - double(dot(direction, towardsLight_)) > oneMinusCosMax_) return RGB(0.0f);
    return value_;
}

float DistantLight::power(const SceneBounds& b) const {
    float irradiance = isDelta() ? luminance(value_)
                                 : luminance(value_) * static_cast<float>(2.0 * std::numbers::pi * oneMinusCosMax_);
    return irradiance * kPi * b.radius * b.radius;
}

std::optional<EmissionSample> DistantLight::sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                           const SceneBounds& scene) const {
    std::optional<LightSample> s = sample(scene.centre, uDirection);
    if (!s) return std::nullopt;
    EmissionSample e = fromInfinity(-s->wi, s->pdf, s->Li, uPosition, scene);
    e.delta = s->delta;
    return e;
}

EmissionDensity DistantLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds& scene) const {
    return {infinityPositionDensity(scene), isDelta() ? 1.0f : pdf(scene.centre, -direction, {}), 1.0f};
}

}  // namespace fluence::render
