// The power-cosine lobe about +z, density (n + 1) / (2 pi) cos^n theta over the hemisphere: the
// sampling distribution of the Phong-family lobes (Lafortune & Willems 1994).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/sampling.h"

namespace fluence::render {

// cos theta = u.x^(1 / (n + 1)), phi = 2 pi u.y.
inline Vec3f samplePowerCosine(Vec2f u, float n) {
    float cosTheta = std::pow(u.x, 1.0f / (n + 1.0f));
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

inline float powerCosinePdf(float cosTheta, float n) {
    return cosTheta > 0.0f ? (n + 1.0f) / (2.0f * kPi) * std::pow(cosTheta, n) : 0.0f;
}

}  // namespace fluence::render
