#include "render/camera_motion.h"

#include <cmath>

#include "render/motion_geometry.h"

namespace fluence::render {

namespace {

struct Quaternion {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

struct Decomposed {
    Vec3d translation;
    Quaternion rotation;
    Vec3d scale;
};

// The unit quaternion of the rotation matrix r (columns orthonormal, determinant 1; Shepperd's
// method, from the largest of the four squared components).
Quaternion quaternionOf(const double r[3][3]) {
    const double trace = r[0][0] + r[1][1] + r[2][2];
    Quaternion q;
    if (trace > 0.0) {
        const double s = 2.0 * std::sqrt(1.0 + trace);
        q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
    } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]);
        q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
    } else if (r[1][1] > r[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]);
        q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
    } else {
        const double s = 2.0 * std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]);
        q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
    }
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Decomposed decompose(const Matrix4& m) {
    Decomposed d;
    d.translation = Vec3d(m.m[0][3], m.m[1][3], m.m[2][3]);
    double r[3][3];
    double scale[3];
    for (int column = 0; column < 3; ++column) {
        scale[column] = std::sqrt(m.m[0][column] * m.m[0][column] + m.m[1][column] * m.m[1][column] +
                                  m.m[2][column] * m.m[2][column]);
        for (int row = 0; row < 3; ++row) r[row][column] = scale[column] > 0.0 ? m.m[row][column] / scale[column] : 0.0;
    }
    const double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                       r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                       r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    if (det < 0.0) {  // a mirror: the scale of z takes the reflection, the rest is a rotation
        scale[2] = -scale[2];
        for (int row = 0; row < 3; ++row) r[row][2] = -r[row][2];
    }
    d.rotation = quaternionOf(r);
    d.scale = Vec3d(scale[0], scale[1], scale[2]);
    return d;
}

Quaternion slerp(Quaternion a, const Quaternion& b, double f) {
    double cosine = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    if (cosine < 0.0) {  // the shorter arc
        a = {-a.w, -a.x, -a.y, -a.z};
        cosine = -cosine;
    }
    double wa = 1.0 - f, wb = f;
    if (cosine < 0.9995) {
        const double angle = std::acos(cosine), sine = std::sin(angle);
        wa = std::sin((1.0 - f) * angle) / sine;
        wb = std::sin(f * angle) / sine;
    }
    Quaternion q{wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
    const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}

}  // namespace

Matrix4 cameraTransformAt(const std::vector<Matrix4>& steps, float time) {
    const MotionSegment segment = motionSegment(steps.size(), time);
    const Decomposed a = decompose(steps[segment.step]), b = decompose(steps[segment.step + 1]);
    const double f = segment.fraction;
    const Quaternion q = slerp(a.rotation, b.rotation, f);
    return Matrix4::translate(a.translation * (1.0 - f) + b.translation * f) *
           Matrix4::fromQuaternion(q.w, q.x, q.y, q.z) * Matrix4::scale(a.scale * (1.0 - f) + b.scale * f);
}

CameraLensStep cameraLensAt(const std::vector<CameraLensStep>& steps, float time) {
    const MotionSegment segment = motionSegment(steps.size(), time);
    const CameraLensStep &a = steps[segment.step], &b = steps[segment.step + 1];
    const float f = segment.fraction;
    auto mix = [f](float x, float y) { return x * (1.0f - f) + y * f; };
    return {mix(a.focalLength, b.focalLength), mix(a.fStop, b.fStop), mix(a.focusDistance, b.focusDistance)};
}

}  // namespace fluence::render
