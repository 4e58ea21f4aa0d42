#include "core/matrix.h"

#include <gtest/gtest.h>

namespace fluence {
namespace {

void expectNear(const Vec3d& a, const Vec3d& b, double eps = 1e-12) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Matrix4, RotationsFollowTheRightHandRule) {
    expectNear(Matrix4::rotateX(90).transformVector({0, 1, 0}), {0, 0, 1});
    expectNear(Matrix4::rotateY(90).transformVector({0, 0, 1}), {1, 0, 0});
    expectNear(Matrix4::rotateZ(90).transformVector({1, 0, 0}), {0, 1, 0});
}

TEST(Matrix4, UsdRowMajorMatricesAreTransposed) {
    // USD writes ( (1,0,0,0), (0,1,0,0), (0,0,1,0), (tx,ty,tz,1) ) for a translation.
    const double usd[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
    expectNear(Matrix4::fromUsdRowMajor(usd).transformPoint({1, 2, 3}), {6, 8, 10});
}

TEST(Matrix4, InverseUndoesTheTransform) {
    Matrix4 m = Matrix4::translate({1, -2, 3}) * Matrix4::rotateY(33) * Matrix4::scale({2, 3, 0.5});
    auto inv = m.inverse();
    ASSERT_TRUE(inv);
    expectNear(inv->transformPoint(m.transformPoint({0.3, -4, 9})), {0.3, -4, 9}, 1e-12);
    EXPECT_FALSE(Matrix4::scale({1, 0, 1}).inverse());
}

TEST(Matrix4, NormalsStayPerpendicularUnderNonUniformScale) {
    Matrix4 m = Matrix4::rotateZ(20) * Matrix4::scale({4, 1, 1});
    Vec3d tangent(1, -1, 0), normal(1, 1, 0);
    EXPECT_NEAR(dot(m.transformVector(tangent), m.transformNormal(normal)), 0.0, 1e-12);
    // A mirroring transform maps normals by the inverse transpose: outward stays outward.
    Matrix4 mirror = Matrix4::scale({-1, 1, 1});
    expectNear(normalize(mirror.transformNormal({1, 0, 1})), normalize(Vec3d(-1, 0, 1)));
    expectNear(normalize(Matrix4::rotateX(-90).transformNormal({0, 0, -1})), {0, -1, 0});
}

TEST(Matrix4, QuaternionRotation) {
    const double s = std::sqrt(0.5);
    expectNear(Matrix4::fromQuaternion(s, 0, 0, s).transformVector({1, 0, 0}), {0, 1, 0});
}

}  // namespace
}  // namespace fluence
