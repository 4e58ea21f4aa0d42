// Direction helpers for BSDFs in the local shading frame (z = normal; directions point away from
// the surface, as in render/bsdf.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/vec.h"

namespace fluence::render {

// The mirror image of w in the tangent plane: the same direction seen from the other side.
inline Vec3f mirrorZ(const Vec3f& w) { return {w.x, w.y, -w.z}; }

// Mirror reflection of w about the unit normal n: 2 (w.n) n - w.
inline Vec3f reflect(const Vec3f& w, const Vec3f& n) { return n * (2.0f * dot(w, n)) - w; }

// Refraction of w (on the side n points to, w.n > 0) through an interface of relative index
// eta = n(transmitted side) / n(w's side), by Snell's law; nullopt on total internal reflection.
inline std::optional<Vec3f> refract(const Vec3f& w, const Vec3f& n, float eta) {
    float cosI = dot(w, n);
    float sin2T = std::max(0.0f, 1.0f - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0f) return std::nullopt;
    float cosT = std::sqrt(1.0f - sin2T);
    return -w / eta + n * (cosI / eta - cosT);
}

}  // namespace fluence::render
