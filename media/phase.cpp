#include "media/phase.h"

#include <algorithm>
#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"

namespace fluence::media {

float henyeyGreenstein(float cosTheta, float g) {
    // Isotropic: the expression below at g = 0 (its denominator exactly 1), without its square root
    // and division; bit for bit the same value for any cos theta but NaN.
    if (g == 0.0f && !std::isnan(cosTheta)) return 1.0f / (4.0f * kPi * 1.0f * 1.0f);
    // 1 + g^2 - 2 g cos theta, written without its cancellation near the peak (cos theta -> 1,
    // where it falls to (1 - g)^2 and sharp lobes need it to full relative precision).
    float denominator = (1.0f - g) * (1.0f - g) + 2.0f * g * (1.0f - cosTheta);
    return (1.0f - g * g) / (4.0f * kPi * denominator * std::sqrt(denominator));
}

HenyeyGreenstein::HenyeyGreenstein(float g) : g_(std::clamp(g, -kMaxG, kMaxG)) {}

float HenyeyGreenstein::p(const Vec3f& wo, const Vec3f& wi) const { return henyeyGreenstein(-dot(wo, wi), g_); }

PhaseSample HenyeyGreenstein::sample(const Vec3f& wo, Vec2f u) const {
    const float a = 2.0f * u.x - 1.0f, d = 1.0f + g_ * a;
    const float cosTheta =
        std::clamp((a + g_) / d + g_ * (1.0f - g_ * g_) * (1.0f - a * a) / (2.0f * d * d), -1.0f, 1.0f);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u.y;
    // Theta is measured from the forward direction -wo.
    Vec3f wi = Frame::fromNormal(-wo).toWorld(Vec3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
    // Evaluated at the returned direction, so that sample().pdf == pdf(wo, sample().wi) exactly.
    float value = p(wo, wi);
    return {wi, value, value};
}

}  // namespace fluence::media
