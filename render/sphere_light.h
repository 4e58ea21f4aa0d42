// UsdLux SphereLight, and the point light it becomes with treatAsPoint.
//
// | UsdLux input   | type  | default | notes                                                      |
// |----------------|-------|---------|------------------------------------------------------------|
// | radius         | float | 0.5     | a non-uniform scale is reduced to the cube root of the     |
// |                |       |         | transform's determinant                                     |
// | normalize      | bool  | false   | radiance / world-space area (4 pi r^2)                      |
// | treatAsPoint   | bool  | false   | a point light of the same power (below)                     |
// | shaping:*      |       |         | light_shaping.h, about the light's local -Z                 |
//
// The sphere emits radiance L outwards everywhere and is sampled uniformly within the cone it
// subtends (exact solid-angle sampling of the visible cap).
//
// UsdLux calls treatAsPoint "a hint that this light can be treated as a point light (effectively,
// a zero-radius sphere)" and does not say how bright that point is. Fluence keeps the power of the
// sphere it stands for: intensity I = L pi r^2 (L / 4 when normalized, whatever the radius), which
// gives the irradiance pi L (r/d)^2 the sphere gives a surface facing it at any distance d > r.
// A zero-radius sphere that is not normalized therefore emits nothing (the delegate warns).
#pragma once

#include "render/light.h"
#include "render/light_shaping.h"
#include "render/scene_description.h"

namespace fluence::render {

class SphereLight final : public Light {
public:
    explicit SphereLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    std::string name() const override { return name_; }
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction, const SceneBounds& scene) const override;

    const Vec3f& centre() const { return centre_; }
    float radius() const { return radius_; }

private:
    std::string name_;
    Vec3f centre_;
    float radius_;
    RGB radiance_;
    LightShaping shaping_;
};

// A point light (a delta light: sample() returns the irradiance I / d^2 with pdf 1).
class PointLight final : public Light {
public:
    explicit PointLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f&, const Vec3f&, const LightHit&) const override { return 0.0f; }
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    std::string name() const override { return name_; }
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction, const SceneBounds& scene) const override;

    const RGB& intensity() const { return intensity_; }

private:
    std::string name_;
    Vec3f position_;
    RGB intensity_;
    LightShaping shaping_;
};

}  // namespace fluence::render
