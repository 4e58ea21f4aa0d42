#include "render/bsdfs/ggx.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sampling.h"

namespace fluence::render {

float GgxDistribution::D(const Vec3f& h) const {
    if (h.z <= 0.0f) return 0.0f;
    // (alpha^2 - 1) cos^2 + 1 written as alpha^2 cos^2 + sin^2, with sin^2 from the tangential
    // components: no cancellation near the normal, where the lobe is peaked.
    float a2 = alpha_ * alpha_;
    float t = a2 * h.z * h.z + (h.x * h.x + h.y * h.y);
    return a2 / (kPi * t * t);
}

float GgxDistribution::lambda(const Vec3f& w) const {
    float cos2 = w.z * w.z;
    if (cos2 == 0.0f) return std::numeric_limits<float>::infinity();
    float tan2 = (w.x * w.x + w.y * w.y) / cos2;
    return 0.5f * (std::sqrt(1.0f + alpha_ * alpha_ * tan2) - 1.0f);
}

Vec3f GgxDistribution::sampleVisibleNormal(const Vec3f& wo, Vec2f u) const {
    // Stretch wo to the configuration where the microsurface is a hemisphere of alpha = 1.
    Vec3f v = normalize(Vec3f(alpha_ * wo.x, alpha_ * wo.y, wo.z));
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
    return normalize(Vec3f(alpha_ * nh.x, alpha_ * nh.y, std::max(0.0f, nh.z)));
}

float GgxDistribution::visibleNormalPdf(const Vec3f& wo, const Vec3f& h) const {
    float cosO = dot(wo, h);
    if (cosO <= 0.0f || wo.z <= 0.0f) return 0.0f;
    return G1(wo) * cosO * D(h) / wo.z;
}

}  // namespace fluence::render
