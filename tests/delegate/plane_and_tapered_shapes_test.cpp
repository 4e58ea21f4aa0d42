// UsdGeomPlane, Cylinder_1 and Capsule_1 (delegate/implicit_geometry.h) against their analytic
// area, volume and placement.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "delegate/implicit_geometry.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
constexpr double kPi = std::numbers::pi;

const render::MeshDesc& onlyMesh(const testing::Populated& p) {
    EXPECT_TRUE(p.warnings.empty()) << (p.warnings.empty() ? "" : p.warnings.front());
    EXPECT_EQ(p.result.scene.meshes.size(), 1u);
    return p.result.scene.meshes.at(0);
}

TEST(PlanePrim, SpansWidthAndLengthAlongTheAxesUsdGeomNames) {
    struct Case {
        const char* axis;
        int normal, widthAxis, lengthAxis;
    };
    for (const Case& c : {Case{"X", 0, 2, 1}, Case{"Y", 1, 0, 2}, Case{"Z", 2, 0, 1}}) {
        SCOPED_TRACE(c.axis);
        auto p = populate(
            std::string(
                "def Plane \"P\"\n{\n    double width = 3\n    double length = 0.5\n    uniform token axis = \"") +
            c.axis + "\"\n}\n");
        const render::MeshDesc& m = onlyMesh(p);
        ASSERT_EQ(m.indices.size(), 6u);
        EXPECT_NEAR(testing::surfaceArea(m), 1.5, 1e-6);
        Vec3d lo(1e9), hi(-1e9);
        for (const Vec3f& v : m.positions) {
            lo = vmin(lo, Vec3d(v));
            hi = vmax(hi, Vec3d(v));
        }
        EXPECT_NEAR(hi[c.widthAxis] - lo[c.widthAxis], 3.0, 1e-6);
        EXPECT_NEAR(hi[c.lengthAxis] - lo[c.lengthAxis], 0.5, 1e-6);
        EXPECT_NEAR(hi[c.normal] - lo[c.normal], 0.0, 1e-9);
        for (std::size_t t = 0; t < 2; ++t) EXPECT_GT(testing::triangleCross(m, t)[c.normal], 0.0) << "faces +axis";
        for (const Vec3f& n : m.cornerNormals) EXPECT_NEAR(n[c.normal], 1.0f, 1e-6f);
    }
    auto fallback = populate("def Plane \"P\"\n{\n}\n");
    EXPECT_NEAR(testing::surfaceArea(onlyMesh(fallback)), 4.0, 1e-6) << "width and length 2";
}

TEST(Cylinder1Prim, IsTheFrustumOfItsTwoRadii) {
    auto p = populate(
        "def Cylinder_1 \"P\"\n{\n    double radiusTop = 0.5\n    double radiusBottom = 1.5\n    double height = 3\n"
        "    uniform token axis = \"Y\"\n}\n");
    const render::MeshDesc& m = onlyMesh(p);
    const double rt = 0.5, rb = 1.5, h = 3.0;
    const double area = kPi * (rt * rt + rb * rb) + kPi * (rt + rb) * std::hypot(h, rb - rt);
    const double volume = kPi * h * (rt * rt + rt * rb + rb * rb) / 3.0;
    EXPECT_NEAR(testing::surfaceArea(m) / area, 1.0, 2e-3);
    EXPECT_NEAR(testing::enclosedVolume(m) / volume, 1.0, 2e-3);
    double top = -1e9;
    for (const Vec3f& v : m.positions) top = std::max(top, double(v.y));
    EXPECT_NEAR(top, 1.5, 1e-6);
    auto fallback = populate("def Cylinder_1 \"P\"\n{\n}\n");
    EXPECT_NEAR(testing::enclosedVolume(onlyMesh(fallback)) / (2.0 * kPi), 1.0, 2e-3) << "radii 1, height 2";
}

TEST(Capsule1Prim, CapsMeetTheirTangentCone) {
    const double rt = 0.5, rb = 1.0, h = 2.0;
    auto p = populate(
        "def Capsule_1 \"P\"\n{\n    double radiusTop = 0.5\n    double radiusBottom = 1\n    double height = 2\n}\n");
    const render::MeshDesc& m = onlyMesh(p);
    // The cone tangent to both spheres: its normal's axial component s = (rt - rb) / h.
    const double s = (rt - rb) / h, c = std::sqrt(1.0 - s * s);
    const double topCap = 2.0 * kPi * rt * rt * (1.0 - s), bottomCap = 2.0 * kPi * rb * rb * (1.0 + s);
    const double r1 = rt * c, r2 = rb * c, w1 = 0.5 * h + rt * s, w2 = -0.5 * h + rb * s;
    const double side = kPi * (r1 + r2) * std::hypot(r2 - r1, w1 - w2);
    EXPECT_NEAR(testing::surfaceArea(m) / (topCap + bottomCap + side), 1.0, 2e-3);
    // Every vertex is on one of the spheres or on the cone between the tangent circles.
    for (const Vec3f& v : m.positions) {
        const double rho = std::hypot(double(v.x), double(v.y)), w = v.z;
        const double onTop = std::abs(std::hypot(rho, w - 0.5 * h) - rt),
                     onBottom = std::abs(std::hypot(rho, w + 0.5 * h) - rb);
        const double onCone = std::abs((rho - r1) * s - (w - w1) * c);  // distance to the cone's line, as (rho, w)
        EXPECT_LT(std::min({onTop, onBottom, onCone}), 1e-5) << v.x << " " << v.y << " " << v.z;
    }
    auto equal = populate("def Capsule_1 \"P\"\n{\n}\n");
    EXPECT_NEAR(testing::surfaceArea(onlyMesh(equal)) / (2.0 * kPi * 0.5 + 4.0 * kPi * 0.25), 1.0, 2e-3) << "a Capsule";
    auto swallowed = populate("def Capsule_1 \"P\"\n{\n    double radiusTop = 0.1\n    double radiusBottom = 3\n}\n");
    EXPECT_TRUE(swallowed.result.scene.meshes.empty());
    ASSERT_FALSE(swallowed.warnings.empty());
    EXPECT_NE(swallowed.warnings.front().find("/P"), std::string::npos) << swallowed.warnings.front();
}

}  // namespace
}  // namespace fluence::delegate
