#include "render/surface_differentials.h"

#include <algorithm>
#include <cmath>

#include "core/frame.h"

namespace fluence::render {

PixelFootprint pixelFootprint(const Vec3f& p, const Vec3f& n, const Vec3f& eye, float pixelsPerUnit) {
    PixelFootprint f;
    Vec3f view = p - eye;
    if (!(pixelsPerUnit > 0.0f) || lengthSquared(view) <= 0.0f) return f;
    Vec3f d = normalize(view);
    Frame screen = Frame::fromNormal(d);
    const float width = 1.0f / pixelsPerUnit;
    float cosine = dot(d, n);
    constexpr float kMinCosine = 0.05f;
    if (std::abs(cosine) < kMinCosine) cosine = std::copysign(kMinCosine, cosine == 0.0f ? 1.0f : cosine);
    // Slide each screen-plane offset along the view direction onto the surface's plane.
    auto onSurface = [&](const Vec3f& v) { return v - d * (dot(v, n) / cosine); };
    f.dpdx = onSurface(screen.s * width);
    f.dpdy = onSurface(screen.t * width);
    f.valid = true;
    return f;
}

void stAlong(const TriangleParameterisation& tri, const Vec3f& dp, float dst[2]) {
    // dp ~ a e1 + b e2 in the least-squares sense (the normal equations of the 3x2 system).
    float g11 = dot(tri.e1, tri.e1), g12 = dot(tri.e1, tri.e2), g22 = dot(tri.e2, tri.e2);
    float r1 = dot(dp, tri.e1), r2 = dot(dp, tri.e2);
    float det = g11 * g22 - g12 * g12;
    if (!(std::abs(det) > 0.0f)) {
        dst[0] = dst[1] = 0.0f;
        return;
    }
    float a = (r1 * g22 - r2 * g12) / det, b = (r2 * g11 - r1 * g12) / det;
    dst[0] = a * tri.d1[0] + b * tri.d2[0];
    dst[1] = a * tri.d1[1] + b * tri.d2[1];
}

namespace {

float stDeterminant(const TriangleParameterisation& tri) { return tri.d1[0] * tri.d2[1] - tri.d1[1] * tri.d2[0]; }

}  // namespace

Vec3f dpds(const TriangleParameterisation& tri) {
    float det = stDeterminant(tri);
    if (!(std::abs(det) > 0.0f)) return Vec3f(0.0f);
    return (tri.e1 * tri.d2[1] - tri.e2 * tri.d1[1]) / det;
}

Vec3f dpdt(const TriangleParameterisation& tri) {
    float det = stDeterminant(tri);
    if (!(std::abs(det) > 0.0f)) return Vec3f(0.0f);
    return (tri.e2 * tri.d1[0] - tri.e1 * tri.d2[0]) / det;
}

}  // namespace fluence::render
