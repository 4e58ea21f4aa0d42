// UsdLux SphereLight (with treatAsPoint it becomes the point light of point_light.h).
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
// Emission sampling: a point uniformly over the sphere, a cosine-weighted direction outwards.
#pragma once

#include "render/light.h"
#include "render/light_shaping.h"
#include "render/scene_description.h"

namespace fluence::render {

// The world-space radius of a sphere light: its radius scaled by the cube root of the
// transform's determinant.
float sphereLightRadius(const LightDesc& desc);
// Its shaping, about the world image of its local -Z (also the point light's).
LightShaping sphereLightShaping(const LightDesc& desc);

class SphereLight final : public Light {
public:
    explicit SphereLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    LightSurface surface() const override { return LightSurface::sphere(centre_, radius_); }
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

    const Vec3f& centre() const { return centre_; }
    float radius() const { return radius_; }

private:
    // The power it emits without its shaping (UsdLux ShapingAPI), which power() scales and bounds() bounds.
    float unshapedPower() const;
    Vec3f centre_;
    float radius_;
    RGB radiance_;
    LightShaping shaping_;
};

}  // namespace fluence::render
