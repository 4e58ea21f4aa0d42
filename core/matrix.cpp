#include "core/matrix.h"

#include <cmath>
#include <numbers>

namespace fluence {

namespace {
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
}  // namespace

Matrix4 Matrix4::identity() {
    Matrix4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0;
    return r;
}

Matrix4 Matrix4::translate(const Vec3d& t) {
    Matrix4 r = identity();
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Matrix4 Matrix4::scale(const Vec3d& s) {
    Matrix4 r = identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Matrix4 Matrix4::rotateX(double degrees) {
    double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    Matrix4 r = identity();
    r.m[1][1] = c;
    r.m[1][2] = -s;
    r.m[2][1] = s;
    r.m[2][2] = c;
    return r;
}

Matrix4 Matrix4::rotateY(double degrees) {
    double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    Matrix4 r = identity();
    r.m[0][0] = c;
    r.m[0][2] = s;
    r.m[2][0] = -s;
    r.m[2][2] = c;
    return r;
}

Matrix4 Matrix4::rotateZ(double degrees) {
    double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    Matrix4 r = identity();
    r.m[0][0] = c;
    r.m[0][1] = -s;
    r.m[1][0] = s;
    r.m[1][1] = c;
    return r;
}

Matrix4 Matrix4::fromQuaternion(double w, double x, double y, double z) {
    double n = std::sqrt(w * w + x * x + y * y + z * z);
    if (n > 0.0) {
        w /= n;
        x /= n;
        y /= n;
        z /= n;
    }
    Matrix4 r = identity();
    r.m[0][0] = 1 - 2 * (y * y + z * z);
    r.m[0][1] = 2 * (x * y - w * z);
    r.m[0][2] = 2 * (x * z + w * y);
    r.m[1][0] = 2 * (x * y + w * z);
    r.m[1][1] = 1 - 2 * (x * x + z * z);
    r.m[1][2] = 2 * (y * z - w * x);
    r.m[2][0] = 2 * (x * z - w * y);
    r.m[2][1] = 2 * (y * z + w * x);
    r.m[2][2] = 1 - 2 * (x * x + y * y);
    return r;
}

Matrix4 Matrix4::fromUsdRowMajor(const double* v) {
    Matrix4 r;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) r.m[col][row] = v[row * 4 + col];
    return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Vec3d Matrix4::transformPoint(const Vec3d& p) const {
    Vec3d r(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
    double w = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
    return w == 1.0 || w == 0.0 ? r : r / w;
}

Vec3d Matrix4::transformVector(const Vec3d& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3d Matrix4::transformNormal(const Vec3d& n) const {
    // Rows of the cofactor matrix of the upper 3x3: cofactor = det * inverse transpose. Scaling
    // by the sign of det gives the direction of inverse-transpose * n, and this works for
    // singular matrices too.
    const auto& a = m;
    Vec3d c0(a[1][1] * a[2][2] - a[1][2] * a[2][1], a[1][2] * a[2][0] - a[1][0] * a[2][2],
             a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    Vec3d c1(a[0][2] * a[2][1] - a[0][1] * a[2][2], a[0][0] * a[2][2] - a[0][2] * a[2][0],
             a[0][1] * a[2][0] - a[0][0] * a[2][1]);
    Vec3d c2(a[0][1] * a[1][2] - a[0][2] * a[1][1], a[0][2] * a[1][0] - a[0][0] * a[1][2],
             a[0][0] * a[1][1] - a[0][1] * a[1][0]);
    Vec3d r(dot(c0, n), dot(c1, n), dot(c2, n));
    return determinant3x3() < 0.0 ? -r : r;
}

double Matrix4::determinant3x3() const {
    const auto& a = m;
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

std::optional<Matrix4> Matrix4::inverse() const {
    // Gauss-Jordan elimination with partial pivoting.
    Matrix4 a = *this, inv = identity();
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::abs(a.m[r][col]) > std::abs(a.m[pivot][col])) pivot = r;
        if (a.m[pivot][col] == 0.0) return std::nullopt;
        std::swap(a.m[pivot], a.m[col]);
        std::swap(inv.m[pivot], inv.m[col]);
        double d = 1.0 / a.m[col][col];
        for (int j = 0; j < 4; ++j) {
            a.m[col][j] *= d;
            inv.m[col][j] *= d;
        }
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            double f = a.m[r][col];
            if (f == 0.0) continue;
            for (int j = 0; j < 4; ++j) {
                a.m[r][j] -= f * a.m[col][j];
                inv.m[r][j] -= f * inv.m[col][j];
            }
        }
    }
    return inv;
}

}  // namespace fluence
