// Rays and the offset that keeps spawned rays off the surface they leave.
#pragma once

#include <limits>

#include "core/vec.h"

namespace fluence::render {

struct Ray {
    Vec3f origin;
    Vec3f direction;  // unit length
    float tMin = 0.0f;
    float tMax = std::numeric_limits<float>::infinity();
};

// Moves a surface point off its surface along the geometric normal by a few ULPs of its
// coordinates, so rays spawned from it do not re-hit the same surface (Wächter & Binder,
// "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, 2019).
// `n` must point to the side the new ray leaves from.
Vec3f offsetRayOrigin(const Vec3f& p, const Vec3f& n);

}  // namespace fluence::render
