#include "render/ray.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace fluence::render {

Vec3f offsetRayOrigin(const Vec3f& p, const Vec3f& n) {
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
