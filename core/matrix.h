// 4x4 affine/projective matrices in double precision, column-vector convention: p' = M * p,
// translation in the last column.
//
// USD writes matrices for row vectors (translation in the last row); convert them with
// Matrix4::fromUsdRowMajor, which transposes.
#pragma once

#include <array>
#include <optional>

#include "core/vec.h"

namespace fluence {

struct Matrix4 {
    std::array<std::array<double, 4>, 4> m{};  // m[row][column]

    static Matrix4 identity();
    static Matrix4 translate(const Vec3d& t);
    static Matrix4 scale(const Vec3d& s);
    static Matrix4 rotateX(double degrees);
    static Matrix4 rotateY(double degrees);
    static Matrix4 rotateZ(double degrees);
    // Rotation by a unit quaternion (real part w, imaginary part xyz).
    static Matrix4 fromQuaternion(double w, double x, double y, double z);
    // 16 values as USD authors them: row-major for row vectors (translation in elements 12..14).
    static Matrix4 fromUsdRowMajor(const double* values16);

    Matrix4 operator*(const Matrix4& o) const;
    bool operator==(const Matrix4&) const = default;

    Vec3d transformPoint(const Vec3d& p) const;
    Vec3d transformVector(const Vec3d& v) const;
    // Transforms a normal by the inverse transpose of the upper 3x3 (not normalised). Under a
    // mirroring transform the normal keeps pointing to the same geometric side (an outward normal
    // stays outward), even though the winding of transformed triangles flips.
    Vec3d transformNormal(const Vec3d& n) const;

    double determinant3x3() const;
    std::optional<Matrix4> inverse() const;
};

}  // namespace fluence
