// UsdLux MeshLightAPI (delegate/mesh_light.h, docs/USDLUX.md): a mesh that is an area light, from
// USDA through the delegate to the render core's triangle lights and surface hits. A quad mesh
// light must light a point as the RectLight of the same size, intensity and normalize does (the
// RectLight's on-axis formula, the one UsdLuxConformance.RectIntensityExposureColorAndNormalize
// checks the RectLight against), be seen with the RectLight's radiance from its front and not from
// its back, and follow light:materialSyncMode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/random.h"
#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace fluence::delegate {
namespace {

using testing::populate;

// A 2 x 1 quad mesh light in its XY plane, its front (by its winding) along its local -Z, 2 units
// above the origin facing down (local -Z along world -Y), as UsdLuxConformance's RectLight of
// width 2 and height 1; `lines` adds attributes, `schemas` API schemas.
std::string quadMeshLight(const std::string& lines, const std::string& scale = "(1, 1, 1)",
                          const std::string& schemas = "\"MeshLightAPI\"") {
    return "def Mesh \"L\" (\n    prepend apiSchemas = [" + schemas +
           "]\n)\n{\n"
           "    uniform token subdivisionScheme = \"none\"\n"
           "    int[] faceVertexCounts = [4]\n    int[] faceVertexIndices = [0, 1, 2, 3]\n"
           "    point3f[] points = [(-1, -0.5, 0), (-1, 0.5, 0), (1, 0.5, 0), (1, -0.5, 0)]\n" +
           lines +
           "\n    double3 xformOp:translate = (0, 2, 0)\n    float3 xformOp:rotateXYZ = (-90, 0, 0)\n"
           "    float3 xformOp:scale = " +
           scale +
           "\n    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\", "
           "\"xformOp:scale\"]\n}\n";
}

// The RectLight's irradiance on its axis at height h over L (UsdLuxConformance): half-sizes a, b.
double rectOnAxis(double a, double b, double h) {
    double x = a / h, y = b / h;
    return 2.0 * (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                  y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y)));
}

// The irradiance at p (normal n) from every light of the scene, each estimated from `count` of its
// own samples: the sum of the lights' independent means, whose variance is the sum of theirs.
struct Measured {
    RGB mean;
    double error = 0.0;  // the largest channel's standard error
};
Measured irradiance(const render::RenderScene& scene, const Vec3f& p, const Vec3f& n, int count = 100000) {
    double mean[3] = {0, 0, 0}, variance[3] = {0, 0, 0};
    for (std::size_t l = 0; l < scene.lightCount(); ++l) {
        test::MeanEstimate e[3];
        for (int i = 0; i < count; ++i) {
            auto s = scene.light(l).sample(p, SampleStream(7, l, std::uint64_t(i)).next2D());
            for (int c = 0; c < 3; ++c)
                e[c].add(s && s->pdf > 0.0f ? double(s->Li[c]) * std::max(0.0f, dot(n, s->wi)) / s->pdf : 0.0);
        }
        for (int c = 0; c < 3; ++c) {
            mean[c] += e[c].mean();
            variance[c] += e[c].standardError() * e[c].standardError();
        }
    }
    Measured m{RGB(float(mean[0]), float(mean[1]), float(mean[2]))};
    for (double v : variance) m.error = std::max(m.error, std::sqrt(v));
    return m;
}

// Five standard errors: a correct estimate fails with probability below 1e-6 per channel.
void expectIrradiance(const std::string& usda, const Vec3f& p, const Vec3f& n, const RGB& expected) {
    auto populated = populate("#usda 1.0\n" + testing::kCamera + usda);
    render::RenderScene scene(populated.result.scene);
    ASSERT_EQ(scene.lightCount(), 2u) << "a quad is two triangle lights";
    Measured m = irradiance(scene, p, n);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(m.mean[c], expected[c], 5.0 * m.error + 1e-4 * std::abs(expected[c]) + 1e-7)
            << "channel " << c << "\n"
            << usda;
}

const std::string kLit =
    "    float inputs:intensity = 3\n    float inputs:exposure = 1\n    color3f inputs:color = (0.5, 1, 0.25)";
const RGB kL = RGB(0.5f, 1.0f, 0.25f) * 6.0f;  // intensity x 2^exposure x color
const Vec3f kOrigin(0.0f), kUp(0.0f, 1.0f, 0.0f);

TEST(UsdLuxMeshLight, AQuadLightsAPointAsTheRectLightOfItsSizeIntensityAndNormalize) {
    expectIrradiance(quadMeshLight(kLit), kOrigin, kUp, kL * float(rectOnAxis(1.0, 0.5, 2.0)));
    // normalize divides by the world-space area: scaled 2x along X, 4 x 1.
    expectIrradiance(quadMeshLight(kLit + "\n    bool inputs:normalize = 1", "(2, 1, 1)"), kOrigin, kUp,
                     kL / 4.0f * float(rectOnAxis(2.0, 0.5, 2.0)));
    // Nothing behind it (a point above it, facing it).
    expectIrradiance(quadMeshLight(kLit), Vec3f(0, 4, 0), Vec3f(0, -1, 0), RGB(0.0f));
}

TEST(UsdLuxMeshLight, ItIsSeenWithItsRadianceFromItsFrontOnly) {
    for (const char* normalize : {"", "\n    bool inputs:normalize = 1"}) {
        auto populated = populate("#usda 1.0\n" + testing::kCamera + quadMeshLight(kLit + normalize));
        EXPECT_TRUE(populated.warnings.empty()) << populated.warnings.front();
        render::RenderScene scene(populated.result.scene);
        const RGB L = *normalize ? kL / 2.0f : kL;  // normalized: over its area, 2
        auto front = scene.intersect({Vec3f(0.1f, 0, 0.1f), kUp});
        ASSERT_TRUE(front);
        for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(front->emission[c], L[c]);
        auto back = scene.intersect({Vec3f(0.1f, 4, 0.1f), -kUp});
        ASSERT_TRUE(back);
        EXPECT_EQ(back->emission, RGB(0.0f));
        EXPECT_EQ(back->material.diffuse, RGB(0.18f)) << "it reflects as a plain mesh does";
    }
}

// The quad bound to a UsdPreviewSurface whose emissiveColor is `glow`, with materialSyncMode `mode`.
std::string glowingQuad(const std::string& mode, const std::string& glow) {
    return quadMeshLight(kLit + "\n    rel material:binding = </M>" +
                         (mode.empty() ? "" : "\n    uniform token light:materialSyncMode = \"" + mode + "\"")) +
           "def Material \"M\"\n{\n    token outputs:surface.connect = </M/S.outputs:surface>\n"
           "    def Shader \"S\"\n    {\n        uniform token info:id = \"UsdPreviewSurface\"\n"
           "        color3f inputs:diffuseColor = (0.5, 0.5, 0.5)\n        color3f inputs:emissiveColor = " +
           glow + "\n        token outputs:surface\n    }\n}\n";
}

TEST(UsdLuxMeshLight, MaterialSyncModeTintsByTheGlowOrTakesTheMaterialsResponseAway) {
    auto lightOf = [](const std::string& usda) {
        auto populated = populate("#usda 1.0\n" + testing::kCamera + usda);
        const render::MeshDesc* mesh = populated.mesh("/L");
        if (!mesh || !mesh->light) throw std::runtime_error("no mesh light");
        return *mesh->light;
    };
    const RGB glow(0.5f, 0.25f, 1.0f);
    // materialGlowTintsLight, the fallback: the light's radiance times the material's glow.
    for (const std::string mode : {"", "materialGlowTintsLight"}) {
        render::MeshLightDesc tinted = lightOf(glowingQuad(mode, "(0.5, 0.25, 1)"));
        EXPECT_EQ(tinted.radiance, kL * glow) << mode;
        EXPECT_TRUE(tinted.materialResponse);
    }
    // A material that does not glow does not tint.
    EXPECT_EQ(lightOf(glowingQuad("", "(0, 0, 0)")).radiance, kL);
    // independent: the light's radiance alone, the material's response kept.
    render::MeshLightDesc independent = lightOf(glowingQuad("independent", "(0.5, 0.25, 1)"));
    EXPECT_EQ(independent.radiance, kL);
    EXPECT_TRUE(independent.materialResponse);
    // noMaterialResponse: the light's radiance, a black surface.
    auto populated = populate("#usda 1.0\n" + testing::kCamera + glowingQuad("noMaterialResponse", "(0.5, 0.25, 1)"));
    render::RenderScene scene(populated.result.scene);
    auto front = scene.intersect({Vec3f(0.1f, 0, 0.1f), kUp});
    ASSERT_TRUE(front);
    EXPECT_EQ(front->emission, kL);
    EXPECT_EQ(front->material.diffuse, RGB(0.0f));
    EXPECT_EQ(front->material.specular, 0.0f);
    // With the material's response, the hit has its diffuse colour.
    render::RenderScene responding(
        populate("#usda 1.0\n" + testing::kCamera + glowingQuad("independent", "(0.5, 0.25, 1)")).result.scene);
    EXPECT_EQ(responding.intersect({Vec3f(0.1f, 0, 0.1f), kUp})->material.diffuse, RGB(0.5f));
}

TEST(UsdLuxMeshLight, AConeLimitsItsLightToTheCone) {
    // Under the quad's centre every direction to it is within atan(sqrt(1.25) / 2) = 29.2 degrees
    // of its axis: a 30-degree cone keeps all of the RectLight formula's irradiance there.
    const std::string cone = "\n    float inputs:shaping:cone:angle = 30";
    expectIrradiance(quadMeshLight(kLit + cone, "(1, 1, 1)", "\"MeshLightAPI\", \"ShapingAPI\""), kOrigin, kUp,
                     kL * float(rectOnAxis(1.0, 0.5, 2.0)));
    // At (3, 0, 0) every direction to it is 45 to 63 degrees off the axis: exactly nothing arrives,
    expectIrradiance(quadMeshLight(kLit + cone, "(1, 1, 1)", "\"MeshLightAPI\", \"ShapingAPI\""), Vec3f(3, 0, 0), kUp,
                     RGB(0.0f));
    // where the unshaped light does deliver (authored inputs shape it without the schema, too).
    auto unshaped = populate("#usda 1.0\n" + testing::kCamera + quadMeshLight(kLit));
    const Measured lit = irradiance(render::RenderScene(unshaped.result.scene), Vec3f(3, 0, 0), kUp, 20000);
    EXPECT_GT(lit.mean[1], 20.0 * lit.error);
    expectIrradiance(quadMeshLight(kLit + cone), Vec3f(3, 0, 0), kUp, RGB(0.0f));
}

// A ray that meets a shaped mesh light sees the radiance its light samples carry in that direction
// (the BSDF strategy and light sampling must weigh the same emission, or MIS is biased): from under
// the quad's centre, inside the 30-degree cone, and from (3, 0, 0), outside it, where the surface
// must look black.
TEST(UsdLuxMeshLight, ARayThatMeetsAShapedMeshLightSeesWhatItsLightSamplesCarry) {
    auto populated = populate("#usda 1.0\n" + testing::kCamera +
                              quadMeshLight(kLit + "\n    float inputs:shaping:cone:angle = 30", "(1, 1, 1)",
                                            "\"MeshLightAPI\", \"ShapingAPI\""));
    render::RenderScene scene(populated.result.scene);
    int outsideTheCone = 0;
    for (const Vec3f& p : {kOrigin, Vec3f(3, 0, 0)})
        for (std::size_t l = 0; l < scene.lightCount(); ++l)
            for (int i = 0; i < 64; ++i) {
                auto s = scene.light(l).sample(p, SampleStream(11, l, std::uint64_t(i)).next2D());
                ASSERT_TRUE(s && s->pdf > 0.0f);
                auto hit = scene.intersect({p, s->wi});
                ASSERT_TRUE(hit);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(hit->emission[c], s->Li[c], 1e-4f * (1.0f + s->Li[c]));
                if (p.x > 0.0f) {
                    EXPECT_EQ(hit->emission, RGB(0.0f));
                    ++outsideTheCone;
                }
            }
    EXPECT_EQ(outsideTheCone, 128);
}

// A quad mesh light and the RectLight of the same size, place and shaping (cone, softness, focus
// with a tint, an IES profile that varies with azimuth) light points around them alike: each
// triangle shapes its emission about its front normal, which is the RectLight's axis, with the
// profile's azimuth from the same local X and Y. The two estimates are independent: their
// difference has variance sigma_mesh^2 + sigma_rect^2; five of its standard deviations.
TEST(UsdLuxMeshLight, ItsShapingIsTheRectLightsOfTheSameShape) {
    test::TempDir dir;
    std::ofstream(dir.file("spot.ies")) << "IESNA:LM-63-2002\nTILT=NONE\n1 -1 1 3 3 1 2 0 0 0\n1 1 10\n"
                                           "0 45 90\n0 90 180\n10 8 2\n6 4 1\n3 2 0.5\n";
    const std::string shaping =
        "\n    float inputs:shaping:cone:angle = 60\n    float inputs:shaping:cone:softness = 0.3"
        "\n    float inputs:shaping:focus = 2\n    color3f inputs:shaping:focusTint = (0, 0, 1)"
        "\n    asset inputs:shaping:ies:file = @" +
        dir.file("spot.ies") + "@";
    const std::string placement =
        "\n    double3 xformOp:translate = (0, 2, 0)\n    float3 xformOp:rotateXYZ = (-90, 0, 0)\n"
        "    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\"]\n";
    auto mesh = populate("#usda 1.0\n" + testing::kCamera +
                         quadMeshLight(kLit + shaping, "(1, 1, 1)", "\"MeshLightAPI\", \"ShapingAPI\""));
    auto rect = populate(
        "#usda 1.0\n" + testing::kCamera + "def RectLight \"R\" (\n    prepend apiSchemas = [\"ShapingAPI\"]\n)\n{\n" +
        "    float inputs:width = 2\n    float inputs:height = 1\n" + kLit + shaping + placement + "}\n");
    ASSERT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
    ASSERT_TRUE(rect.warnings.empty()) << rect.warnings.front();
    render::RenderScene meshScene(mesh.result.scene), rectScene(rect.result.scene);
    for (const Vec3f& p : {Vec3f(0, 0, 0), Vec3f(1.5f, 0, 0.5f), Vec3f(-1, 0, -1.5f), Vec3f(0.3f, 0, 2)}) {
        const Measured a = irradiance(meshScene, p, kUp), b = irradiance(rectScene, p, kUp);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a.mean[c], b.mean[c], 5.0 * std::hypot(a.error, b.error) + 1e-6)
                << "channel " << c << " at " << p.x << ", " << p.z;
    }
}

// `body` (the quad light /L) in the class /P that two native instances at the same place reference, or as the prototype of
// a point instancer's two instances, the second scaled by `scale` about the instancer's origin.
std::string nativeInstancesOf(const std::string& body) {
    return "class Xform \"P\"\n{\n" + body +
           "}\n"
           "def Xform \"I1\" (\n    instanceable = true\n    references = </P>\n)\n{\n}\n"
           "def Xform \"I2\" (\n    instanceable = true\n    references = </P>\n)\n{\n}\n";
}
std::string pointInstancesOf(const std::string& body, const std::string& scale) {
    return "def PointInstancer \"PI\"\n{\n    rel prototypes = [</PI/P>]\n    int[] protoIndices = [0, 0]\n"
           "    point3f[] positions = [(0, 0, 0), (0, 0, 0)]\n    float3[] scales = [(1, 1, 1), " +
           scale + "]\n    def Xform \"P\"\n    {\n" + body + "    }\n}\n";
}

// `body` (the quad light /L) in the prototype /PI/P/Inner/Q of a point instancer nested in the
// prototype of another: the inner one places Q twice in one place, the outer one its prototype once.
std::string nestedPointInstancesOf(const std::string& body) {
    return "def PointInstancer \"PI\"\n{\n    rel prototypes = [</PI/P>]\n    int[] protoIndices = [0]\n"
           "    point3f[] positions = [(0, 0, 0)]\n    def Xform \"P\"\n    {\n"
           "    def PointInstancer \"Inner\"\n    {\n    rel prototypes = [</PI/P/Inner/Q>]\n"
           "    int[] protoIndices = [0, 0]\n    point3f[] positions = [(0, 0, 0), (0, 0, 0)]\n"
           "    def Xform \"Q\"\n    {\n" +
           body + "    }\n    }\n    }\n}\n";
}

// Each instance of a mesh light is an emitter of its own: two instances in one place light a
// point twice as one does, with twice its power; a normalized one scaled 2x keeps its power and
// spreads it over its placed area (4 x 2 at height 4: L / 8 over rectOnAxis(2, 1, 4)); two
// normalized copies in one place each divide by their own area.
TEST(UsdLuxMeshLight, EachInstanceIsAnEmitterOfItsOwn) {
    auto measure = [](const std::string& usda, const Vec3f& p, const RGB& expected, std::size_t triangles) {
        auto populated = populate("#usda 1.0\n" + testing::kCamera + usda);
        EXPECT_TRUE(populated.warnings.empty()) << populated.warnings.front();
        render::RenderScene scene(populated.result.scene);
        ASSERT_EQ(scene.lightCount(), triangles) << usda;
        Measured m = irradiance(scene, p, kUp);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(m.mean[c], expected[c], 5.0 * m.error + 1e-4 * std::abs(expected[c])) << "channel " << c << "\n"
                                                                                              << usda;
    };
    const RGB one = kL * float(rectOnAxis(1.0, 0.5, 2.0));
    measure(nativeInstancesOf(quadMeshLight(kLit)), kOrigin, one * 2.0f, 4);
    measure(pointInstancesOf(quadMeshLight(kLit), "(1, 1, 1)"), kOrigin, one * 2.0f, 4);
    const std::string normalized = kLit + "\n    bool inputs:normalize = 1";
    measure(pointInstancesOf(quadMeshLight(normalized), "(2, 2, 2)"), kOrigin,
            kL / 2.0f * float(rectOnAxis(1.0, 0.5, 2.0)) + kL / 8.0f * float(rectOnAxis(2.0, 1.0, 4.0)), 4);
    // Two copies that a nested instancer places in one place are two emitters too, each normalized
    // by its own area (2): twice L / 2, not the two as one light of area 4.
    measure(nestedPointInstancesOf(quadMeshLight(normalized)), kOrigin, one, 4);
}

// The quad light over two cubes of UsdGeomCube's fallback size 2 (tops at y = 1): /Near under it
// and /Far off to its side, with /Blocker between /Far's top and the light; `links` adds the
// light's collections.
std::string quadOverCubes(const std::string& links) {
    return quadMeshLight(kLit + links) +
           "def Cube \"Near\"\n{\n    double3 xformOp:translate = (0, 0, 0)\n"
           "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n"
           "def Cube \"Far\"\n{\n    double3 xformOp:translate = (3, 0, 0)\n"
           "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n"
           "def Cube \"Blocker\"\n{\n    double size = 0.3\n    double3 xformOp:translate = (1.5, 1.5, 0)\n"
           "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n";
}

// The render core's lights that are triangles of the mesh light /L.
std::vector<int> quadLightTriangles(const render::RenderScene& scene) {
    std::vector<int> lights;
    for (std::size_t l = 0; l < scene.lightCount(); ++l)
        if (scene.light(l).name() == "/L") lights.push_back(int(l));
    return lights;
}

TEST(UsdLuxMeshLight, ItsLightLinksDecideWhatEveryTriangleLights) {
    for (bool linked : {false, true}) {
        auto populated = populate("#usda 1.0\n" + testing::kCamera +
                                  quadOverCubes(linked ? "\n    rel collection:lightLink:excludes = </Near>" : ""));
        EXPECT_TRUE(populated.warnings.empty()) << populated.warnings.front();
        render::RenderScene scene(populated.result.scene);
        const std::vector<int> triangles = quadLightTriangles(scene);
        ASSERT_EQ(triangles.size(), 2u);
        const auto near = scene.intersect({Vec3f(0.1f, 1.5f, 0.1f), -kUp});
        const auto far = scene.intersect({Vec3f(3.1f, 1.5f, 0.1f), -kUp});
        ASSERT_TRUE(near && far);
        // Every integrator counts a light's emission at a vertex only where lightReaches says it
        // lights the geometry (render/light_links.h; LightLinks.* check the integrators): an
        // excluded mesh gets exactly nothing from any triangle, the rest are lit as before.
        for (int l : triangles) {
            EXPECT_EQ(scene.lightReaches(l, near->linkGroup), !linked) << "triangle " << l;
            EXPECT_TRUE(scene.lightReaches(l, far->linkGroup)) << "triangle " << l;
        }
    }
}

TEST(UsdLuxMeshLight, ItsShadowLinksDecideWhatBlocksItsShadowRays) {
    for (bool linked : {false, true}) {
        auto populated = populate("#usda 1.0\n" + testing::kCamera +
                                  quadOverCubes(linked ? "\n    rel collection:shadowLink:excludes = </Blocker>" : ""));
        render::RenderScene scene(populated.result.scene);
        // From /Far's top towards the light's centre, through /Blocker.
        const Vec3f from(3.0f, 1.0001f, 0.0f), to(0.0f, 2.0f, 0.0f);
        const Vec3f direction = normalize(to - from);
        const float distance = length(to - from) * 0.999f;
        for (int l : quadLightTriangles(scene)) {
            EXPECT_EQ(scene.shadowTest(l, from, direction, distance),
                      linked ? render::ShadowTest::PassedThrough : render::ShadowTest::Blocked)
                << "triangle " << l;
            EXPECT_EQ(scene.lightPassesSurfaces(l), linked);
        }
    }
}

TEST(UsdLuxMeshLight, WhatStaysUnreadIsNamedInAWarning) {
    auto populated = populate(
        "#usda 1.0\n" + testing::kCamera +
        quadMeshLight(kLit + "\n    uniform token light:materialSyncMode = \"glowing\"\n    rel light:filters = </F>"));
    ASSERT_EQ(populated.warnings.size(), 2u);
    EXPECT_NE(populated.warnings[0].find("light:materialSyncMode 'glowing'"), std::string::npos)
        << populated.warnings[0];
    EXPECT_NE(populated.warnings[1].find("light:filters is not read"), std::string::npos) << populated.warnings[1];
    ASSERT_TRUE(populated.mesh("/L") && populated.mesh("/L")->light);
}

}  // namespace
}  // namespace fluence::delegate
