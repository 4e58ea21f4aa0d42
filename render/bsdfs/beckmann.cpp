#include "render/bsdfs/beckmann.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"

namespace fluence::render {

float BeckmannDistribution::D(const Vec3f& h) const {
    if (h.z <= 0.0f) return 0.0f;
    float cos2 = h.z * h.z;
    float tan2 = (h.x * h.x + h.y * h.y) / cos2;  // no cancellation near the normal
    float m2 = m_ * m_;
    return std::exp(-tan2 / m2) / (kPi * m2 * cos2 * cos2);
}

Vec3f BeckmannDistribution::sampleNormal(Vec2f u) const {
    float tan2 = -m_ * m_ * std::log1p(-u.x);
    float cosTheta = 1.0f / std::sqrt(1.0f + tan2);
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

}  // namespace fluence::render
