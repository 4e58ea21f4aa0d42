#include "render/bsdfs/blinn_phong.h"

#include <cmath>

#include "render/bsdfs/power_cosine.h"

namespace fluence::render {

float BlinnPhongLobe::albedoAtNormalIncidence(float n) {
    // With wo = +z, wi = reflect(wo, h) has theta_i = 2 theta_h and dwi = 4 cos theta_h dh, so
    // the albedo is 8 pi * integral over [0, pi/4] of cos^(n+1) (2 cos^2 - 1) sin d theta_h.
    return 8.0f * kPi * (n + std::exp2(-0.5f * n)) / ((n + 2.0f) * (n + 4.0f));
}

Vec3f BlinnPhongLobe::sample(const Vec3f& wo, Vec2f u, float n) { return reflect(wo, samplePowerCosine(u, n)); }

float BlinnPhongLobe::pdf(const Vec3f& wo, const Vec3f& wi, float n) {
    Vec3f h = normalize(wo + wi);
    return powerCosinePdf(h.z, n) / (4.0f * dot(wo, h));
}

}  // namespace fluence::render
