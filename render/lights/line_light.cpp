#include "render/lights/line_light.h"

#include <cmath>

#include "core/sampling.h"
#include "render/lights/cylinder_light.h"

namespace fluence::render {

LineLight::LineLight(const LightDesc& d) : Light(d.name) {
    Cylinder c = cylinderOf(d);
    axis_ = c.axis;
    length_ = c.length;
    start_ = c.centre - axis_ * (0.5f * length_);
    linearIntensity_ = c.radiance * (2.0f * c.radius);
    shaping_ = c.shaping;
}

std::optional<LightSample> LineLight::sample(const Vec3f& p, Vec2f u) const {
    // With p's foot on the line at `along` and distance h, a point at offset s from the foot is at
    // angle phi = atan(s / h). Uniform phi has density h / d^2 per unit length, which cancels the
    // inverse square law: the estimate of E = integral of I sin(theta) cos / d^2 ds is
    // I (h/d) cos / d^2 * d^2 / h * (phi1 - phi0) = I (phi1 - phi0) cos / d.
    Vec3f q = p - start_;
    float along = dot(q, axis_);
    float h = length(q - axis_ * along);
    if (!(h > 1e-6f * length_)) return std::nullopt;
    float phi0 = std::atan2(-along, h), phi1 = std::atan2(length_ - along, h);
    float phi = phi0 + u.x * (phi1 - phi0);
    Vec3f point = start_ + axis_ * (along + h * std::tan(phi));
    Vec3f d = point - p;
    float dist = length(d);
    Vec3f wi = d / dist;
    return LightSample{linearIntensity_ * shaping_.factor(-wi) * ((phi1 - phi0) / dist), wi, dist, 1.0f, true};
}

float LineLight::unshapedPower() const { return luminance(linearIntensity_) * kPi * kPi * length_; }

float LineLight::power(const SceneBounds&) const { return unshapedPower() * shaping_.powerFraction(false); }

std::optional<LightBounds> LineLight::bounds() const {
    LightBounds b;
    segmentBounds(start_ + axis_ * (0.5f * length_), axis_, length_, 0.0f, b.lo, b.hi);
    b.phi = unshapedPower();
    return shaping_.narrow(b, false);
}

}  // namespace fluence::render
