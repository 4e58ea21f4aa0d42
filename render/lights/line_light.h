// The line light a UsdLux CylinderLight with treatAsLine becomes (cylinder_light.h says how
// bright it is): a delta light, whose sampler picks a point uniformly in the angle the line
// subtends at p and returns that sample's estimate of the irradiance with pdf 1. No emission
// sampling (a light subpath never starts on it).
#pragma once

#include "render/light.h"
#include "render/light_shaping.h"
#include "render/scene_description.h"

namespace fluence::render {

class LineLight final : public Light {
public:
    explicit LineLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f&, const Vec3f&, const LightHit&) const override { return 0.0f; }
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;

    // Radiant intensity per unit length towards a direction at right angles to the line.
    const RGB& linearIntensity() const { return linearIntensity_; }

private:
    // The power it emits without its shaping (UsdLux ShapingAPI), which power() scales and bounds() bounds.
    float unshapedPower() const;
    Vec3f start_, axis_;  // the line runs from start_ along unit axis_ for length_
    float length_;
    RGB linearIntensity_;
    LightShaping shaping_;
};

}  // namespace fluence::render
