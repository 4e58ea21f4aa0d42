// UsdGeomNurbsPatch (delegate/nurbs_patch.h) against surfaces it represents exactly: a bilinear
// rectangle, and a quarter cylinder drawn by a rational quadratic (its points on the circle to
// rounding, its area that of the arc to the tessellation's chord error).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
constexpr double kPi = std::numbers::pi;

const std::string kQuarterCylinder = R"(def NurbsPatch "P"
{
    int uVertexCount = 3
    int vVertexCount = 2
    int uOrder = 3
    int vOrder = 2
    double[] uKnots = [0, 0, 0, 1, 1, 1]
    double[] vKnots = [0, 0, 1, 1]
    double[] pointWeights = [1, 0.7071067811865476, 1, 1, 0.7071067811865476, 1]
    point3f[] points = [(2, 0, 0), (2, 2, 0), (0, 2, 0), (2, 0, 3), (2, 2, 3), (0, 2, 3)]
)";

// A 2 x 3 rectangle as an order-2 patch with the given uKnots.
std::string bilinearPatch(const std::string& name, const std::string& uKnots) {
    return "def NurbsPatch \"" + name + R"("
{
    int uVertexCount = 2
    int vVertexCount = 2
    int uOrder = 2
    int vOrder = 2
    double[] uKnots = )" +
           uKnots + R"(
    double[] vKnots = [0, 0, 1, 1]
    point3f[] points = [(0, 0, 0), (2, 0, 0), (0, 3, 0), (2, 3, 0)]
}
)";
}

TEST(NurbsPatchPrim, BilinearPatchIsItsRectangle) {
    auto p = populate(bilinearPatch("Rectangle", "[0, 0, 1, 1]"));
    EXPECT_TRUE(p.warnings.empty()) << (p.warnings.empty() ? "" : p.warnings.front());
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    const render::MeshDesc& m = p.result.scene.meshes[0];
    EXPECT_EQ(m.indices.size(), 6u) << "order 2: one step per span";
    EXPECT_NEAR(testing::surfaceArea(m), 6.0, 1e-9);
    EXPECT_GT(testing::triangleCross(m, 0).z, 0.0) << "du x dv faces +z";
}

TEST(NurbsPatchPrim, RationalQuadraticDrawsAnExactCircle) {
    auto p = populate(kQuarterCylinder + "}\n");
    EXPECT_TRUE(p.warnings.empty()) << (p.warnings.empty() ? "" : p.warnings.front());
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    const render::MeshDesc& m = p.result.scene.meshes[0];
    for (const Vec3f& v : m.positions) EXPECT_NEAR(std::hypot(v.x, v.y), 2.0, 1e-5) << v.x << " " << v.y;
    const double area = 0.5 * kPi * 2.0 * 3.0, tessellated = testing::surfaceArea(m);
    EXPECT_LT(tessellated, area) << "chords lie inside the arc";
    EXPECT_GT(tessellated, area * (1.0 - 2e-3));
    for (std::size_t c = 0; c < m.indices.size(); ++c) {
        const Vec3f& v = m.positions[m.indices[c]];
        const Vec3f& n = m.cornerNormals[c];
        EXPECT_NEAR(n.x * v.x / 2.0 + n.y * v.y / 2.0, 1.0, 1e-4) << "the outward radial normal";
    }
}

TEST(NurbsPatchPrim, LeftHandedFlipsAndTrimCurvesWarn) {
    auto p = populate(kQuarterCylinder +
                      "    uniform token orientation = \"leftHanded\"\n    int[] trimCurve:counts = [1]\n}\n");
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    const render::MeshDesc& m = p.result.scene.meshes[0];
    EXPECT_LT(m.cornerNormals[0].x * m.positions[m.indices[0]].x + m.cornerNormals[0].y * m.positions[m.indices[0]].y,
              0.0);
    const Vec3f& a = m.positions[m.indices[0]];
    EXPECT_LT(testing::triangleCross(m, 0).x * a.x + testing::triangleCross(m, 0).y * a.y, 0.0) << "wound inwards too";
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("/P"), std::string::npos);
    EXPECT_NE(p.warnings[0].find("trim curves"), std::string::npos) << p.warnings[0];
}

TEST(NurbsPatchPrim, MalformedPatchIsSkippedNamingIt) {
    auto p = populate(bilinearPatch("Bad", "[0, 0, 1]"));
    EXPECT_TRUE(p.result.scene.meshes.empty());
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("/Bad"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("uKnots"), std::string::npos) << p.warnings[0];
}

}  // namespace
}  // namespace fluence::delegate
