// UsdLux MeshLightAPI (delegate/mesh_light.h, docs/USDLUX.md): a mesh that is an area light, from
// USDA through the delegate to the render core's triangle lights and surface hits. A quad mesh
// light must light a point as the RectLight of the same size, intensity and normalize does (the
// RectLight's on-axis formula, the one UsdLuxConformance.RectIntensityExposureColorAndNormalize
// checks the RectLight against), be seen with the RectLight's radiance from its front and not from
// its back, and follow light:materialSyncMode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/random.h"
#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/statistics.h"

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

TEST(UsdLuxMeshLight, WhatStaysUnreadIsNamedInAWarning) {
    auto populated = populate("#usda 1.0\n" + testing::kCamera +
                              quadMeshLight(kLit + "\n    float inputs:shaping:cone:angle = 30\n"
                                                   "    uniform token light:materialSyncMode = \"glowing\"",
                                            "(1, 1, 1)", "\"MeshLightAPI\", \"ShapingAPI\""));
    ASSERT_EQ(populated.warnings.size(), 2u);
    EXPECT_NE(populated.warnings[0].find("light:materialSyncMode 'glowing'"), std::string::npos)
        << populated.warnings[0];
    EXPECT_NE(populated.warnings[1].find("shaping inputs (ShapingAPI) are not applied to a mesh light"),
              std::string::npos)
        << populated.warnings[1];
    ASSERT_TRUE(populated.mesh("/L") && populated.mesh("/L")->light);
}

}  // namespace
}  // namespace fluence::delegate
