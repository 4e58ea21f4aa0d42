// Rays and the offset that keeps spawned rays off the surface they leave.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/vec.h"

namespace fluence::render {

struct Ray {
    Vec3f origin;
    Vec3f direction;  // unit length
    float tMin = 0.0f;
    float tMax = std::numeric_limits<float>::infinity();
    // When in the shutter interval the ray travels: 0 at its opening, 1 at its close (moving
    // geometry is met where it is then). A camera ray draws it; every ray of its path keeps it.
    float time = 0.0f;
    // Whether it is a camera ray (Camera::generateRay): it sees a UsdLux mesh light's surface as
    // its material shades it, not the light (RenderScene::intersect). Rays made from a hit are not.
    bool fromCamera = false;
};

// Moves a surface point off its surface along the geometric normal by a few ULPs of its
// coordinates, so rays spawned from it do not re-hit the same surface (Wächter & Binder,
// "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, 2019).
// `n` must point to the side the new ray leaves from. Inline: it runs at every path vertex.
inline Vec3f offsetRayOrigin(const Vec3f& p, const Vec3f& n) {
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    Vec3f result;
    for (int i = 0; i < 3; ++i) {
        auto offsetInt = static_cast<std::int32_t>(kIntScale * n[i]);
        std::int32_t bits = std::bit_cast<std::int32_t>(p[i]);
        float moved = std::bit_cast<float>(bits + (p[i] < 0.0f ? -offsetInt : offsetInt));
        result[i] = std::abs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : moved;
    }
    return result;
}

}  // namespace fluence::render
