#include "render/light_motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/motion_geometry.h"

namespace fluence::render {

namespace {

// The upper 3x3 of m (the rest the identity's).
Matrix4 linearPart(const Matrix4& m) {
    Matrix4 r = Matrix4::identity();
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) r.m[row][column] = m.m[row][column];
    return r;
}

Matrix4 transposed(const Matrix4& m) {
    Matrix4 t = Matrix4::identity();
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) t.m[row][column] = m.m[column][row];
    return t;
}

// The rotation nearest to the invertible linear map a (its polar factor), by Newton's iteration
// X <- (X + X^-T) / 2, which converges quadratically from a itself.
Matrix4 nearestRotation(Matrix4 x) {
    for (int iteration = 0; iteration < 32; ++iteration) {
        const std::optional<Matrix4> inverse = x.inverse();
        if (!inverse) return Matrix4::identity();
        const Matrix4 inverseTranspose = transposed(*inverse);
        double change = 0.0;
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < 3; ++column) {
                const double next = 0.5 * (x.m[row][column] + inverseTranspose.m[row][column]);
                change = std::max(change, std::abs(next - x.m[row][column]));
                x.m[row][column] = next;
            }
        if (change < 1e-12) break;
    }
    return x;
}

Vec3d originOf(const Matrix4& m) { return Vec3d(m.m[0][3], m.m[1][3], m.m[2][3]); }

bool sameLinearPart(const Matrix4& a, const Matrix4& b) {
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            if (a.m[row][column] != b.m[row][column]) return false;
    return true;
}

}  // namespace

LightMotion::LightMotion(const Matrix4& frame, std::vector<Matrix4> steps) : frame_(frame), steps_(std::move(steps)) {
    if (steps_.size() < 2) throw std::invalid_argument("light motion needs at least two time steps");
    turns_ = std::any_of(steps_.begin(), steps_.end(), [&](const Matrix4& s) { return !sameLinearPart(s, frame_); });
}

RigidMotion LightMotion::at(float time) const {
    const Matrix4 placed = transformAt(steps_, time);
    Matrix4 rotation = Matrix4::identity();
    if (turns_) {
        const std::optional<Matrix4> frameInverse = linearPart(frame_).inverse();
        if (frameInverse) rotation = nearestRotation(linearPart(placed) * *frameInverse);
    }
    const Vec3d from = originOf(frame_), to = originOf(placed);
    return {Matrix4::translate(to) * rotation * Matrix4::translate(-from),
            Matrix4::translate(from) * transposed(rotation) * Matrix4::translate(-to)};
}

LightBounds LightMotion::sweptBounds(const LightBounds& frame) const {
    const Vec3d origin = originOf(frame_);
    std::vector<LightBounds> places;
    if (!turns_) {
        for (const Matrix4& step : steps_) {
            const Vec3f offset(originOf(step) - origin);
            LightBounds b = frame;
            b.lo = frame.lo + offset;
            b.hi = frame.hi + offset;
            places.push_back(b);
        }
        return unionOfLightBounds(places);
    }
    // The ball about the origin holding the box: to its farthest corner.
    const Vec3d centre = (Vec3d(frame.lo) + Vec3d(frame.hi)) * 0.5;
    const double reach = length(centre - origin) + 0.5 * length(Vec3d(frame.hi) - Vec3d(frame.lo));
    for (const Matrix4& step : steps_) {
        LightBounds b = frame;
        b.lo = Vec3f(originOf(step) - Vec3d(reach));
        b.hi = Vec3f(originOf(step) + Vec3d(reach));
        b.cosThetaO = -1.0f;
        places.push_back(b);
    }
    return unionOfLightBounds(places);
}

LightBounds unionOfLightBounds(const std::vector<LightBounds>& places) {
    LightBounds u = places.front();
    for (const LightBounds& b : places) {
        u.lo = vmin(u.lo, b.lo);
        u.hi = vmax(u.hi, b.hi);
        u.phi = std::max(u.phi, b.phi);
        u.cosThetaE = std::min(u.cosThetaE, b.cosThetaE);
        u.twoSided = u.twoSided || b.twoSided;
        if (b.axis.x != u.axis.x || b.axis.y != u.axis.y || b.axis.z != u.axis.z || b.cosThetaO != u.cosThetaO)
            u.cosThetaO = -1.0f;
    }
    return u;
}

}  // namespace fluence::render
