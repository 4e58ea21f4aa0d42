// Displacement (delegate/displacement.h, delegate/polygon_dicing.h), each test against a known
// answer: a plane displaced by a constant, a sphere's silhouette, a step texture's height field,
// and meshes that do not displace left bit for bit as they were.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "delegate/polygon_dicing.h"
#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"
#include "texture/texture_system.h"

namespace fluence::delegate {
namespace {

using testing::stageFrom;

struct Described {
    std::unique_ptr<usd::Stage> stage;
    render::SceneDescription scene;
    std::vector<std::string> warnings;
};

Described describe(const std::string& usda, int uniformLevel = -1) {
    Described d;
    d.stage = stageFrom(usda);
    DelegateOptions options;
    options.resolution = std::make_pair(256, 256);
    options.dicing.uniformLevel = uniformLevel;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&d](const std::string& path, const std::string& message) {
        d.warnings.push_back(path + ": " + message);
    };
    options.textures = std::make_shared<texture::TextureSystem>(color::ColorManagement::load());
    d.scene = populateScene(*d.stage, options).scene;
    return d;
}

// A material /Looks/M whose UsdPreviewSurface displacement is `displacement` (its body).
std::string material(const std::string& displacement) {
    return R"(
def Scope "Looks"
{
    def Material "M"
    {
        token outputs:surface.connect = </Looks/M/Surface.outputs:surface>
        def Shader "Surface"
        {
            uniform token info:id = "UsdPreviewSurface"
)" + displacement +
           R"(
            token outputs:surface
        }
        def Shader "Reader"
        {
            uniform token info:id = "UsdPrimvarReader_float2"
            string inputs:varname = "st"
            float2 outputs:result
        }
    }
}
)";
}

// The unit quad in z = 0 (polygons, facing +z, st = xy), under a camera 3 units above it.
std::string plane(const std::string& binding) {
    return R"(#usda 1.0
def Camera "Cam"
{
    double3 xformOp:translate = (0.5, 0.5, 3)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Mesh "Plane"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (
        interpolation = "vertex"
    )
)" + binding +
           "\n}\n";
}

const std::string kBound = "    rel material:binding = </Looks/M>";

// The same scene with the plane's subdivisionScheme `scheme`: "catmullClark" makes it a subdivision
// surface whose limit is the same flat square (one face, corners interpolated), st following xy.
std::string withScheme(std::string usda, const std::string& scheme) {
    return usda.replace(usda.find("\"none\""), 6, "\"" + scheme + "\"");
}

const std::string kSchemes[] = {"none", "catmullClark"};

float hitDistance(const render::SceneDescription& scene, const Vec3f& origin, const Vec3f& direction) {
    render::RenderScene built(scene);
    render::Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    std::optional<render::SurfaceHit> hit = built.intersect(ray);
    return hit ? hit->t : -1.0f;
}

TEST(Displacement, PlaneMovesByTheConstantAlongItsNormal) {
    const float d = 0.25f;
    for (const std::string& scheme : kSchemes) {
        Described flat = describe(withScheme(plane(""), scheme));
        Described raised =
            describe(withScheme(plane(kBound), scheme) + material("            float inputs:displacement = 0.25"));
        ASSERT_TRUE(raised.warnings.empty()) << raised.warnings.front();
        const render::MeshDesc& mesh = raised.scene.meshes.at(0);
        EXPECT_GT(mesh.indices.size(), 6u) << scheme << ": diced finer than two triangles";
        for (const Vec3f& p : mesh.positions) EXPECT_FLOAT_EQ(p.z, d) << scheme;
        for (const Vec3f& n : mesh.cornerNormals) EXPECT_NEAR(n.z, 1.0f, 1e-6f) << scheme;
        // A ray straight down meets the displaced plane d sooner.
        for (const Vec3f& origin : {Vec3f(0.3f, 0.6f, 5.0f), Vec3f(0.77f, 0.21f, 5.0f)}) {
            const float before = hitDistance(flat.scene, origin, Vec3f(0, 0, -1));
            const float after = hitDistance(raised.scene, origin, Vec3f(0, 0, -1));
            EXPECT_NEAR(before, 5.0f, 1e-5f) << scheme;
            EXPECT_NEAR(before - after, d, 1e-5f) << scheme;
        }
    }
}

TEST(Displacement, SphereSilhouetteHasTheDisplacedRadius) {
    // A Sphere of radius 1 displaced by 0.25, seen along -z by parallel rays (an orthographic
    // camera's): the covered area is that of a disc of radius 1.25. The tessellation's sag
    // (implicit_geometry.h: 0.1% of the radius) and the ray grid's quantisation (about 0.02% of
    // the area at 400 x 400 rays) bound the difference well within 0.5%.
    const std::string scene = R"(#usda 1.0
def Camera "Cam"
{
    double3 xformOp:translate = (0, 0, 6)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Sphere "Ball"
{
    double radius = 1
)" + kBound + "\n}\n" + material("            float inputs:displacement = 0.25");
    Described d = describe(scene);
    ASSERT_TRUE(d.warnings.empty()) << d.warnings.front();
    render::RenderScene built(d.scene);
    const int n = 400;
    const float half = 1.5f, cell = 2.0f * half / n;
    int covered = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            render::Ray ray;
            ray.origin = Vec3f(-half + (x + 0.5f) * cell, -half + (y + 0.5f) * cell, 5.0f);
            ray.direction = Vec3f(0, 0, -1);
            covered += built.intersect(ray) ? 1 : 0;
        }
    const double area = covered * double(cell) * cell, expected = std::numbers::pi * 1.25 * 1.25;
    EXPECT_NEAR(area / expected, 1.0, 0.005);
}

// A 2 x 1 float image, texel values 0 (left) and 1 (right).
std::string writeStepTexture() {
    const std::string path = (std::filesystem::temp_directory_path() / "fluence_displacement_step.exr").string();
    const float texels[2] = {0.0f, 1.0f};
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(2, 1, 1, OIIO::TypeDesc::FLOAT)));
    out->write_image(OIIO::TypeDesc::FLOAT, texels);
    out->close();
    return path;
}

std::string textured(const std::string& file) {
    return R"(
            float inputs:displacement.connect = </Looks/M/Height.outputs:r>
        }
        def Shader "Height"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @)" +
           file + R"(@
            token inputs:sourceColorSpace = "raw"
            token inputs:wrapS = "clamp"
            token inputs:wrapT = "clamp"
            float4 inputs:scale = (0.5, 0.5, 0.5, 1)
            float4 inputs:bias = (0.1, 0.1, 0.1, 0)
            float2 inputs:st.connect = </Looks/M/Reader.outputs:result>
            float outputs:r)";
}

TEST(Displacement, StepTextureGivesItsHeightField) {
    // Bilinear between the texel centres s = 1/4 and 3/4, clamped outside: h(s) = 0.5 * ramp + 0.1,
    // at every vertex of the polygon plane and of the subdivision surface (whose st is x there).
    const std::string file = writeStepTexture();
    for (const std::string& scheme : kSchemes) {
        Described d = describe(withScheme(plane(kBound), scheme) + material(textured(file)), 3);
        ASSERT_TRUE(d.warnings.empty()) << d.warnings.front();
        const render::MeshDesc& mesh = d.scene.meshes.at(0);
        if (scheme == "none") {
            EXPECT_EQ(mesh.indices.size(), 2u * 64u * 3u) << "--subdiv-level 3: 8 segments per edge";
        }
        for (const Vec3f& p : mesh.positions) {
            const float ramp = std::clamp((p.x - 0.25f) / 0.5f, 0.0f, 1.0f);
            EXPECT_NEAR(p.z, 0.5f * ramp + 0.1f, 1e-4f) << scheme << " at s = " << p.x;
        }
    }
}

TEST(Displacement, MissingTextureIsNamedAndDisplacesNothing) {
    Described d = describe(plane(kBound) + material(textured("no_such_height.exr")), 2);
    ASSERT_FALSE(d.warnings.empty());
    EXPECT_NE(d.warnings.front().find("no_such_height.exr"), std::string::npos) << d.warnings.front();
    for (const Vec3f& p : d.scene.meshes.at(0).positions) EXPECT_EQ(p.z, 0.0f);
}

TEST(Displacement, MaterialsThatDoNotDisplaceLeaveMeshesBitForBit) {
    const std::string still = material("            float inputs:displacement = 0");
    for (const std::string& scheme : kSchemes) {
        Described bare = describe(withScheme(plane(""), scheme));
        Described bound = describe(withScheme(plane(kBound), scheme) + still);
        const render::MeshDesc &a = bare.scene.meshes.at(0), &b = bound.scene.meshes.at(0);
        EXPECT_EQ(a.positions.size(), b.positions.size()) << scheme;
        EXPECT_TRUE(std::equal(a.positions.begin(), a.positions.end(), b.positions.begin(), b.positions.end(),
                               [](const Vec3f& p, const Vec3f& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }))
            << scheme;
        EXPECT_EQ(a.indices, b.indices) << scheme;
        EXPECT_EQ(a.cornerNormals.size(), b.cornerNormals.size()) << scheme;
    }
}

TEST(Displacement, DicedTrianglesMeetWhereTheirEdgeCountsDiffer) {
    // Two triangles sharing the diagonal, cut into 4 and 1 segments per edge: the finer one's
    // points on the diagonal snap to the diagonal's own single segment, so both sides agree.
    render::MeshDesc mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    TriangleEdges edges(mesh);
    std::vector<int> segments(edges.edges().size(), 1);
    for (std::size_t e = 0; e < segments.size(); ++e)
        if (edges.edges()[e] == std::pair(0, 1)) segments[e] = 4;
    DicedTriangles diced = diceTriangles(mesh, edges, segments);
    EXPECT_EQ(diced.mesh.indices.size() / 3, 16u + 1u);
    // Every point of the diced mesh on the diagonal x = y is one of its ends.
    for (const Vec3f& p : diced.mesh.positions)
        if (std::abs(p.x - p.y) < 1e-6f) {
            EXPECT_TRUE(p.x == 0.0f || p.x == 1.0f) << p.x;
        }
    EXPECT_EQ(dicedTriangleCount(edges, 2, segments), 17u);
}

}  // namespace
}  // namespace fluence::delegate
