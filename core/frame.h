// An orthonormal frame (tangent, bitangent, normal): world <-> local shading space, z = normal.
#pragma once

#include <cmath>

#include "core/vec.h"

namespace fluence {

struct Frame {
    Vec3f s, t, n;

    // Builds a frame around a unit normal without branches on the sign (Duff et al. 2017,
    // "Building an Orthonormal Basis, Revisited").
    static Frame fromNormal(const Vec3f& n) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        return {Vec3f(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3f(b, sign + n.y * n.y * a, -n.y), n};
    }
    // A frame around a unit normal whose s axis points along `tangent` (made perpendicular to n by
    // Gram-Schmidt), so that anisotropic lobes line up with the surface; t = n x s keeps the frame
    // right-handed. Falls back to fromNormal() when the tangent is zero or (nearly) along n.
    static Frame fromNormalAndTangent(const Vec3f& n, const Vec3f& tangent) {
        Vec3f s = tangent - n * dot(n, tangent);
        float len2 = lengthSquared(s);
        if (!(len2 > 1e-8f)) return fromNormal(n);
        s = s / std::sqrt(len2);
        return {s, cross(n, s), n};
    }
    Vec3f toLocal(const Vec3f& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3f toWorld(const Vec3f& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace fluence
