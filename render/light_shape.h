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

// THE BACK OF A LIGHT. One-sided light shapes (rect lights' quads, disks) emit from their front
// only, and a ray that meets one from behind -- travelling along its emitting direction `front`,
// or edge on -- passes through it: it neither sees the light nor is blocked by it, as shadow rays
// are never blocked by lights. RenderScene applies it to quads in an Embree filter, and disks in
// their exact intersection (DiskLight::intersect); both ask this.
inline bool meetsFront(const Vec3f& rayDirection, const Vec3f& front) { return dot(rayDirection, front) < 0.0f; }

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
    // shape (a disk) is met from its emitting side only (meetsFront).
    virtual std::optional<ShapeHit> intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const = 0;
};

}  // namespace fluence::render
