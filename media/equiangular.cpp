#include "media/equiangular.h"

#include <algorithm>
#include <cmath>

namespace fluence::media {

EquiangularDistance::EquiangularDistance(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                                         const Vec3f& centre)
    : tMin_(tMin), tMax_(tMax) {
    const Vec3d toCentre = Vec3d(centre) - Vec3d(origin), w(direction);
    delta_ = dot(toCentre, w);
    const double scale =
        std::isfinite(tMax) ? double(tMax) - double(tMin) : std::max(std::abs(delta_), length(toCentre));
    distance_ = std::max(length(toCentre - w * delta_), kMinDistance * std::max(scale, 1e-30));
    thetaA_ = std::atan((double(tMin) - delta_) / distance_);
    thetaB_ = std::isfinite(tMax) ? std::atan((double(tMax) - delta_) / distance_) : 0.5 * 3.14159265358979323846;
}

float EquiangularDistance::sample(float u) const {
    const double theta = thetaA_ + double(u) * (thetaB_ - thetaA_);
    return std::clamp(float(delta_ + distance_ * std::tan(theta)), tMin_, tMax_);
}

float EquiangularDistance::pdf(float t) const {
    if (!(t >= tMin_ && t <= tMax_) || !(thetaB_ > thetaA_)) return 0.0f;
    const double x = double(t) - delta_;
    return float(distance_ / ((thetaB_ - thetaA_) * (distance_ * distance_ + x * x)));
}

}  // namespace fluence::media
