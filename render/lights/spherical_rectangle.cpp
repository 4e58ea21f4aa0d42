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
    r.oneLessB0Squared_ = z2 / (r.y0_ * r.y0_ + z2);
    return r;
}

Vec2f SphericalRectangle::sample(Vec2f u) const {
    // The column: the sub-rectangle [x0, xu] x [y0, y1] has solid angle u.x S. The paper's
    // au = 2 pi - g2 - g3 + u.x S is pi - t, t = u.x S - phi23, so its
    // fu = (cos au b0 - b1) / sin au = n / sin t, n = b0 cos t + b1, and its
    // xu = -cu z0 / sqrt(1 - cu^2), cu = sign(fu) / sqrt(fu^2 + b0^2), simplify to
    // xu = -z0 sign(n) sin t / sqrt(n^2 - (1 - b0^2) sin^2 t): one square root and one division
    // (1 - b0^2 = z0^2 / (y0^2 + z0^2), kept exact in oneLessB0Squared_).
    const double t = double(u.x) * solidAngle_ - phi23_;
    const double sinT = std::sin(t), n = b0_ * std::cos(t) + b1_;
    double xu = -z0_ * sinT * std::copysign(1.0, n) / std::sqrt(std::max(0.0, n * n - oneLessB0Squared_ * sinT * sinT));
    xu = std::isnan(xu) ? 0.5 * (x0_ + x1_) : std::clamp(xu, x0_, x1_);  // 0/0: n and sin t both 0
    // The row: uniform in h = y / |(xu, y, z0)| between the column's ends; y = h sqrt(dd^2 / (1 - h^2)).
    const double dd2 = xu * xu + z0_ * z0_;
    const double h0 = y0_ / std::sqrt(dd2 + y0_ * y0_), h1 = y1_ / std::sqrt(dd2 + y1_ * y1_);
    const double hv = h0 + double(u.y) * (h1 - h0);
    const double yv = std::clamp(hv * std::sqrt(dd2 / std::max(0.0, 1.0 - hv * hv)), y0_, y1_);
    return {float(std::clamp((xu - x0_) / (x1_ - x0_), 0.0, 1.0)),
            float(std::clamp((yv - y0_) / (y1_ - y0_), 0.0, 1.0))};
}

}  // namespace fluence::render
