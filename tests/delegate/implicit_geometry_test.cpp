#include "delegate/implicit_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "delegate/prim_reader.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::populateStrict;
constexpr double kPi = std::numbers::pi;

// An implicit prim's analytic shape, centred at the origin.
struct Shape {
    std::string type;
    double radius = 0.0;  // Cube: half the size
    double height = 0.0;  // Cylinder, Cone: total; Capsule: the cylinder part
    int axis = 2;         // index of the spine axis

    double area() const {
        double r = radius, h = height;
        if (type == "Sphere") return 4.0 * kPi * r * r;
        if (type == "Cube") return 6.0 * 4.0 * r * r;
        if (type == "Cylinder") return 2.0 * kPi * r * h + 2.0 * kPi * r * r;
        if (type == "Cone") return kPi * r * std::hypot(r, h) + kPi * r * r;
        return 2.0 * kPi * r * h + 4.0 * kPi * r * r;  // Capsule
    }
    double volume() const {
        double r = radius, h = height;
        if (type == "Sphere") return 4.0 / 3.0 * kPi * r * r * r;
        if (type == "Cube") return 8.0 * r * r * r;
        if (type == "Cylinder") return kPi * r * r * h;
        if (type == "Cone") return kPi * r * r * h / 3.0;
        return kPi * r * r * h + 4.0 / 3.0 * kPi * r * r * r;  // Capsule
    }

    // Unsigned distance from `p` to the analytic surface.
    double distance(const Vec3d& p) const {
        if (type == "Cube") {
            Vec3d q(std::abs(p.x) - radius, std::abs(p.y) - radius, std::abs(p.z) - radius);
            double inside = std::min(maxComponent(q), 0.0);
            return std::abs(inside + length(vmax(q, Vec3d(0.0))));
        }
        double w = p[axis];
        double rho = std::hypot(p[(axis + 1) % 3], p[(axis + 2) % 3]);
        const double r = radius, top = 0.5 * height, bottom = -0.5 * height;
        auto segment = [&](double ar, double aw, double br, double bw) {
            double dr = br - ar, dw = bw - aw;
            double t = std::clamp(((rho - ar) * dr + (w - aw) * dw) / (dr * dr + dw * dw), 0.0, 1.0);
            return std::hypot(rho - (ar + t * dr), w - (aw + t * dw));
        };
        if (type == "Sphere") return std::abs(std::hypot(rho, w) - r);
        if (type == "Capsule") return std::abs(std::hypot(rho, w - std::clamp(w, bottom, top)) - r);
        if (type == "Cylinder")
            return std::min({segment(0, top, r, top), segment(r, top, r, bottom), segment(r, bottom, 0, bottom)});
        return std::min(segment(0, top, r, bottom), segment(r, bottom, 0, bottom));  // Cone
    }
};

struct Case {
    std::string usda;  // one prim named "P" at the origin
    Shape shape;
};

std::vector<Case> cases() {
    return {
        {"def Sphere \"P\"\n{\n}\n", {"Sphere", 1.0}},
        {"def Sphere \"P\"\n{\n    double radius = 2.5\n}\n", {"Sphere", 2.5}},
        {"def Cube \"P\"\n{\n}\n", {"Cube", 1.0}},
        {"def Cube \"P\"\n{\n    double size = 0.5\n}\n", {"Cube", 0.25}},
        {"def Cylinder \"P\"\n{\n}\n", {"Cylinder", 1.0, 2.0, 2}},
        {"def Cylinder \"P\"\n{\n    double radius = 0.5\n    double height = 3\n    uniform token axis = \"X\"\n}\n",
         {"Cylinder", 0.5, 3.0, 0}},
        {"def Cone \"P\"\n{\n}\n", {"Cone", 1.0, 2.0, 2}},
        {"def Cone \"P\"\n{\n    double radius = 2\n    double height = 0.5\n    uniform token axis = \"Y\"\n}\n",
         {"Cone", 2.0, 0.5, 1}},
        {"def Capsule \"P\"\n{\n}\n", {"Capsule", 0.5, 1.0, 2}},
        {"def Capsule \"P\"\n{\n    double radius = 1.5\n    double height = 4\n    uniform token axis = \"Y\"\n}\n",
         {"Capsule", 1.5, 4.0, 1}},
        {"def Capsule \"P\"\n{\n    double radius = 1\n    double height = 0\n    uniform token axis = \"X\"\n}\n",
         {"Capsule", 1.0, 0.0, 0}},
    };
}

std::string label(const Case& c) {
    return c.shape.type + " r=" + std::to_string(c.shape.radius) + " h=" + std::to_string(c.shape.height) +
           " axis=" + "XYZ"[c.shape.axis];
}

TEST(ImplicitGeometry, SegmentCountsFollowFromTheTolerance) {
    EXPECT_EQ(circleSegments(), 72);
    EXPECT_LE(1.0 - std::cos(kPi / circleSegments()), kSilhouetteTolerance);
    EXPECT_GT(1.0 - std::cos(kPi / (circleSegments() - 4)), kSilhouetteTolerance) << "the smallest multiple of 4";
    EXPECT_EQ(sphereSegments(), 100);
}

TEST(ImplicitGeometry, VerticesLieOnTheSurfaceAndTrianglesWithinTheTolerance) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(label(c));
        auto p = populate(c.usda);
        ASSERT_EQ(p.result.scene.meshes.size(), 1u);
        const render::MeshDesc& m = p.result.scene.meshes[0];
        EXPECT_EQ(m.name, "/P");
        ASSERT_FALSE(m.indices.empty());
        const double scale = c.shape.radius;
        double worstVertex = 0.0, worstSag = 0.0;
        for (const Vec3f& v : m.positions) worstVertex = std::max(worstVertex, c.shape.distance(Vec3d(v)));
        for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
            Vec3d a = testing::corner(m, 3 * t), b = testing::corner(m, 3 * t + 1), d = testing::corner(m, 3 * t + 2);
            for (const Vec3d& q : {(a + b + d) / 3.0, (a + b) / 2.0, (b + d) / 2.0, (d + a) / 2.0})
                worstSag = std::max(worstSag, c.shape.distance(q));
        }
        EXPECT_LT(worstVertex, 1e-6 * scale + 1e-6);
        EXPECT_LE(worstSag, kSilhouetteTolerance * scale * (1.0 + 1e-4));
    }
}

TEST(ImplicitGeometry, AreaAndVolumeMatchTheAnalyticShape) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(label(c));
        auto p = populate(c.usda);
        ASSERT_EQ(p.result.scene.meshes.size(), 1u);
        const render::MeshDesc& m = p.result.scene.meshes[0];
        double areaError = testing::surfaceArea(m) / c.shape.area() - 1.0;
        double volumeError = testing::enclosedVolume(m) / c.shape.volume() - 1.0;
        EXPECT_LT(std::abs(areaError), 0.002);
        EXPECT_LT(std::abs(volumeError), 0.002);
        // Inscribed tessellations only lose area and volume (the cube is exact).
        EXPECT_LT(areaError, 1e-6);
        EXPECT_LT(volumeError, 1e-6);
        RecordProperty(label(c) + " area error", std::to_string(areaError));
        RecordProperty(label(c) + " volume error", std::to_string(volumeError));
    }
}

TEST(ImplicitGeometry, NormalsAreUnitAndOutward) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(label(c));
        auto p = populate(c.usda);
        const render::MeshDesc& m = p.result.scene.meshes.at(0);
        ASSERT_EQ(m.cornerNormals.size(), m.indices.size());
        for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
            Vec3d geometric = testing::triangleCross(m, t);
            ASSERT_GT(length(geometric), 0.0) << "degenerate triangle " << t;
            Vec3d centroid =
                (testing::corner(m, 3 * t) + testing::corner(m, 3 * t + 1) + testing::corner(m, 3 * t + 2)) / 3.0;
            ASSERT_GT(dot(geometric, centroid), 0.0) << "triangle " << t << " winds inwards";  // all five are convex
            for (std::size_t k = 3 * t; k < 3 * t + 3; ++k) {
                Vec3d n(m.cornerNormals[k]);
                ASSERT_NEAR(length(n), 1.0, 1e-6);
                ASSERT_GT(dot(n, testing::corner(m, k)), 0.0) << "corner " << k << " normal points inwards";
                ASSERT_GT(dot(n, geometric), 0.0) << "corner " << k << " normal is on the back of its triangle";
            }
        }
    }
}

TEST(ImplicitGeometry, SmoothNormalsOnCurvedPartsAndFlatOnCapsAndCube) {
    auto p = populate(R"(
def Sphere "Sphere"
{
}
def Cylinder "Cylinder"
{
}
def Cube "Cube"
{
}
def Cone "Cone"
{
    double height = 3
}
)");
    const render::MeshDesc* sphere = p.mesh("/Sphere");
    ASSERT_NE(sphere, nullptr);
    for (std::size_t k = 0; k < sphere->indices.size(); ++k) {
        Vec3d radial = normalize(testing::corner(*sphere, k));
        ASSERT_NEAR(length(Vec3d(sphere->cornerNormals[k]) - radial), 0.0, 1e-6) << "sphere corner " << k;
    }
    const render::MeshDesc* cylinder = p.mesh("/Cylinder");
    ASSERT_NE(cylinder, nullptr);
    for (std::size_t k = 0; k < cylinder->indices.size(); ++k) {
        Vec3f n = cylinder->cornerNormals[k];
        Vec3f q = cylinder->positions[cylinder->indices[k]];
        bool cap = std::abs(n.z) > 0.5f;
        if (cap) {
            EXPECT_EQ(n, Vec3f(0, 0, q.z > 0 ? 1.0f : -1.0f)) << "flat cap";
        } else {
            EXPECT_EQ(n.z, 0.0f);
            EXPECT_NEAR(n.x, q.x, 1e-6f) << "radial side normal";
            EXPECT_NEAR(n.y, q.y, 1e-6f);
        }
    }
    const render::MeshDesc* cube = p.mesh("/Cube");
    ASSERT_NE(cube, nullptr);
    EXPECT_EQ(cube->indices.size(), 36u);
    for (std::size_t t = 0; t < 12; ++t)
        for (std::size_t k = 3 * t; k < 3 * t + 3; ++k)
            EXPECT_NEAR(length(Vec3d(cube->cornerNormals[k]) - normalize(testing::triangleCross(*cube, t))), 0.0, 1e-7);
    // The cone's side normal tilts towards the apex by atan(radius / height).
    const render::MeshDesc* cone = p.mesh("/Cone");
    ASSERT_NE(cone, nullptr);
    const float expectedZ = static_cast<float>(1.0 / std::hypot(1.0, 3.0));
    std::size_t side = 0;
    for (const Vec3f& n : cone->cornerNormals)
        if (n.z > 0.0f) {
            EXPECT_NEAR(n.z, expectedZ, 1e-6f);
            ++side;
        }
    EXPECT_EQ(side, 3u * static_cast<std::size_t>(circleSegments()));
}

// The extent of a mesh along each world axis.
std::pair<Vec3f, Vec3f> bounds(const render::MeshDesc& m) {
    Vec3f lo(1e30f), hi(-1e30f);
    for (const Vec3f& p : m.positions) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    return {lo, hi};
}

TEST(ImplicitGeometry, AxisOrientsTheSpine) {
    for (const char* axis : {"X", "Y", "Z"}) {
        SCOPED_TRACE(axis);
        const int a = axis[0] - 'X';
        auto p = populate(std::string(R"(
def Cylinder "Cylinder"
{
    double radius = 0.5
    double height = 6
    uniform token axis = ")") +
                          axis + R"("
}
def Cone "Cone"
{
    double radius = 0.5
    double height = 6
    uniform token axis = ")" +
                          axis + R"("
}
def Capsule "Capsule"
{
    double radius = 0.5
    double height = 6
    uniform token axis = ")" +
                          axis + R"("
}
)");
        for (const char* name : {"/Cylinder", "/Cone", "/Capsule"}) {
            SCOPED_TRACE(name);
            const render::MeshDesc* m = p.mesh(name);
            ASSERT_NE(m, nullptr);
            auto [lo, hi] = bounds(*m);
            float half = std::string(name) == "/Capsule" ? 3.5f : 3.0f;
            for (int i = 0; i < 3; ++i) {
                EXPECT_NEAR(lo[i], i == a ? -half : -0.5f, 1e-5f) << "axis " << i;
                EXPECT_NEAR(hi[i], i == a ? half : 0.5f, 1e-5f) << "axis " << i;
            }
        }
        // The cone's apex is at +height/2 on its axis.
        const render::MeshDesc* cone = p.mesh("/Cone");
        for (const Vec3f& q : cone->positions)
            if (q[a] > 2.9f) {
                EXPECT_NEAR(q[(a + 1) % 3], 0.0f, 1e-6f);
                EXPECT_NEAR(q[(a + 2) % 3], 0.0f, 1e-6f);
            }
    }
}

TEST(ImplicitGeometry, WorldTransformIsApplied) {
    auto p = populate(R"(
def Xform "Group"
{
    double3 xformOp:translate = (1, 2, 3)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def Sphere "Scaled"
    {
        double radius = 0.5
        float3 xformOp:scale = (2, 2, 2)
        uniform token[] xformOpOrder = ["xformOp:scale"]
    }
    def Cube "Mirrored"
    {
        float3 xformOp:scale = (-1, 1, 1)
        float xformOp:rotateZ = 45
        uniform token[] xformOpOrder = ["xformOp:rotateZ", "xformOp:scale"]
    }
}
)");
    const Vec3d centre(1, 2, 3);
    const render::MeshDesc* sphere = p.mesh("/Group/Scaled");
    ASSERT_NE(sphere, nullptr);
    for (const Vec3f& q : sphere->positions) ASSERT_NEAR(length(Vec3d(q) - centre), 1.0, 1e-6);
    for (std::size_t k = 0; k < sphere->indices.size(); ++k)
        ASSERT_NEAR(length(Vec3d(sphere->cornerNormals[k]) - normalize(testing::corner(*sphere, k) - centre)), 0.0,
                    1e-6);
    EXPECT_NEAR(testing::enclosedVolume(*sphere), 4.0 / 3.0 * kPi, 0.002 * 4.0 / 3.0 * kPi);

    // Under a mirroring transform the triangles still wind outwards.
    const render::MeshDesc* cube = p.mesh("/Group/Mirrored");
    ASSERT_NE(cube, nullptr);
    for (std::size_t t = 0; t < cube->indices.size() / 3; ++t) {
        Vec3d centroid =
            (testing::corner(*cube, 3 * t) + testing::corner(*cube, 3 * t + 1) + testing::corner(*cube, 3 * t + 2)) /
            3.0;
        EXPECT_GT(dot(testing::triangleCross(*cube, t), centroid - centre), 0.0) << "triangle " << t;
        EXPECT_GT(dot(Vec3d(cube->cornerNormals[3 * t]), centroid - centre), 0.0) << "triangle " << t;
    }
    auto [lo, hi] = bounds(*cube);
    EXPECT_NEAR(hi.x - lo.x, 2.0 * std::sqrt(2.0), 1e-5) << "rotated 45 degrees about Z";
    EXPECT_NEAR(hi.z - lo.z, 2.0, 1e-5);
}

TEST(ImplicitGeometry, DisplayColorAndMaterialBinding) {
    auto p = populate(R"(
def Material "Red"
{
    token outputs:surface.connect = </Red/S.outputs:surface>
    def Shader "S"
    {
        uniform token info:id = "UsdPreviewSurface"
        color3f inputs:diffuseColor = (1, 0, 0)
    }
}
def Sphere "Constant"
{
    color3f[] primvars:displayColor = [(0.25, 0.5, 0.75)]
}
def Cube "Indexed"
{
    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0)] (
        interpolation = "constant"
    )
    int[] primvars:displayColor:indices = [1]
}
def Cylinder "Uniform"
{
    color3f[] primvars:displayColor = [(0, 0, 1), (1, 1, 0)] (
        interpolation = "uniform"
    )
}
def Cone "Bound"
{
    rel material:binding = </Red>
    color3f[] primvars:displayColor = [(0, 1, 1)]
}
def Capsule "Plain"
{
}
)");
    const auto& s = p.result.scene;
    ASSERT_EQ(s.meshes.size(), 5u);
    auto colors = [&](const char* name) { return p.mesh(name)->cornerColors; };
    auto all = [](const std::vector<RGB>& c, const RGB& value) {
        return !c.empty() && std::all_of(c.begin(), c.end(), [&](const RGB& x) { return x == value; });
    };
    EXPECT_EQ(colors("/Constant").size(), p.mesh("/Constant")->indices.size());
    EXPECT_TRUE(all(colors("/Constant"), RGB(0.25f, 0.5f, 0.75f)));
    EXPECT_TRUE(all(colors("/Indexed"), RGB(0, 1, 0)));
    EXPECT_TRUE(all(colors("/Uniform"), RGB(0, 0, 1))) << "non-constant: the first value";
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("/Uniform: 'primvars:displayColor' with uniform interpolation"), std::string::npos)
        << p.warnings[0];

    const render::MeshDesc* bound = p.mesh("/Bound");
    ASSERT_GE(bound->material, 0);
    EXPECT_EQ(s.materials[static_cast<std::size_t>(bound->material)].name, "/Red");
    EXPECT_EQ(s.materials[static_cast<std::size_t>(bound->material)].diffuse, RGB(1, 0, 0));
    EXPECT_TRUE(bound->cornerColors.empty()) << "a bound material replaces displayColor";
    EXPECT_EQ(p.mesh("/Plain")->material, -1);
    EXPECT_TRUE(p.mesh("/Plain")->cornerColors.empty());
}

TEST(ImplicitGeometry, VisibilityAndPurposeAsForMeshes) {
    auto p = populate(R"(
def Sphere "Hidden"
{
    token visibility = "invisible"
}
def Xform "HiddenGroup"
{
    token visibility = "invisible"
    def Cube "Child"
    {
    }
}
def Cone "Guide"
{
    uniform token purpose = "guide"
}
def Capsule "Proxy"
{
    uniform token purpose = "proxy"
}
def Cylinder "Render"
{
    uniform token purpose = "render"
}
)");
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    EXPECT_EQ(p.result.scene.meshes[0].name, "/Render");
    EXPECT_TRUE(p.warnings.empty());
}

TEST(ImplicitGeometry, InvalidAttributesNameThePrim) {
    auto expectError = [](const std::string& usda, const std::string& fragment) {
        try {
            populateStrict(usda);
            ADD_FAILURE() << "expected SceneError for " << usda;
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("/Bad"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    expectError("def Sphere \"Bad\"\n{\n    double radius = -1\n}\n", "'radius' must be a finite, non-negative number");
    expectError("def Cube \"Bad\"\n{\n    double size = -2\n}\n", "'size'");
    expectError("def Cylinder \"Bad\"\n{\n    uniform token axis = \"W\"\n}\n", "axis must be");
    expectError("def Capsule \"Bad\"\n{\n    double height = -1\n}\n", "'height'");
    // A radius of zero is no surface at all: nothing to render, no error.
    EXPECT_TRUE(populate("def Sphere \"Empty\"\n{\n    double radius = 0\n}\n").result.scene.meshes.empty());
}

TEST(ImplicitGeometry, PopulateSceneRendersAllFiveTypesWithoutWarnings) {
    auto p = populate(R"(
def Xform "World"
{
    def Sphere "Sphere"
    {
    }
    def Cube "Cube"
    {
    }
    def Cylinder "Cylinder"
    {
    }
    def Cone "Cone"
    {
    }
    def Capsule "Capsule"
    {
    }
}
)");
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
    ASSERT_EQ(p.result.scene.meshes.size(), 5u);
    std::vector<std::string> names;
    for (const auto& m : p.result.scene.meshes) {
        names.push_back(m.name);
        EXPECT_FALSE(m.indices.empty());
        EXPECT_EQ(m.cornerNormals.size(), m.indices.size());
    }
    EXPECT_EQ(names, (std::vector<std::string>{"/World/Sphere", "/World/Cube", "/World/Cylinder", "/World/Cone",
                                               "/World/Capsule"}));
}

}  // namespace
}  // namespace fluence::delegate
