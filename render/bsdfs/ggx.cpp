#include "render/bsdfs/ggx.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sampling.h"

namespace fluence::render {

GgxDistribution GgxDistribution::fromRoughness(float roughness, float anisotropy) {
    float r = std::clamp(roughness, 0.0f, 1.0f);
    float alpha = r * r;
    if (!(anisotropy > 0.0f)) return GgxDistribution(alpha);
    float aspect = std::sqrt(1.0f - std::min(anisotropy, 0.98f));
    return GgxDistribution(std::min(alpha / aspect, 1.0f), alpha * aspect);
}

float GgxDistribution::D(const Vec3f& h) const {
    if (h.z <= 0.0f) return 0.0f;
    // hx^2 / ax^2 + hy^2 / ay^2 + hz^2, multiplied through by ax ay so that the tangential terms
    // carry no cancellation near the normal, where the lobe is peaked:
    // D = ax ay / (pi (ay/ax hx^2 + ax/ay hy^2 + ax ay hz^2)^2). Isotropic: alpha^2 / (pi (alpha^2
    // cos^2 + sin^2)^2).
    float t = (alphaY_ / alphaX_) * h.x * h.x + (alphaX_ / alphaY_) * h.y * h.y + alphaX_ * alphaY_ * h.z * h.z;
    return alphaX_ * alphaY_ / (kPi * t * t);
}

float GgxDistribution::lambda(const Vec3f& w) const {
    float cos2 = w.z * w.z;
    if (cos2 == 0.0f) return std::numeric_limits<float>::infinity();
    float ax = alphaX_ * w.x, ay = alphaY_ * w.y;
    return 0.5f * (std::sqrt(1.0f + (ax * ax + ay * ay) / cos2) - 1.0f);
}

Vec3f GgxDistribution::sampleVisibleNormal(const Vec3f& wo, Vec2f u) const {
    // Stretch wo to the configuration where the microsurface is a hemisphere of width 1.
    Vec3f v = normalize(Vec3f(alphaX_ * wo.x, alphaY_ * wo.y, wo.z));
    // An orthonormal basis around v (t1 horizontal).
    float lensq = v.x * v.x + v.y * v.y;
    Vec3f t1 = lensq > 0.0f ? Vec3f(-v.y, v.x, 0.0f) / std::sqrt(lensq) : Vec3f(1.0f, 0.0f, 0.0f);
    Vec3f t2 = cross(v, t1);
    // A uniform point on the unit disk, warped so that it is uniform on the projection of the
    // part of the hemisphere visible from v.
    float r = std::sqrt(u.x);
    float phi = 2.0f * kPi * u.y;
    float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    float s = 0.5f * (1.0f + v.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    // Lift onto the hemisphere and unstretch.
    Vec3f nh = t1 * p1 + t2 * p2 + v * std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2));
    return normalize(Vec3f(alphaX_ * nh.x, alphaY_ * nh.y, std::max(0.0f, nh.z)));
}

float GgxDistribution::visibleNormalPdf(const Vec3f& wo, const Vec3f& h) const {
    float cosO = dot(wo, h);
    if (cosO <= 0.0f || wo.z <= 0.0f) return 0.0f;
    return G1(wo) * cosO * D(h) / wo.z;
}

}  // namespace fluence::render
