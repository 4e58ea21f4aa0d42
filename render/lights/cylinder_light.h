// UsdLux CylinderLight (with treatAsLine it becomes the line light of line_light.h).
//
// | UsdLux input  | type  | default | notes                                                       |
// |---------------|-------|---------|-------------------------------------------------------------|
// | length        | float | 1       | along local X, scaled by the transform's X axis              |
// | radius        | float | 0.5     | scaled to keep the area of the cross-section the transform  |
// |               |       |         | gives (sqrt of its YZ area scale)                           |
// | normalize     | bool  | false   | radiance / world-space side area (2 pi r length)             |
// | treatAsLine   | bool  | false   | a line light of the same power (below)                       |
// | shaping:*     |       |         | light_shaping.h, about the light's local -Z                  |
//
// The cylinder emits radiance L outwards from its side; its flat end caps emit nothing (UsdLux)
// and are not part of its surface. The sampler works in the plane across the axis, where a point
// p at distance h > r from the axis sees the cross-section's circle under +-asin(r/h): it picks
// a direction uniformly in that angle (landing on the arc that faces p, so no sample is wasted
// on the back) and a position along the axis uniformly. Its density in solid angle is
// d^3 / (2 asin(r/h) length rho^2), with d the distance to the point and rho that distance
// across the axis: bounded, unlike area sampling's, which grows as 1/cos at the silhouette.
//
// UsdLux calls treatAsLine "a hint that this light can be treated as a line light (effectively, a
// zero-radius cylinder)" without saying how bright the line is. Fluence keeps the cylinder's power
// and far field: each unit of length emits intensity 2 r L sin(theta) at angle theta to the axis
// (the cylinder's projected width is 2 r sin(theta)), so the line's power is pi^2 (2 r L) length,
// the cylinder's 2 pi^2 r L length. Normalized, 2 r L / (2 pi r length) = L / (pi length).
// The line is a delta light: its sampler picks a point uniformly in the angle the line subtends
// at p and returns that sample's estimate of the irradiance with pdf 1.
// Cylinder lights offer no emission sampling (a light subpath never starts on them).
#pragma once

#include "core/frame.h"
#include "render/light.h"
#include "render/light_shape.h"
#include "render/light_shaping.h"
#include "render/scene_description.h"

namespace fluence::render {

// The cylinder a LightDesc describes, in world space (also the line light's).
struct Cylinder {
    Vec3f centre, axis;
    float length, radius;
    RGB radiance;  // normalized by the side area when asked
    LightShaping shaping;
};
Cylinder cylinderOf(const LightDesc& desc);

// Box around a segment of `length` centred at `centre` along unit `axis`, widened by `radius`
// across it.
void segmentBounds(const Vec3f& centre, const Vec3f& axis, float length, float radius, Vec3f& lo, Vec3f& hi);

class CylinderLight final : public Light, public AnalyticLightShape {
public:
    explicit CylinderLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    LightSurface surface() const override { return LightSurface::analytic(*this); }

    void shapeBounds(Vec3f& lo, Vec3f& hi) const override;
    std::optional<ShapeHit> intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const override;

    const Vec3f& centre() const { return centre_; }
    const Vec3f& axis() const { return frame_.n; }
    float radius() const { return radius_; }
    float length() const { return length_; }

private:
    // The power it emits without its shaping (UsdLux ShapingAPI), which power() scales and bounds() bounds.
    float unshapedPower() const;
    // Half the angle the cross-section subtends at p, across the axis (0 when p is within the
    // radius of the axis: only the open ends are in view).
    float halfAngleAcross(const Vec3f& p) const;

    Vec3f centre_;
    Frame frame_;  // n: the cylinder's axis (local +X)
    float radius_, length_;
    RGB radiance_;
    LightShaping shaping_;
};

}  // namespace fluence::render
