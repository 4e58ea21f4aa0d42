// UsdLux DiskLight: a flat disk emitting from its front (local -Z) side only. Its surface is put
// in the ray-tracing scene as user geometry (render/light_shape.h), so camera and BSDF rays see
// it; shadow rays do not.
//
// | UsdLux input  | type  | default | notes                                                       |
// |---------------|-------|---------|-------------------------------------------------------------|
// | radius        | float | 0.5     | a non-uniform scale keeps a disk, of the world-space area of |
// |               |       |         | the ellipse it would be                                      |
// | normalize     | bool  | false   | radiance / world-space area                                  |
// | shaping:*     |       |         | light_shaping.h                                              |
// Sampled uniformly by area; emission sampling draws a point by area and a direction
// cosine-weighted about the emitting normal.
#pragma once

#include <optional>

#include "core/frame.h"
#include "render/light.h"
#include "render/light_shape.h"
#include "render/light_shaping.h"
#include "render/scene_description.h"

namespace fluence::render {

class DiskLight final : public Light, public AnalyticLightShape {
public:
    explicit DiskLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    LightSurface surface() const override { return LightSurface::analytic(*this); }
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

    void shapeBounds(Vec3f& lo, Vec3f& hi) const override;
    std::optional<ShapeHit> intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const override;

    const Vec3f& centre() const { return centre_; }
    const Vec3f& normal() const { return frame_.n; }  // the emitting direction
    float radius() const { return radius_; }

private:
    // The power it emits without its shaping (UsdLux ShapingAPI), which power() scales and bounds() bounds.
    float unshapedPower() const;
    Vec3f centre_;
    Frame frame_;  // n: emitting direction
    float radius_, area_;
    RGB radiance_;
    LightShaping shaping_;
};

}  // namespace fluence::render
