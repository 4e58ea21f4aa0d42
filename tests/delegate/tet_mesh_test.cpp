// UsdGeomTetMesh (delegate/tet_mesh.h): its boundary surface is the faces that belong to one
// tetrahedron only, wound outward (OpenUSD's own example of two tetrahedra gives the faces its
// file authors); a one-tet TetMesh renders as a closed surface enclosing the tetrahedron's volume,
// right- or left-handed; authored surfaceFaceVertexIndices are used as they are; an index out of
// range leaves the prim out with a warning naming it.
#include <gtest/gtest.h>

#include "delegate/tet_mesh.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::Populated;

TEST(TetMesh, SurfaceFacesAreThoseOfOneTetrahedronOnlyWoundOutward) {
    // OpenUSD's testUsdGeomTetMesh: two tetrahedra sharing the face (0, 1, 2).
    const std::vector<std::array<int, 3>> faces = tetSurfaceFaces({{0, 1, 2, 3}, {0, 2, 1, 4}});
    const std::vector<std::array<int, 3>> expected = {{0, 1, 3}, {0, 2, 4}, {0, 3, 2}, {0, 4, 1}, {1, 2, 3}, {2, 1, 4}};
    EXPECT_EQ(faces, expected);
    EXPECT_EQ(tetSurfaceFaces({{0, 1, 2, 3}}).size(), 4u);
    EXPECT_TRUE(tetSurfaceFaces({}).empty());
}

// A tetrahedron with legs of 2 along the axes (volume 4/3); `mirror` negates x and makes it
// left-handed, as OpenUSD's tetMeshLH.usda does.
std::string oneTet(bool mirror, const std::string& lines = "") {
    const std::string x = mirror ? "-2" : "2";
    return R"(
def TetMesh "Tet"
{
    point3f[] points = [(0, 0, 0), ()" +
           x + R"(, 0, 0), (0, 2, 0), (0, 0, 2)]
    int4[] tetVertexIndices = [(0, 1, 2, 3)]
)" + (mirror ? "    uniform token orientation = \"leftHanded\"\n" : "") +
           lines + "}\n";
}

TEST(TetMesh, AOneTetMeshIsAClosedSurfaceEnclosingItsVolume) {
    for (bool mirror : {false, true}) {
        const Populated p = populate(oneTet(mirror));
        const render::MeshDesc* tet = p.mesh("/Tet");
        ASSERT_NE(tet, nullptr) << "mirror " << mirror;
        EXPECT_EQ(tet->indices.size(), 12u);
        EXPECT_NEAR(testing::enclosedVolume(*tet), 4.0 / 3.0, 1e-6) << "mirror " << mirror;
        // Three right triangles of legs 2 and the equilateral face of side 2 sqrt 2.
        EXPECT_NEAR(testing::surfaceArea(*tet), 3 * 2.0 + std::sqrt(3.0) / 4 * 8.0, 1e-5);
        for (const std::string& w : p.warnings) EXPECT_EQ(w.find("/Tet"), std::string::npos) << w;
    }
}

TEST(TetMesh, AuthoredSurfaceFacesAreUsedAsTheyAre) {
    const Populated p = populate(oneTet(false, "    int3[] surfaceFaceVertexIndices = [(1, 2, 3)]\n"));
    const render::MeshDesc* tet = p.mesh("/Tet");
    ASSERT_NE(tet, nullptr);
    ASSERT_EQ(tet->indices.size(), 3u);
    EXPECT_EQ(Vec3d(tet->positions[tet->indices[0]]), Vec3d(2, 0, 0));
}

TEST(TetMesh, AnIndexOutOfRangeLeavesThePrimOutNamingIt) {
    const Populated p = populate(oneTet(false, "    int3[] surfaceFaceVertexIndices = [(1, 2, 7)]\n"));
    EXPECT_EQ(p.mesh("/Tet"), nullptr);
    bool named = false;
    for (const std::string& w : p.warnings)
        named = named || (w.find("/Tet") != std::string::npos &&
                          w.find("surfaceFaceVertexIndices[0] names point 7") != std::string::npos);
    EXPECT_TRUE(named);
}

}  // namespace
}  // namespace fluence::delegate
