// Equiangular distance sampling (Kulla & Fajardo 2012, "Importance sampling techniques for path
// tracing in participating media", section 4.1): a distance t along a ray segment drawn so that
// the point ray.at(t), seen from a light's centre c, sweeps the angle uniformly. Single
// scattering from a point light falls off as 1 / |x(t) - c|^2; this density follows it exactly,
// where free-flight sampling (media/free_flight.h) follows the transmittance from the ray's start
// and rarely lands near a light deep inside a medium.
//
// With Delta the t of the point of the ray's line closest to c and D its distance from c,
//     t = Delta + D tan(theta),  theta uniform over [thetaA, thetaB],
//     thetaA = atan((tMin - Delta) / D),  thetaB = atan((tMax - Delta) / D),
// and the density over t in [tMin, tMax] is
//     pdf(t) = D / ((thetaB - thetaA) (D^2 + (t - Delta)^2)).
// tMax may be infinite (thetaB = pi / 2). A centre on the ray's line (D = 0) would make the
// density a Dirac delta: D is held at least kMinDistance times the segment's scale (its length,
// or |Delta| and the distance to its start when it is unbounded), which keeps the density finite
// and the sampler and pdf exactly consistent. Evaluated in double precision: far from c, tan and
// atan of nearly equal angles would lose the float's digits.
//
// This is the sampler alone; how the path tracer chooses the light, estimates the transmittance
// to the point and weighs it against free-flight sampling is in integrators/equiangular_strategy.h.
#pragma once

#include "core/vec.h"

namespace fluence::media {

class EquiangularDistance {
public:
    static constexpr double kMinDistance = 1e-4;

    // The segment origin + t direction, t in [tMin, tMax] (0 <= tMin < tMax; tMax may be
    // infinite), towards `centre`; direction is a unit vector.
    EquiangularDistance(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax, const Vec3f& centre);

    // t in [tMin, tMax] from u in [0, 1).
    float sample(float u) const;
    // The density sample() draws t with, per unit length; 0 outside [tMin, tMax].
    float pdf(float t) const;

private:
    double delta_ = 0.0, distance_ = 0.0, thetaA_ = 0.0, thetaB_ = 0.0;
    float tMin_, tMax_;
};

}  // namespace fluence::media
