#include "render/lights/spherical_rectangle.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fluence::render {

namespace {

// gi + gj - pi, for two angles in (0, pi) given as (cos, sin) up to positive factors: the
// argument of -(ci + i si)(cj + i sj), which lies in (-pi, pi).
double sumLessPi(double ci, double si, double cj, double sj) {
    return std::atan2(-(ci * sj + si * cj), -(ci * cj - si * sj));
}

}  // namespace

std::optional<SphericalRectangle> SphericalRectangle::seenFrom(const Vec3d& p, const Vec3d& corner, const Vec3d& ex,
                                                               const Vec3d& ey, double width, double height) {
    const Vec3d d = corner - p;
    SphericalRectangle r;
    r.x0_ = dot(d, ex);
    r.y0_ = dot(d, ey);
    r.z0_ = -std::abs(dot(d, cross(ex, ey)));
    if (!(r.z0_ < 0.0)) return std::nullopt;
    r.x1_ = r.x0_ + width;
    r.y1_ = r.y0_ + height;
    const double z2 = r.z0_ * r.z0_, az = -r.z0_;
    auto reach = [z2](double x, double y) { return std::sqrt(x * x + y * y + z2); };  // |v| to a corner
    r.phi23_ = sumLessPi(r.x0_ * r.y1_, az * reach(r.x0_, r.y1_), -r.x0_ * r.y0_, az * reach(r.x0_, r.y0_));
    const double phi01 = sumLessPi(r.x1_ * r.y0_, az * reach(r.x1_, r.y0_), -r.x1_ * r.y1_, az * reach(r.x1_, r.y1_));
    r.solidAngle_ = phi01 + r.phi23_;
    if (!(r.solidAngle_ > 0.0)) return std::nullopt;
    r.b0_ = -r.y0_ / std::sqrt(r.y0_ * r.y0_ + z2);
    r.b1_ = r.y1_ / std::sqrt(r.y1_ * r.y1_ + z2);
    return r;
}

Vec2f SphericalRectangle::sample(Vec2f u) const {
    // The column: the sub-rectangle [x0, xu] x [y0, y1] has solid angle u.x S. With the paper's
    // au = 2 pi - g2 - g3 + u.x S = pi - t, t = u.x S - phi23, its
    // fu = (cos au b0 - b1) / sin au = (b0 cos t + b1) / sin t is cot of the angle the plane through
    // p and the column makes, and xu = -cu z0 / sqrt(1 - cu^2) with cu = sign(fu) / sqrt(fu^2 + b0^2).
    const double t = double(u.x) * solidAngle_ - phi23_;
    const double fu = (b0_ * std::cos(t) + b1_) / std::sin(t);
    const double cu = std::clamp(std::copysign(1.0 / std::sqrt(fu * fu + b0_ * b0_), fu), -1.0, 1.0);
    double xu = -cu * z0_ / std::sqrt(std::max(0.0, 1.0 - cu * cu));
    xu = std::isnan(xu) ? 0.5 * (x0_ + x1_) : std::clamp(xu, x0_, x1_);  // 0/0: sin t and its numerator both 0
    // The row: uniform in h = y / |(xu, y, z0)| between the column's ends.
    const double dd2 = xu * xu + z0_ * z0_;
    const double h0 = y0_ / std::sqrt(dd2 + y0_ * y0_), h1 = y1_ / std::sqrt(dd2 + y1_ * y1_);
    const double hv = h0 + double(u.y) * (h1 - h0);
    const double yv = std::clamp(hv * std::sqrt(dd2) / std::sqrt(std::max(0.0, 1.0 - hv * hv)), y0_, y1_);
    const double width = x1_ - x0_, height = y1_ - y0_;
    return {float(std::clamp((xu - x0_) / width, 0.0, 1.0)), float(std::clamp((yv - y0_) / height, 0.0, 1.0))};
}

}  // namespace fluence::render
