#include "render/thin_lens.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/sampling.h"

namespace fluence::render {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
}

Vec2f ThinLens::sampleAperture(Vec2f u) const {
    if (blades < 3) {
        const Vec2f d = sampleUniformDisk(u);
        return {d.x * radius, d.y * radius};
    }
    // The polygon is `blades` equal triangles (the centre and two neighbouring vertices): u.x picks
    // one and, rescaled, places the point in it with u.y.
    const float scaled = u.x * static_cast<float>(blades);
    const int k = std::min(static_cast<int>(scaled), blades - 1);
    const float a = scaled - static_cast<float>(k), b = u.y;
    const float root = std::sqrt(a);  // uniform over the triangle (centre, v_k, v_k+1)
    const float s = root * (1.0f - b), t = root * b;
    const float step = 2.0f * kPi / static_cast<float>(blades), start = rotationDegrees * (kPi / 180.0f);
    const float angle0 = start + step * static_cast<float>(k), angle1 = angle0 + step;
    return {radius * (s * std::cos(angle0) + t * std::cos(angle1)),
            radius * (s * std::sin(angle0) + t * std::sin(angle1))};
}

}  // namespace fluence::render
