// The point light a UsdLux SphereLight with treatAsPoint becomes (sphere_light.h says how bright
// it is): a delta light, whose sample() returns the irradiance I / d^2 with pdf 1. Emission
// sampling draws a direction uniformly over the sphere (cone and focus only weight it), or, with
// an IES profile, from the shaping's direction density (render/light_shaping.h).
#pragma once

#include "render/light.h"
#include "render/light_shaping.h"
#include "render/scene_description.h"

namespace fluence::render {

class PointLight final : public Light {
public:
    explicit PointLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f&, const Vec3f&, const LightHit&) const override { return 0.0f; }
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

    const RGB& intensity() const { return intensity_; }

private:
    // The power it emits without its shaping (UsdLux ShapingAPI), which power() scales and bounds() bounds.
    float unshapedPower() const;
    Vec3f position_;
    RGB intensity_;
    LightShaping shaping_;
};

}  // namespace fluence::render
