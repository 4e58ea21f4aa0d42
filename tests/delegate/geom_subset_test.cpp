#include "delegate/geom_subset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "delegate/prim_reader.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::populateStrict;

const std::string kLooks = R"(
def Scope "Looks"
{
    def Material "Red"
    {
        token outputs:surface.connect = </Looks/Red/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (1, 0, 0)
        }
    }
    def Material "Blue"
    {
        token outputs:surface.connect = </Looks/Blue/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0, 0, 1)
        }
    }
    def Material "Grey"
    {
        token outputs:surface.connect = </Looks/Grey/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0.5, 0.5, 0.5)
        }
    }
}
)";

// A cube of six quads: faces 0..5 are +Z, +Y, -Z, -Y, +X, -X, each with its own (uniform) colour
// and (faceVarying) normal. `binding` and `children` are spliced into the Mesh.
std::string cube(const std::string& binding, const std::string& children) {
    return R"(
def Mesh "Box"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
    int[] faceVertexIndices = [0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4]
    point3f[] points = [(-1, -1, 1), (1, -1, 1), (-1, 1, 1), (1, 1, 1), (-1, 1, -1), (1, 1, -1), (-1, -1, -1), (1, -1, -1)]
    normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1),
                          (0, 1, 0), (0, 1, 0), (0, 1, 0), (0, 1, 0),
                          (0, 0, -1), (0, 0, -1), (0, 0, -1), (0, 0, -1),
                          (0, -1, 0), (0, -1, 0), (0, -1, 0), (0, -1, 0),
                          (1, 0, 0), (1, 0, 0), (1, 0, 0), (1, 0, 0),
                          (-1, 0, 0), (-1, 0, 0), (-1, 0, 0), (-1, 0, 0)] (
        interpolation = "faceVarying"
    )
    color3f[] primvars:displayColor = [(0, 0, 0.1), (0, 0.1, 0), (0, 0, 0.2), (0, 0.2, 0), (0.1, 0, 0), (0.2, 0, 0)] (
        interpolation = "uniform"
    )
)" + binding +
           children + "}\n";
}

std::string subset(const std::string& name, const std::string& indices, const std::string& material,
                   const std::string& family = "materialBind") {
    return "    def GeomSubset \"" + name + "\"\n    {\n        uniform token elementType = \"face\"\n" +
           "        uniform token familyName = \"" + family + "\"\n        int[] indices = " + indices + "\n" +
           (material.empty() ? "" : "        rel material:binding = <" + material + ">\n") + "    }\n";
}

const std::string kTwoSubsets = subset("Red", "[0, 2]", "/Looks/Red") + subset("Blue", "[4]", "/Looks/Blue");

std::string materialName(const testing::Populated& p, const render::MeshDesc& m) {
    return m.material < 0 ? "" : p.result.scene.materials[static_cast<std::size_t>(m.material)].name;
}

// The set of triangles of `m` as world-space corner positions, for comparing splits.
std::multiset<std::vector<float>> triangleSet(const render::MeshDesc& m) {
    std::multiset<std::vector<float>> out;
    for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
        std::vector<float> corners;
        for (std::size_t c = 3 * t; c < 3 * t + 3; ++c) {
            const Vec3f& q = m.positions[m.indices[c]];
            corners.insert(corners.end(), {q.x, q.y, q.z});
        }
        out.insert(corners);
    }
    return out;
}

TEST(GeomSubset, SplitsAMeshIntoOnePartPerMaterial) {
    auto p = populate(kLooks + cube("    rel material:binding = </Looks/Grey>\n", kTwoSubsets));
    const auto& meshes = p.result.scene.meshes;
    ASSERT_EQ(meshes.size(), 3u);
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
    // The faces in no subset first, under the mesh's name and binding; then the subsets.
    EXPECT_EQ(meshes[0].name, "/Box");
    EXPECT_EQ(materialName(p, meshes[0]), "/Looks/Grey");
    EXPECT_EQ(meshes[0].indices.size(), 3u * 6u);  // faces 1, 3, 5
    EXPECT_EQ(meshes[1].name, "/Box/Red");
    EXPECT_EQ(materialName(p, meshes[1]), "/Looks/Red");
    EXPECT_EQ(p.result.scene.materials[static_cast<std::size_t>(meshes[1].material)].diffuse, RGB(1, 0, 0));
    EXPECT_EQ(meshes[1].indices.size(), 3u * 4u);  // faces 0, 2
    EXPECT_EQ(meshes[2].name, "/Box/Blue");
    EXPECT_EQ(materialName(p, meshes[2]), "/Looks/Blue");
    EXPECT_EQ(meshes[2].indices.size(), 3u * 2u);  // face 4
    EXPECT_EQ(p.result.scene.materials.size(), 3u);

    // Each part holds only the points it uses, and its faces' normals.
    EXPECT_EQ(meshes[1].positions.size(), 8u) << "two opposite quads";
    EXPECT_EQ(meshes[2].positions.size(), 4u);
    for (const Vec3f& n : meshes[1].cornerNormals) EXPECT_EQ(std::abs(n.z), 1.0f) << "the +Z and -Z faces";
    for (const Vec3f& n : meshes[2].cornerNormals) EXPECT_EQ(n, Vec3f(1, 0, 0)) << "the +X face";
    for (const auto& m : meshes) {
        EXPECT_EQ(m.cornerNormals.size(), m.indices.size());
        EXPECT_TRUE(m.cornerColors.empty()) << "bound materials replace displayColor";
        for (std::uint32_t i : m.indices) EXPECT_LT(i, m.positions.size());
    }

    // Together the parts are exactly the unsplit mesh's triangles.
    auto whole = populate(kLooks + cube("    rel material:binding = </Looks/Grey>\n", ""));
    ASSERT_EQ(whole.result.scene.meshes.size(), 1u);
    std::multiset<std::vector<float>> parts;
    for (const auto& m : meshes) parts.merge(triangleSet(m));
    EXPECT_EQ(parts, triangleSet(whole.result.scene.meshes[0]));
}

TEST(GeomSubset, UnboundFacesKeepTheirDisplayColorAndNormals) {
    auto p = populate(kLooks + cube("", subset("Red", "[0, 1]", "/Looks/Red")));
    const auto& meshes = p.result.scene.meshes;
    ASSERT_EQ(meshes.size(), 2u);
    const render::MeshDesc& rest = meshes[0];
    EXPECT_EQ(rest.name, "/Box");
    EXPECT_EQ(rest.material, -1);
    ASSERT_EQ(rest.cornerColors.size(), 3u * 8u);  // faces 2..5, two triangles each
    // Faces 2, 3, 4, 5 in order, each colour with its face's normal.
    const std::vector<RGB> colours = {{0, 0, 0.2f}, {0, 0.2f, 0}, {0.1f, 0, 0}, {0.2f, 0, 0}};
    const std::vector<Vec3f> normals = {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}};
    for (std::size_t c = 0; c < rest.cornerColors.size(); ++c) {
        EXPECT_EQ(rest.cornerColors[c], colours[c / 6]) << "corner " << c;
        EXPECT_EQ(rest.cornerNormals[c], normals[c / 6]) << "corner " << c;
    }
    EXPECT_EQ(materialName(p, meshes[1]), "/Looks/Red");
    EXPECT_TRUE(meshes[1].cornerColors.empty());
}

TEST(GeomSubset, ASubsetWithoutItsOwnBindingTakesTheMeshsAndDistinctMaterialsMerge) {
    // "Plain" has no binding: it resolves to the mesh's (Grey) and joins the mesh's part. "Red2"
    // binds Red again: one part for both Red subsets.
    auto p = populate(kLooks + cube("    rel material:binding = </Looks/Grey>\n",
                                    subset("Red", "[0]", "/Looks/Red") + subset("Plain", "[1, 2]", "") +
                                        subset("Red2", "[3]", "/Looks/Red")));
    const auto& meshes = p.result.scene.meshes;
    ASSERT_EQ(meshes.size(), 2u);
    EXPECT_EQ(materialName(p, meshes[0]), "/Looks/Grey");
    EXPECT_EQ(meshes[0].indices.size(), 3u * 8u);  // faces 1, 2, 4, 5
    EXPECT_EQ(meshes[1].name, "/Box/Red");
    EXPECT_EQ(materialName(p, meshes[1]), "/Looks/Red");
    EXPECT_EQ(meshes[1].indices.size(), 3u * 4u);  // faces 0, 3
}

TEST(GeomSubset, OnlyMaterialBindFaceSubsetsCount) {
    auto p = populate(kLooks + cube("", subset("Other", "[0]", "/Looks/Red", "partition") +
                                            subset("NoBinding", "[1]", "", "uvSets")));
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    EXPECT_EQ(p.result.scene.meshes[0].material, -1);
    EXPECT_EQ(p.result.scene.meshes[0].indices.size(), 36u);
    ASSERT_EQ(p.warnings.size(), 1u) << "the binding on a subset outside materialBind is reported";
    EXPECT_NE(p.warnings[0].find("/Box/Other has a material binding but its familyName is 'partition'"),
              std::string::npos)
        << p.warnings[0];
}

TEST(GeomSubset, OverlappingSubsetsWarnAndTheFirstWins) {
    auto p =
        populate(kLooks + cube("", subset("Red", "[0, 1]", "/Looks/Red") + subset("Blue", "[1, 2]", "/Looks/Blue")));
    const auto& meshes = p.result.scene.meshes;
    ASSERT_EQ(meshes.size(), 3u);
    EXPECT_EQ(meshes[1].indices.size(), 3u * 4u) << "Red keeps face 1";
    EXPECT_EQ(meshes[2].indices.size(), 3u * 2u);
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find(
                  "/Box/Blue lists 1 face (first: face 1) already in an earlier materialBind subset (/Box/Red)"),
              std::string::npos)
        << p.warnings[0];
}

TEST(GeomSubset, FaceIndicesCountHolesAndSmallFaces) {
    // Face 1 is a hole and face 2 a degenerate two-vertex face: neither gives triangles, but both
    // count in the subset's face numbering.
    auto p = populate(kLooks + R"(
def Mesh "Strip"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [3, 3, 2, 3]
    int[] faceVertexIndices = [0, 1, 2, 1, 3, 2, 0, 1, 2, 3, 4]
    int[] holeIndices = [1]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 2, 0)]
    def GeomSubset "Last"
    {
        uniform token familyName = "materialBind"
        int[] indices = [3]
        rel material:binding = </Looks/Red>
    }
}
)");
    const auto& meshes = p.result.scene.meshes;
    ASSERT_EQ(meshes.size(), 2u);
    EXPECT_EQ(meshes[1].name, "/Strip/Last");
    ASSERT_EQ(meshes[1].indices.size(), 3u);
    EXPECT_EQ(meshes[1].positions[meshes[1].indices[2]], Vec3f(0, 2, 0)) << "the triangle of face 3";
    EXPECT_EQ(meshes[0].indices.size(), 3u) << "face 0 only";
}

TEST(GeomSubset, OutOfRangeFaceIndicesNameTheSubset) {
    for (const char* indices : {"[0, 6]", "[-1]"}) {
        SCOPED_TRACE(indices);
        try {
            populateStrict(kLooks +
                           cube("", subset("Red", "[0]", "/Looks/Red") + subset("Bad", indices, "/Looks/Blue")));
            FAIL() << "expected SceneError";
        } catch (const SceneError& e) {
            std::string what = e.what();
            EXPECT_NE(what.find("/Box/Bad"), std::string::npos) << what;
            EXPECT_NE(what.find("is not a face of /Box (6 faces)"), std::string::npos) << what;
        }
    }
}

TEST(GeomSubset, SubsetsOfInvisibleMeshesAreNotRead) {
    auto p = populate(kLooks + R"(
def Mesh "Hidden"
{
    uniform token subdivisionScheme = "none"
    token visibility = "invisible"
    int[] faceVertexCounts = [3]
    int[] faceVertexIndices = [0, 1, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    def GeomSubset "Bad"
    {
        uniform token familyName = "materialBind"
        int[] indices = [7]
    }
}
)");
    EXPECT_TRUE(p.result.scene.meshes.empty());
}

}  // namespace
}  // namespace fluence::delegate
