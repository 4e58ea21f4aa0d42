// The camera's importance, densities and connections (render/camera.h, "Importance"), for light
// tracing: bdpt's t = 1 strategy (integrators/bdpt.h).
#include <cmath>
#include <optional>

#include "render/camera.h"

namespace fluence::render {

float Camera::directionDensity(const Vec3f& w, Vec2f aperture) const {
    if (!hasImportance()) return 0.0f;
    const Vec3d local = toCamera_.transformVector(Vec3d(w));
    if (!(local.z < 0.0)) return 0.0f;  // the camera looks along -Z
    const double mx = local.x / -local.z, my = local.y / -local.z;
    double wx = mx, wy = my;  // where the ray crosses the window (through the plane of focus it aims at)
    if (!lens_.isPinhole()) {
        wx += aperture.x / double(lens_.focusDistance);
        wy += aperture.y / double(lens_.focusDistance);
    }
    if (std::abs(wx - centreX_) > halfWidth_ || std::abs(wy - centreY_) > halfHeight_) return 0.0f;
    // The direction m = (mx, my, -1), at unit depth in camera space, is seen along the world vector
    // T m (T the transform's linear part), so a patch dA of the window spans the solid angle
    // |det T| |det(e_x, e_y, m)| dA / |T m|^3 = |det T| dA / |T m|^3. Uniform over the window's area
    // 4 halfWidth halfHeight, a direction's density is therefore |T m|^3 / (|det T| 4 halfWidth halfHeight).
    const double seen = length(toWorld_.transformVector(Vec3d(mx, my, -1.0)));
    const double window = 4.0 * double(halfWidth_) * double(halfHeight_);
    return static_cast<float>(seen * seen * seen / (std::abs(toWorld_.determinant3x3()) * window));
}

float Camera::importance(const Vec3f& w, Vec2f aperture) const {
    const float density = directionDensity(w, aperture);
    return density > 0.0f ? density / dot(w, forward_) : 0.0f;
}

Vec2f Camera::apertureOf(const Vec3f& origin) const {
    if (lens_.isPinhole()) return {0.0f, 0.0f};
    const Vec3d local = toCamera_.transformPoint(Vec3d(origin));
    return {static_cast<float>(local.x), static_cast<float>(local.y)};
}

std::optional<Vec2f> Camera::rasterPosition(const Vec3f& worldPoint, Vec2f aperture) const {
    if (!hasImportance()) return std::nullopt;
    const float depth = viewDepth(worldPoint);  // from the lens plane, which holds the aperture
    if (!(depth > near_) || !(depth <= far_)) return std::nullopt;
    Vec3d local = toCamera_.transformPoint(Vec3d(worldPoint));
    if (!(local.z < 0.0)) return std::nullopt;
    double wx = local.x / -local.z, wy = local.y / -local.z;
    if (!lens_.isPinhole()) {  // seen from the aperture point, through the plane of focus
        const double f = lens_.focusDistance;
        wx = aperture.x / f + (local.x - aperture.x) / -local.z;
        wy = aperture.y / f + (local.y - aperture.y) / -local.z;
    }
    // generateRay's mapping from pixels to the window, inverted.
    const double sx = (wx - centreX_) / halfWidth_, sy = (wy - centreY_) / halfHeight_;
    const auto x = static_cast<float>(0.5 * (sx + 1.0) * width_), y = static_cast<float>(0.5 * (1.0 - sy) * height_);
    if (!(x >= 0.0f && x < static_cast<float>(width_) && y >= 0.0f && y < static_cast<float>(height_)))
        return std::nullopt;
    return Vec2f{x, y};
}

std::optional<Camera::Connection> Camera::connect(const Vec3f& worldPoint, Vec2f aperture) const {
    const std::optional<Vec2f> raster = rasterPosition(worldPoint, aperture);
    if (!raster) return std::nullopt;
    // As generateRay places the aperture point.
    const Vec3f lensPoint = lens_.isPinhole() ? position_ : position_ + axisX_ * aperture.x + axisY_ * aperture.y;
    const Vec3f d = lensPoint - worldPoint;
    const float distance = length(d);
    if (!(distance > 0.0f)) return std::nullopt;
    Connection c;
    c.raster = *raster;
    c.lensPoint = lensPoint;
    c.direction = d / distance;
    c.distance = distance;
    const float cosView = -dot(c.direction, forward_);
    c.density = directionDensity(-c.direction, aperture);
    if (!(cosView > 0.0f) || !(c.density > 0.0f)) return std::nullopt;
    c.nearDistance = near_ / cosView;
    c.importance = c.density / (distance * distance);
    return c;
}

}  // namespace fluence::render
