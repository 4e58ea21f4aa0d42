// The pinhole camera's importance, densities and connections (render/camera.h, "Importance"), for
// light tracing: bdpt's t = 1 strategy (integrators/bdpt.h).
#include <cmath>
#include <optional>

#include "render/camera.h"

namespace fluence::render {

float Camera::directionDensity(const Vec3f& w) const {
    if (!hasImportance()) return 0.0f;
    const Vec3d local = toCamera_.transformVector(Vec3d(w));
    if (!(local.z < 0.0)) return 0.0f;  // the camera looks along -Z
    const double wx = local.x / -local.z, wy = local.y / -local.z;
    if (std::abs(wx - centreX_) > halfWidth_ || std::abs(wy - centreY_) > halfHeight_) return 0.0f;
    // The window point m = (wx, wy, -1), at unit distance in camera space, is seen along the world
    // vector T m (T the transform's linear part), so a patch dA of the window spans the solid angle
    // |det T| |det(e_x, e_y, m)| dA / |T m|^3 = |det T| dA / |T m|^3. Uniform over the window's area
    // 4 halfWidth halfHeight, a direction's density is therefore |T m|^3 / (|det T| 4 halfWidth halfHeight).
    const double seen = length(toWorld_.transformVector(Vec3d(wx, wy, -1.0)));
    const double window = 4.0 * double(halfWidth_) * double(halfHeight_);
    return static_cast<float>(seen * seen * seen / (std::abs(toWorld_.determinant3x3()) * window));
}

float Camera::importance(const Vec3f& w) const {
    const float density = directionDensity(w);
    return density > 0.0f ? density / dot(w, forward_) : 0.0f;
}

std::optional<Vec2f> Camera::rasterPosition(const Vec3f& worldPoint) const {
    if (!hasImportance()) return std::nullopt;
    const float depth = viewDepth(worldPoint);
    if (!(depth > near_) || !(depth <= far_)) return std::nullopt;
    const Vec3d local = toCamera_.transformPoint(Vec3d(worldPoint));
    if (!(local.z < 0.0)) return std::nullopt;
    // generateRay's mapping from pixels to the window, inverted.
    const double sx = (local.x / -local.z - centreX_) / halfWidth_, sy = (local.y / -local.z - centreY_) / halfHeight_;
    const auto x = static_cast<float>(0.5 * (sx + 1.0) * width_), y = static_cast<float>(0.5 * (1.0 - sy) * height_);
    if (!(x >= 0.0f && x < static_cast<float>(width_) && y >= 0.0f && y < static_cast<float>(height_)))
        return std::nullopt;
    return Vec2f{x, y};
}

std::optional<Camera::Connection> Camera::connect(const Vec3f& worldPoint) const {
    const std::optional<Vec2f> raster = rasterPosition(worldPoint);
    if (!raster) return std::nullopt;
    const Vec3f d = position_ - worldPoint;
    const float distance = length(d);
    if (!(distance > 0.0f)) return std::nullopt;
    Connection c;
    c.raster = *raster;
    c.direction = d / distance;
    c.distance = distance;
    const float cosView = -dot(c.direction, forward_);
    c.density = directionDensity(-c.direction);
    if (!(cosView > 0.0f) || !(c.density > 0.0f)) return std::nullopt;
    c.nearDistance = near_ / cosView;
    c.importance = c.density / (distance * distance);
    return c;
}

}  // namespace fluence::render
