// The surface of a disk or cylinder light, for the ray-tracing scene.
//
// Rect and sphere lights are put in Embree as triangles and as an Embree sphere. Disks and
// cylinders are not Embree primitives; tessellating them would make the surface rays hit differ
// from the one the light samples (and the MIS weights disagree at its rim), so RenderScene puts
// them in as Embree user geometry whose callbacks call this exact intersection.
#pragma once

#include <optional>

#include "core/vec.h"

namespace fluence::render {

struct ShapeHit {
    float t = 0.0f;
    Vec3f normal;  // unit geometric normal: the emitting side's for a disk, outward for a cylinder
};

class AnalyticLightShape {
public:
    virtual ~AnalyticLightShape() = default;
    // World-space box holding the surface.
    virtual void shapeBounds(Vec3f& lo, Vec3f& hi) const = 0;
    // The nearest intersection of the ray o + t d with the surface for t in (tMin, tMax); a one-sided
    // shape (a disk) is met from its emitting side only, as rect lights are (RenderScene).
    virtual std::optional<ShapeHit> intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const = 0;
};

}  // namespace fluence::render
