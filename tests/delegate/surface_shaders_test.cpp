// UsdPreviewSurface and MaterialX Standard Surface read into the render core's parameter set.
#include <gtest/gtest.h>

#include <cmath>

#include "delegate/scene_delegate.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

const render::MaterialDesc& theMaterial(const testing::Populated& p) {
    EXPECT_EQ(p.result.scene.materials.size(), 1u);
    return p.result.scene.materials.at(0);
}

TEST(SurfaceShaders, PreviewSurfaceFallbacksAndMetallicWorkflow) {
    auto p = populate(testing::quadBoundTo(R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0.8, 0.1, 0.1)
            float inputs:metallic = 0.75
            float inputs:roughness = 0.3
            float inputs:clearcoat = 1
            float inputs:opacity = 0.4
            float inputs:opacityThreshold = 0.2
            float inputs:ior = 1.33
            color3f inputs:specularColor = (0, 1, 0)
        }
)"));
    const render::MaterialDesc& m = theMaterial(p);
    EXPECT_EQ(m.diffuse, RGB(0.8f, 0.1f, 0.1f));
    EXPECT_FLOAT_EQ(m.metallic, 0.75f);
    EXPECT_FLOAT_EQ(m.roughness, 0.3f);
    EXPECT_FLOAT_EQ(m.coat, 1.0f);
    EXPECT_FLOAT_EQ(m.coatRoughness, 0.01f) << "UsdPreviewSurface's fallback";
    EXPECT_FLOAT_EQ(m.opacity, 0.4f);
    EXPECT_FLOAT_EQ(m.opacityThreshold, 0.2f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FALSE(m.specularWorkflow);
    EXPECT_EQ(m.specularColor, RGB(1.0f)) << "the metallic workflow ignores specularColor";
    EXPECT_TRUE(p.warnings.empty()) << "every input read here renders";
}

TEST(SurfaceShaders, PreviewSurfaceSpecularWorkflow) {
    auto p = populate(testing::quadBoundTo(R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            int inputs:useSpecularWorkflow = 1
            color3f inputs:specularColor = (0.9, 0.6, 0.2)
            float inputs:metallic = 1
        }
)"));
    const render::MaterialDesc& m = theMaterial(p);
    EXPECT_TRUE(m.specularWorkflow);
    EXPECT_EQ(m.specularColor, RGB(0.9f, 0.6f, 0.2f));
    EXPECT_FLOAT_EQ(m.metallic, 0.0f) << "the specular workflow ignores metallic";
    EXPECT_EQ(m.diffuse, RGB(0.18f));
    EXPECT_FLOAT_EQ(m.roughness, 0.5f);
}

// The MaterialX context wins over the universal one, through a NodeGraph output.
const char* kStandardSurface = R"(
        token outputs:mtlx:surface.connect = </Looks/M/mtlx.outputs:out>
        token outputs:surface.connect = </Looks/M/Preview.outputs:surface>
        def Shader "Preview"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0, 0, 1)
        }
        def NodeGraph "mtlx"
        {
            token outputs:out.connect = </Looks/M/mtlx/SS.outputs:out>
            def Shader "SS"
            {
                uniform token info:id = "ND_standard_surface_surfaceshader"
                float inputs:base = 0.5
                color3f inputs:base_color = (1, 0.5, 0.25)
                float inputs:metalness = 0.2
                float inputs:specular_roughness = 0.35
                float inputs:specular_IOR = 1.6
                float inputs:transmission = 0.3
                float inputs:coat = 0.5
                float inputs:emission = 2
                color3f inputs:emission_color = (1, 0.5, 0)
                color3f inputs:opacity = (1, 0.5, 0)
                bool inputs:thin_walled = 1
                float inputs:subsurface = 0.25
                color3f inputs:subsurface_radius = (1, 0.2, 0.1)
                token outputs:out
            }
        }
)";

TEST(SurfaceShaders, StandardSurfaceThroughTheMaterialXContext) {
    auto p = populate(testing::quadBoundTo(kStandardSurface));
    const render::MaterialDesc& m = theMaterial(p);
    EXPECT_EQ(m.diffuse, RGB(0.5f, 0.25f, 0.125f)) << "base * base_color";
    EXPECT_FLOAT_EQ(m.metallic, 0.2f);
    EXPECT_FLOAT_EQ(m.roughness, 0.35f);
    EXPECT_FLOAT_EQ(m.ior, 1.6f);
    EXPECT_FLOAT_EQ(m.transmission, 0.3f);
    EXPECT_FLOAT_EQ(m.coat, 0.5f);
    EXPECT_FLOAT_EQ(m.coatRoughness, 0.1f) << "Standard Surface's fallback";
    EXPECT_EQ(m.emission, RGB(2.0f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(m.opacity, 0.5f);
    EXPECT_TRUE(m.thinWalled);
    EXPECT_FLOAT_EQ(m.subsurface, 0.25f);
    EXPECT_EQ(m.subsurfaceRadius, RGB(1.0f, 0.2f, 0.1f));
    EXPECT_FLOAT_EQ(m.specular, 1.0f);
    EXPECT_FLOAT_EQ(m.sheenRoughness, 0.3f);
    EXPECT_TRUE(p.warnings.empty()) << "every lobe read here renders";
    EXPECT_FALSE(m.interior.has_value()) << "a thin wall has no inside to walk in";
}

TEST(SurfaceShaders, StandardSurfaceTransmissionDepthFillsTheInteriorWithAMedium) {
    auto p = populate(testing::quadBoundTo(R"(
        token outputs:mtlx:surface.connect = </Looks/M/S.outputs:out>
        def Shader "S"
        {
            uniform token info:id = "ND_standard_surface_surfaceshader"
            float inputs:transmission = 1
            color3f inputs:transmission_color = (0.5, 0.25, 1)
            float inputs:transmission_depth = 2
            color3f inputs:transmission_scatter = (0.5, 0, 0.2)
            float inputs:transmission_scatter_anisotropy = 0.3
        }
)"));
    const render::MaterialDesc& m = theMaterial(p);
    ASSERT_TRUE(m.interior.has_value());
    EXPECT_EQ(m.transmissionColor, RGB(1.0f)) << "the colour is the medium's now, not a tint at the surface";
    // sigmaT = -ln(colour) / depth; sigmaS = scatter / depth; sigmaA = sigmaT - sigmaS, and where
    // that is negative (blue: sigmaT 0, sigmaS 0.1) every channel's absorption rises by as much.
    const RGB sigmaT(std::log(2.0f) / 2.0f, std::log(4.0f) / 2.0f, 0.0f), sigmaS(0.25f, 0.0f, 0.1f);
    const RGB sigmaA = sigmaT - sigmaS + RGB(0.1f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(m.interior->sigmaS[c], sigmaS[c], 1e-6f) << c;
        EXPECT_NEAR(m.interior->sigmaA[c], sigmaA[c], 1e-6f) << c;
    }
    EXPECT_FLOAT_EQ(m.interior->g, 0.3f);

    auto thin = populate(testing::quadBoundTo(R"(
        token outputs:mtlx:surface.connect = </Looks/M/S.outputs:out>
        def Shader "S"
        {
            uniform token info:id = "ND_standard_surface_surfaceshader"
            float inputs:transmission = 1
            float inputs:transmission_depth = 2
            bool inputs:thin_walled = 1
        }
)"));
    EXPECT_FALSE(theMaterial(thin).interior.has_value()) << "a thin wall encloses nothing";
}

TEST(SurfaceShaders, SubsurfaceMakesARandomWalkInteriorOrDiffusionByItsType) {
    auto shader = [](const std::string& extra) {
        return populate(testing::quadBoundTo(R"(
        token outputs:mtlx:surface.connect = </Looks/M/S.outputs:out>
        def Shader "S"
        {
            uniform token info:id = "ND_standard_surface_surfaceshader"
            float inputs:subsurface = 1
            color3f inputs:subsurface_color = (0.8, 0.5, 0.2)
            color3f inputs:subsurface_radius = (1, 0.5, 0.25)
            float inputs:subsurface_scale = 0.2
            )" + extra + R"(
        }
)"));
    };
    auto walk = shader("");
    const render::MaterialDesc& m = theMaterial(walk);
    EXPECT_EQ(m.subsurfaceMethod, render::SubsurfaceMethod::RandomWalkGuided) << "the fallback";
    ASSERT_TRUE(m.interior.has_value());
    EXPECT_NEAR(m.interior->sigmaA.y + m.interior->sigmaS.y, 1.0f / (0.5f * 0.2f), 1e-3f) << "1 / (radius x scale)";
    EXPECT_TRUE(walk.warnings.empty());

    auto diffusion = shader(R"(uniform token inputs:subsurface_type = "diffusion")");
    EXPECT_EQ(theMaterial(diffusion).subsurfaceMethod, render::SubsurfaceMethod::Diffusion);
    auto guided = shader(R"(uniform token inputs:subsurface_type = "randomwalk_guided")");
    EXPECT_EQ(theMaterial(guided).subsurfaceMethod, render::SubsurfaceMethod::RandomWalkGuided);
    EXPECT_TRUE(guided.warnings.empty());
    for (const char* classic : {"randomwalk", "randomwalk_v2"}) {
        auto walked = shader(std::string(R"(uniform token inputs:subsurface_type = ")") + classic + "\"");
        EXPECT_EQ(theMaterial(walked).subsurfaceMethod, render::SubsurfaceMethod::RandomWalk) << classic;
        EXPECT_TRUE(walked.warnings.empty()) << classic;
    }
    auto unknown = shader(R"(uniform token inputs:subsurface_type = "dipole")");
    EXPECT_EQ(theMaterial(unknown).subsurfaceMethod, render::SubsurfaceMethod::RandomWalkGuided);
    ASSERT_EQ(unknown.warnings.size(), 1u);
}

TEST(SurfaceShaders, UnsupportedShadersFallBackToTheUniversalOutputThenWarn) {
    auto p = populate(testing::quadBoundTo(R"(
        token outputs:mtlx:surface.connect = </Looks/M/Odd.outputs:out>
        token outputs:surface.connect = </Looks/M/Preview.outputs:surface>
        def Shader "Odd"
        {
            uniform token info:id = "ND_gltf_pbr_surfaceshader"
        }
        def Shader "Preview"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0, 0, 1)
        }
)"));
    EXPECT_EQ(theMaterial(p).diffuse, RGB(0.0f, 0.0f, 1.0f));
    auto q = populate(testing::quadBoundTo(R"(
        token outputs:surface.connect = </Looks/M/Odd.outputs:out>
        def Shader "Odd"
        {
            uniform token info:id = "ND_gltf_pbr_surfaceshader"
        }
)"));
    EXPECT_EQ(theMaterial(q).diffuse, RGB(0.18f));
    ASSERT_EQ(q.warnings.size(), 1u);
    EXPECT_NE(q.warnings[0].find("'ND_gltf_pbr_surfaceshader') is not supported"), std::string::npos) << q.warnings[0];
}

}  // namespace
}  // namespace fluence::delegate
