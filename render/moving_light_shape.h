// The surface of a moving UsdLux light (render/light_motion.h) in the ray-tracing scene: one
// Embree user geometry whose box holds the light's surface over the whole shutter, and whose
// intersection takes the ray into the frame's light by the inverse of the light's motion at the
// ray's time and meets the frame's surface exactly there (the rect's quad with its one-sided rule,
// render/light_shape.h; the sphere's outside, as a still sphere light's; the disk's and
// cylinder's exact shapes). So a ray sees the
// light where sampling puts it at the same time, the shape and the samples never disagree.
#pragma once

#include <optional>

#include "render/light.h"
#include "render/light_motion.h"
#include "render/light_shape.h"

struct RTCGeometryTy;  // Embree's geometry handle (embree3/rtcore_geometry.h)
struct RTCDeviceTy;    // Embree's device handle (embree3/rtcore_device.h)

namespace fluence::render {

class MovingLightShape {
public:
    // `frame`: the light's surface at the frame (not None); `motion` is kept by reference.
    MovingLightShape(const LightSurface& frame, const LightMotion& motion);

    // The nearest hit of the ray o + t d, t in (tMin, tMax), on the surface where it is at `time`
    // (normal in world space: the emitting side's for a quad and a disk, outward otherwise).
    std::optional<ShapeHit> intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax, float time) const;
    // The box holding the surface at every time of the shutter.
    const Vec3f& lo() const { return lo_; }
    const Vec3f& hi() const { return hi_; }

    // A committed Embree user geometry of this shape (its user data: this object, which must outlive it).
    RTCGeometryTy* newGeometry(RTCDeviceTy* device) const;

private:
    std::optional<ShapeHit> intersectFrame(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const;

    LightSurface frame_;
    const LightMotion* motion_;
    Vec3f lo_, hi_;
};

}  // namespace fluence::render
