// Subdivision surfaces through the delegate: USD meshes subdivide unless they say "none", are
// diced for the camera, honour --subdiv-level, budgets, displacement and orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>
#include <tuple>

#include "delegate/scene_delegate.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::enclosedVolume;
using testing::stageFrom;

// A unit cube cage (a Catmull-Clark mesh by USD's fallback) at the origin, seen by a camera at
// DISTANCE along +Z through a 512x512 image.
std::string cubeScene(double distance, const std::string& meshExtras = "", const std::string& sceneExtras = "") {
    return R"(#usda 1.0
def Camera "Cam"
{
    double3 xformOp:translate = (0, 0, )" +
           std::to_string(distance) + R"()
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Mesh "Cube"
{
    int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
    int[] faceVertexIndices = [0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4]
    point3f[] points = [(-0.5, -0.5, 0.5), (0.5, -0.5, 0.5), (-0.5, 0.5, 0.5), (0.5, 0.5, 0.5), (-0.5, 0.5, -0.5), (0.5, 0.5, -0.5), (-0.5, -0.5, -0.5), (0.5, -0.5, -0.5)]
)" + meshExtras +
           R"(
}
)" + sceneExtras;
}

struct Described {
    std::unique_ptr<usd::Stage> stage;
    render::SceneDescription scene;
    std::vector<std::string> warnings;
};

Described describe(const std::string& usda, DicingSettings dicing = {}, std::set<std::string> aovPrimvars = {}) {
    Described d;
    d.stage = stageFrom(usda);
    DelegateOptions options;
    options.resolution = std::make_pair(512, 512);
    options.dicing = dicing;
    options.aovPrimvars = std::move(aovPrimvars);
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&d](const std::string& path, const std::string& message) {
        d.warnings.push_back(path + ": " + message);
    };
    d.scene = populateScene(*d.stage, options).scene;
    return d;
}

std::size_t triangles(const render::SceneDescription& scene) {
    std::size_t n = 0;
    for (const auto& m : scene.meshes) n += m.indices.size() / 3;
    return n;
}

float maxRadius(const render::MeshDesc& mesh) {
    float r = 0.0f;
    for (const Vec3f& p : mesh.positions) r = std::max(r, length(p));
    return r;
}

TEST(SubdivisionMesh, AMeshWithoutASchemeIsACatmullClarkLimitSurface) {
    Described cage = describe(cubeScene(4, R"(    uniform token subdivisionScheme = "none")"));
    Described limit = describe(cubeScene(4));
    ASSERT_EQ(limit.scene.meshes.size(), 1u);
    EXPECT_EQ(triangles(cage.scene), 12u);
    EXPECT_GT(triangles(limit.scene), 1000u);
    // The limit surface of a cube cage lies inside it, with its corners rounded off.
    const render::MeshDesc& mesh = limit.scene.meshes[0];
    for (const Vec3f& p : mesh.positions) {
        EXPECT_LE(std::abs(p.x), 0.5f + 1e-6f);
        EXPECT_LE(std::abs(p.y), 0.5f + 1e-6f);
        EXPECT_LE(std::abs(p.z), 0.5f + 1e-6f);
    }
    EXPECT_LT(maxRadius(mesh), 0.5f) << "the cage's corners are at radius 0.866";
    EXPECT_GT(enclosedVolume(mesh), 0.0) << "triangles wind outwards";
    ASSERT_EQ(mesh.cornerNormals.size(), mesh.indices.size()) << "limit normals shade";
    EXPECT_TRUE(limit.warnings.empty());
}

TEST(SubdivisionMesh, TrianglesFallAsTheCameraMovesAway) {
    std::size_t previous = std::numeric_limits<std::size_t>::max();
    for (double distance : {2.0, 8.0, 32.0, 128.0}) {
        std::size_t n = triangles(describe(cubeScene(distance)).scene);
        EXPECT_LT(n, previous) << "at distance " << distance;
        previous = n;
    }
    // 128 units away, a unit edge spans 512 / (2 * 10.4775 / 50) / 128 = 9.5 pixels: 10 segments,
    // so at most 6 faces * 10 * 10 quads * 2 triangles.
    EXPECT_LE(previous, 1200u);
}

TEST(SubdivisionMesh, DicingRateAndPerPrimOverride) {
    std::size_t fine = triangles(describe(cubeScene(8)).scene);
    DicingSettings coarse;
    coarse.rate = 4.0f;
    std::size_t coarser = triangles(describe(cubeScene(8), coarse).scene);
    EXPECT_LT(coarser * 8, fine) << "4x the micro-edge length: about 16x fewer triangles";
    std::size_t overridden = triangles(describe(cubeScene(8, "    float primvars:fluence:dicingRate = 4")).scene);
    EXPECT_EQ(overridden, coarser);
}

TEST(SubdivisionMesh, UniformLevelIgnoresTheCamera) {
    DicingSettings uniform;
    uniform.uniformLevel = 3;
    EXPECT_EQ(triangles(describe(cubeScene(2), uniform).scene), 6u * 2u * 64u);
    EXPECT_EQ(triangles(describe(cubeScene(100), uniform).scene), 6u * 2u * 64u);
}

TEST(SubdivisionMesh, PerMeshBudgetBitesWithAWarning) {
    DicingSettings tight;
    tight.meshTriangleBudget = 2000;
    Described d = describe(cubeScene(2), tight);
    EXPECT_LE(triangles(d.scene), 2000u);
    EXPECT_GT(triangles(d.scene), 500u) << "coarser, not collapsed";
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings[0].find("exceeds the per-mesh budget of 2000"), std::string::npos) << d.warnings[0];
}

TEST(SubdivisionMesh, SceneBudgetScalesEveryMesh) {
    DicingSettings tight;
    tight.sceneTriangleBudget = 3000;
    Described d = describe(cubeScene(2), tight);
    EXPECT_LE(triangles(d.scene), 3000u);
    ASSERT_FALSE(d.warnings.empty());
    EXPECT_NE(d.warnings.back().find("over the scene budget of 3000"), std::string::npos) << d.warnings.back();
}

TEST(SubdivisionMesh, LeftHandedMeshesStillFaceOutwards) {
    Described d = describe(cubeScene(4, R"(    uniform token orientation = "leftHanded")"));
    // The same cage read left-handed winds inwards, so its limit surface faces inwards too.
    EXPECT_LT(enclosedVolume(d.scene.meshes.at(0)), 0.0);
}

TEST(SubdivisionMesh, DisplacementMovesTheLimitSurfaceAlongItsNormal) {
    const std::string material = R"(
def Material "Puffy"
{
    token outputs:surface.connect = </Puffy/Surface.outputs:surface>
    def Shader "Surface"
    {
        uniform token info:id = "UsdPreviewSurface"
        float inputs:displacement = 0.25
        token outputs:surface
    }
}
)";
    DicingSettings uniform;
    uniform.uniformLevel = 3;
    float plain = maxRadius(describe(cubeScene(4), uniform).scene.meshes.at(0));
    Described displaced = describe(cubeScene(4, "    rel material:binding = </Puffy>", material), uniform);
    // Outward along the unit normal by 0.25 everywhere, so the farthest point moves out by 0.25
    // (the corners, where the normal points away from the centre).
    EXPECT_NEAR(maxRadius(displaced.scene.meshes.at(0)), plain + 0.25f, 1e-4f);
}

TEST(SubdivisionMesh, DisplayColorIsRefinedWithTheSurface) {
    // Vertex colours: red on the +z points, blue on the -z ones; the limit blends them.
    const std::string colors =
        R"(    color3f[] primvars:displayColor = [(1, 0, 0), (1, 0, 0), (1, 0, 0), (1, 0, 0), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1)] (
        interpolation = "vertex"
    ))";
    DicingSettings uniform;
    uniform.uniformLevel = 2;
    Described blended = describe(cubeScene(4, colors), uniform);
    const render::MeshDesc& mesh = blended.scene.meshes.at(0);
    ASSERT_EQ(mesh.cornerColors.size(), mesh.indices.size());
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
        const Vec3f& p = mesh.positions[mesh.indices[c]];
        const RGB& color = mesh.cornerColors[c];
        EXPECT_NEAR(color.x + color.z, 1.0f, 1e-5f) << "a blend of the two";
        if (p.z > 0.3f) {
            EXPECT_GT(color.x, color.z);
        } else if (p.z < -0.3f) {
            EXPECT_LT(color.x, color.z);
        }
    }
    // Uniform colours: one per face, constant over it.
    const std::string uniformColors =
        R"(    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (0, 1, 1), (1, 0, 1)] (
        interpolation = "uniform"
    ))";
    Described perFace = describe(cubeScene(4, uniformColors), uniform);
    const render::MeshDesc& faces = perFace.scene.meshes.at(0);
    std::set<std::tuple<float, float, float>> distinct;
    for (const RGB& c : faces.cornerColors) distinct.insert({c.x, c.y, c.z});
    EXPECT_EQ(distinct.size(), 6u);
}

TEST(SubdivisionMesh, EditingPointsKeepsTheTopologyAndMovingKeepsEverything) {
    auto stage = stageFrom(cubeScene(4));
    DelegateOptions options;
    options.resolution = std::make_pair(64, 64);
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [](const std::string&, const std::string&) {};
    SceneDelegate delegate(*stage, options);
    delegate.sync();
    const auto& cube = static_cast<const MeshRprim&>(*delegate.renderIndex().find("/Cube"));
    const SubdivisionSurface* topology = &cube.subdivided().at(0).mesh->surface();
    const float radius = maxRadius(delegate.sceneDescription().meshes.at(0));

    std::vector<double> bigger;
    for (double c : {-1, -1, 1, 1, -1, 1, -1, 1, 1, 1, 1, 1, -1, 1, -1, 1, 1, -1, -1, -1, -1, 1, -1, -1})
        bigger.push_back(c);
    delegate.setAttribute("/Cube", "points", usd::Value::numeric("point3f[]", bigger, 3, true));
    delegate.sync();
    EXPECT_EQ(&cube.subdivided().at(0).mesh->surface(), topology) << "points alone do not rebuild the topology";
    EXPECT_NEAR(maxRadius(delegate.sceneDescription().meshes.at(0)), 2.0f * radius, 1e-3f) << "the cage doubled";

    delegate.setAttribute("/Cube", "faceVertexCounts", usd::Value::numeric("int[]", {4, 4, 4, 4, 4, 4}, 1, true));
    delegate.sync();
    EXPECT_NE(&cube.subdivided().at(0).mesh->surface(), topology) << "a topology edit rebuilds it";
}

TEST(SubdivisionMesh, BadTopologyNamesThePrimAndSkipsIt) {
    Described d = describe(std::regex_replace(cubeScene(4), std::regex("0, 1, 3, 2, 2"), "0, 1, 3, 9, 2"));
    EXPECT_TRUE(d.scene.meshes.empty()) << "a point index out of range was accepted";
    ASSERT_EQ(d.warnings.size(), 1u);
    EXPECT_NE(d.warnings[0].find("/Cube: not rendered: "), std::string::npos) << d.warnings[0];
    EXPECT_NE(d.warnings[0].find("faceVertexIndices[3] = 9"), std::string::npos) << d.warnings[0];
}

// Indexed primvars only compress values: one `st` value may serve corners at different points (Maya
// writes this where a UV edge collapses to one value). OpenSubdiv's face-varying topology assumes
// each value belongs to one point; each point now gets its own copy of a shared value. 21 faces (a
// hexagon and a heptagon among them) whose connectivity is modelled on Kitchen Set's WallPineapple
// pCube587 (renumbered; made-up points and values), with `st` values shared by different points and
// another face-varying primvar before it. Before the fix Bfr gave face 18 a face-varying control
// point out of channel 1's range: a segfault in SubdivisionSurface::Impl::evaluateFaceVarying.
TEST(SubdivisionMesh, SharedFaceVaryingValuesOnIrregularFacesStayInRange) {
    const std::string usda = R"(#usda 1.0
def Mesh "M"
{
    float[] primvars:a = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88] (
        interpolation = "faceVarying"
    )
    int[] faceVertexCounts = [4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 4, 6, 7]
    int[] faceVertexIndices = [0, 1, 2, 3, 1, 0, 4, 5, 5, 4, 6, 7, 8, 9, 10, 11, 11, 10, 12, 13, 14, 3, 13, 12, 15, 0, 3, 14, 0, 15, 16, 4, 4, 16, 17, 6, 18, 19, 20, 21, 22, 23, 21, 20, 24, 25, 19, 18, 8, 26, 24, 18, 8, 18, 21, 9, 23, 27, 9, 21, 28, 7, 6, 29, 29, 6, 17, 30, 31, 30, 17, 32, 33, 34, 35, 36, 37, 38, 39, 33, 40, 41, 40, 33, 36, 35, 42, 43, 44]
    point3f[] points = [(0, 0, 0), (1, 0, 3), (2, 0, 1), (3, 0, 4), (4, 0, 2), (5, 0, 0), (6, 0, 3), (0, 1, 1), (1, 1, 4), (2, 1, 2), (3, 1, 0), (4, 1, 3), (5, 1, 1), (6, 1, 4), (0, 2, 2), (1, 2, 0), (2, 2, 3), (3, 2, 1), (4, 2, 4), (5, 2, 2), (6, 2, 0), (0, 3, 3), (1, 3, 1), (2, 3, 4), (3, 3, 2), (4, 3, 0), (5, 3, 3), (6, 3, 1), (0, 4, 4), (1, 4, 2), (2, 4, 0), (3, 4, 3), (4, 4, 1), (5, 4, 4), (6, 4, 2), (0, 5, 0), (1, 5, 3), (2, 5, 1), (3, 5, 4), (4, 5, 2), (5, 5, 0), (6, 5, 3), (0, 6, 1), (1, 6, 4), (2, 6, 2)]
    texCoord2f[] primvars:st = [(0, 0), (0.166667, 0), (0.333333, 0), (0.5, 0), (0.666667, 0), (0.833333, 0), (0, 0.166667), (0.166667, 0.166667), (0.333333, 0.166667), (0.5, 0.166667), (0.666667, 0.166667), (0.833333, 0.166667), (0, 0.333333), (0.166667, 0.333333), (0.333333, 0.333333), (0.5, 0.333333), (0.666667, 0.333333), (0.833333, 0.333333), (0, 0.5), (0.166667, 0.5), (0.333333, 0.5), (0.5, 0.5), (0.666667, 0.5), (0.833333, 0.5), (0, 0.666667), (0.166667, 0.666667), (0.333333, 0.666667), (0.5, 0.666667), (0.666667, 0.666667), (0.833333, 0.666667), (0, 0.833333), (0.166667, 0.833333), (0.333333, 0.833333), (0.5, 0.833333), (0.666667, 0.833333), (0.833333, 0.833333), (0, 1), (0.166667, 1), (0.333333, 1), (0.5, 1)] (
        interpolation = "faceVarying"
    )
    int[] primvars:st:indices = [0, 1, 2, 3, 1, 0, 4, 5, 5, 4, 6, 7, 8, 9, 10, 11, 11, 10, 12, 13, 14, 3, 13, 12, 15, 0, 3, 14, 0, 15, 16, 4, 4, 16, 17, 6, 18, 19, 20, 21, 22, 23, 21, 20, 24, 24, 19, 18, 8, 25, 24, 18, 8, 18, 21, 9, 23, 26, 9, 21, 27, 27, 6, 28, 28, 6, 17, 29, 30, 29, 17, 31, 32, 33, 34, 35, 24, 24, 36, 32, 37, 38, 37, 32, 35, 34, 27, 27, 39]
}
)";
    Described d = describe(usda, {}, {"a", "st"});
    ASSERT_EQ(d.scene.meshes.size(), 1u);
    const render::MeshDesc& mesh = d.scene.meshes[0];
    ASSERT_GT(mesh.indices.size(), 0u);
    ASSERT_EQ(mesh.primvars.size(), 2u);
    for (const render::CornerPrimvar& pv : mesh.primvars) {
        SCOPED_TRACE(pv.name);
        ASSERT_EQ(pv.values.size(), std::size_t(pv.components) * mesh.indices.size());
        const float high = pv.name == "a" ? 88.0f : 1.0f;  // the data's largest value
        for (float v : pv.values) {
            ASSERT_TRUE(std::isfinite(v));
            EXPECT_GE(v, -1e-3f);
            EXPECT_LE(v, high + 1e-3f);
        }
    }
}

TEST(SubdivisionMesh, InstancedSubdivisionSurfacesAreDicedForTheNearestInstance) {
    const std::string scene = cubeScene(3, "", R"(
def PointInstancer "Many"
{
    int[] protoIndices = [0, 0]
    point3f[] positions = [(0, 0, -100), (0, 0, POSITION)]
    rel prototypes = </Many/Protos/Cube>
    def Scope "Protos"
    {
        def Mesh "Cube"
        {
            int[] faceVertexCounts = [4, 4, 4, 4, 4, 4]
            int[] faceVertexIndices = [0, 1, 3, 2, 2, 3, 5, 4, 4, 5, 7, 6, 6, 7, 1, 0, 1, 7, 5, 3, 6, 0, 2, 4]
            point3f[] points = [(-0.5, -0.5, 0.5), (0.5, -0.5, 0.5), (-0.5, 0.5, 0.5), (0.5, 0.5, 0.5), (-0.5, 0.5, -0.5), (0.5, 0.5, -0.5), (-0.5, -0.5, -0.5), (0.5, -0.5, -0.5)]
        }
    }
}
)");
    // The standalone cube is 3 units from the camera. With the second instance also at 3 units
    // (position 0), the prototype is diced as finely as the standalone cube; with both instances
    // far away, much coarser.
    Described near = describe(std::regex_replace(scene, std::regex("POSITION"), "0"));
    Described far = describe(std::regex_replace(scene, std::regex("POSITION"), "-100"));
    ASSERT_EQ(near.scene.prototypes.size(), 1u);
    std::size_t standalone = near.scene.meshes.at(0).indices.size();
    EXPECT_EQ(near.scene.prototypes[0].meshes.at(0).indices.size(), standalone);
    EXPECT_LT(far.scene.prototypes[0].meshes.at(0).indices.size() * 20, standalone);
}

}  // namespace
}  // namespace fluence::delegate
