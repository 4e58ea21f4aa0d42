// A rectangle as seen from a point: its solid angle and the area-preserving map from the unit
// square onto it (Ureña, Fajardo & King 2013, "An area-preserving parametrization for spherical
// rectangles", EGSR), which draws directions towards the rectangle with the uniform density
// 1 / solidAngle. RectLight samples with it where the rectangle looks big enough for the solid
// angle to pay (render/lights/rect_light.h).
//
// In the paper's frame (origin at the point, x and y along the rectangle's edges, z towards the
// rectangle's plane flipped so that the plane lies at z0 < 0) the rectangle spans
// [x0, x1] x [y0, y1]. The spherical rectangle's internal angles g0..g3 (at the projections of
// the corners (x1, y0), (x1, y1), (x0, y1), (x0, y0)) have, up to one positive factor per angle,
//   cos g = (x1 y0, -x1 y1, x0 y1, -x0 y0),  sin g = |z0| (|v10|, |v11|, |v01|, |v00|),
// where v is the vector to that corner (written out from the paper's edge-plane normals), so each
// angle is one atan2 of exact products, with no cancellation. The solid angle is
// g0 + g1 + g2 + g3 - 2 pi = phi01 + phi23 with phiij = gi + gj - pi in (-pi, pi), one atan2 of
// the product of the two angles' complex numbers each: accurate to about 1e-16 absolutely, so
// down to tiny solid angles in double (the paper's float sum of four angles loses about 1e-7).
// The map: the first number sweeps the sub-rectangle's solid angle from the x0 edge, u.x S, which
// gives the column xu; the second is uniform in the column's height h = y / sqrt(y^2 + xu^2 + z0^2),
// which gives yv.
#pragma once

#include <optional>

#include "core/vec.h"

namespace fluence::render {

class SphericalRectangle {
public:
    // The rectangle corner + a ex + b ey, a in [0, width], b in [0, height] (ex, ey orthonormal),
    // seen from p; nullopt when p lies in its plane (z0 = 0) or the solid angle is not positive.
    static std::optional<SphericalRectangle> seenFrom(const Vec3d& p, const Vec3d& corner, const Vec3d& ex,
                                                      const Vec3d& ey, double width, double height);

    double solidAngle() const { return solidAngle_; }
    // The point of the rectangle that u maps to, as fractions (a / width, b / height) in [0, 1]^2;
    // its direction from p has density 1 / solidAngle().
    Vec2f sample(Vec2f u) const;

private:
    double x0_, x1_, y0_, y1_, z0_;  // the rectangle in the local frame, z0_ < 0
    double b0_, b1_;                 // z of the unit normals of the planes through p and the y0, y1 edges
    double oneLessB0Squared_;        // 1 - b0_^2, without the cancellation
    double phi23_;                   // g2 + g3 - pi
    double solidAngle_;
};

}  // namespace fluence::render
