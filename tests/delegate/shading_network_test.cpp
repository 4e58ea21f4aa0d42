// Shading networks behind UsdPreviewSurface / Standard Surface inputs read into bindings, and the
// primvars meshes hand the render core for them.
#include <gtest/gtest.h>

#include <algorithm>

#include "delegate/scene_delegate.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

// The quad of testing::quadBoundTo with a faceVarying st (and a primvar nothing reads) bound to
// /Looks/M, whose network is `material`; `mesh` adds to the mesh.
std::string quadWith(const std::string& material, const std::string& mesh = "") {
    return testing::quadBoundTo(
        material, R"(    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "faceVarying")
    float[] primvars:unused = [1, 2, 3, 4] (interpolation = "vertex")
)" + mesh);
}

const std::string kTexturedPreview = R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        token inputs:frame:stPrimvarName = "st"
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = </Looks/M/Tex.outputs:rgb>
            float inputs:roughness.connect = </Looks/M/Arm.outputs:g>
            float inputs:metallic.connect = </Looks/M/Arm.outputs:b>
            normal3f inputs:normal.connect = </Looks/M/Normal.outputs:rgb>
            float inputs:opacity.connect = </Looks/M/Tex.outputs:a>
            float inputs:opacityThreshold = 0.5
        }
        def Shader "Reader"
        {
            uniform token info:id = "UsdPrimvarReader_float2"
            token inputs:varname.connect = </Looks/M.inputs:frame:stPrimvarName>
            float2 inputs:fallback = (0.5, 0.25)
            float2 outputs:result
        }
        def Shader "Place"
        {
            uniform token info:id = "UsdTransform2d"
            float2 inputs:in.connect = </Looks/M/Reader.outputs:result>
            float inputs:rotation = 90
            float2 inputs:scale = (2, 3)
            float2 inputs:translation = (0.1, 0.2)
            float2 outputs:result
        }
        def Shader "Tex"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @textures/albedo.<UDIM>.png@
            float2 inputs:st.connect = </Looks/M/Place.outputs:result>
            token inputs:wrapS = "clamp"
            token inputs:wrapT = "mirror"
            float4 inputs:fallback = (1, 0, 1, 1)
            token inputs:sourceColorSpace = "sRGB"
            float3 outputs:rgb
            float outputs:a
        }
        def Shader "Arm"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @textures/arm.png@
            float2 inputs:st.connect = </Looks/M/Reader.outputs:result>
            token inputs:sourceColorSpace = "raw"
            float outputs:g
            float outputs:b
        }
        def Shader "Normal"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @textures/normal.png@
            float4 inputs:scale = (2, 2, 2, 1)
            float4 inputs:bias = (-1, -1, -1, 0)
            token inputs:sourceColorSpace = "raw"
            float3 outputs:rgb
        }
)";

const render::InputBinding* bindingFor(const render::MaterialDesc& m, render::MaterialInput input) {
    auto it = std::find_if(m.bindings.begin(), m.bindings.end(),
                           [&](const render::InputBinding& b) { return b.input == input; });
    return it == m.bindings.end() ? nullptr : &*it;
}

TEST(ShadingNetwork, UsdUVTextureWithReaderAndTransform) {
    auto p = populate(quadWith(kTexturedPreview));
    const render::MaterialDesc& m = p.result.scene.materials.at(0);
    ASSERT_EQ(m.bindings.size(), 5u);
    const render::InputBinding* diffuse = bindingFor(m, render::MaterialInput::Diffuse);
    ASSERT_TRUE(diffuse && diffuse->texture);
    const render::TextureDesc& t = *diffuse->texture;
    EXPECT_NE(t.file.find("textures/albedo.<UDIM>.png"), std::string::npos) << t.file;
    EXPECT_EQ(diffuse->firstChannel, 0);
    EXPECT_EQ(diffuse->channels, 3);
    EXPECT_EQ(t.wrapS, texture::Wrap::Clamp);
    EXPECT_EQ(t.wrapT, texture::Wrap::Mirror);
    EXPECT_EQ(t.fallback[1], 0.0f);
    EXPECT_EQ(t.fallback[2], 1.0f);
    EXPECT_EQ(t.colorSpace, texture::SourceColorSpace::SRGB);
    EXPECT_EQ(t.uvPrimvar, "st") << "the varname, through the material's interface input";
    EXPECT_EQ(t.uvFallback[0], 0.5f);
    EXPECT_EQ(t.uvTransform.rotationDegrees, 90.0f);
    EXPECT_EQ(t.uvTransform.scale[1], 3.0f);
    EXPECT_EQ(t.uvTransform.translation[0], 0.1f);

    const render::InputBinding* roughness = bindingFor(m, render::MaterialInput::Roughness);
    ASSERT_TRUE(roughness);
    EXPECT_EQ(roughness->firstChannel, 1);
    EXPECT_EQ(roughness->channels, 1);
    EXPECT_EQ(roughness->texture->colorSpace, texture::SourceColorSpace::Raw);
    EXPECT_EQ(roughness->texture->uvTransform.rotationDegrees, 0.0f) << "straight from the reader";
    EXPECT_EQ(bindingFor(m, render::MaterialInput::Metallic)->firstChannel, 2);
    EXPECT_EQ(bindingFor(m, render::MaterialInput::Opacity)->firstChannel, 3);
    const render::InputBinding* normal = bindingFor(m, render::MaterialInput::Normal);
    ASSERT_TRUE(normal);
    EXPECT_EQ(normal->texture->scale[0], 2.0f);
    EXPECT_EQ(normal->texture->bias[2], -1.0f);
    EXPECT_EQ(normal->texture->uvPrimvar, "st") << "an unconnected st reads the primvar st";
    EXPECT_FLOAT_EQ(m.opacityThreshold, 0.5f);

    // Every missing file is named.
    for (const char* file : {"albedo.<UDIM>.png", "arm.png", "normal.png"})
        EXPECT_TRUE(std::any_of(p.warnings.begin(), p.warnings.end(), [&](const std::string& w) {
            return w.find(file) != std::string::npos && w.find("not found") != std::string::npos;
        })) << file;
}

TEST(ShadingNetwork, MeshesCarryTheCornerPrimvarsTheirMaterialReads) {
    auto p = populate(quadWith(kTexturedPreview));
    const render::MeshDesc* quad = p.mesh("/Quad");
    ASSERT_TRUE(quad);
    ASSERT_EQ(quad->primvars.size(), 1u) << "st only: nothing reads 'unused'";
    const render::CornerPrimvar& st = quad->primvars[0];
    EXPECT_EQ(st.name, "st");
    EXPECT_EQ(st.components, 2);
    ASSERT_EQ(st.values.size(), 6u * 2u);
    // Corners follow the triangles' point indices: st equals the point's (x, y) here.
    for (std::size_t c = 0; c < quad->indices.size(); ++c) {
        const Vec3f& p0 = quad->positions[quad->indices[c]];
        EXPECT_EQ(st.values[2 * c], p0.x);
        EXPECT_EQ(st.values[2 * c + 1], p0.y);
    }
}

TEST(ShadingNetwork, SubdivisionSurfacesRefineTheirSt) {
    auto p = populate(quadWith(kTexturedPreview, R"(    uniform token subdivisionScheme = "catmullClark")"));
    ASSERT_FALSE(p.result.scene.meshes.empty());
    const render::MeshDesc& quad = p.result.scene.meshes[0];
    ASSERT_EQ(quad.primvars.size(), 1u);
    const render::CornerPrimvar& st = quad.primvars[0];
    ASSERT_EQ(st.values.size(), quad.indices.size() * 2);
    // A single quad's limit surface is a bilinear-like patch: st stays in [0, 1] and spans it.
    auto [lo, hi] = std::minmax_element(st.values.begin(), st.values.end());
    EXPECT_GE(*lo, 0.0f);
    EXPECT_LE(*hi, 1.0f);
    EXPECT_LT(*lo, 0.01f);
    EXPECT_GT(*hi, 0.99f);
}

TEST(ShadingNetwork, PrimvarReadersFeedInputsDirectly) {
    auto p = populate(quadWith(R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = </Looks/M/Color.outputs:result>
        }
        def Shader "Color"
        {
            uniform token info:id = "UsdPrimvarReader_float3"
            string inputs:varname = "displayColor"
            float3 inputs:fallback = (0.1, 0.2, 0.3)
            float3 outputs:result
        }
)",
                               R"(    color3f[] primvars:displayColor = [(1, 0, 0)] (interpolation = "constant"))"));
    const render::MaterialDesc& m = p.result.scene.materials.at(0);
    ASSERT_EQ(m.bindings.size(), 1u);
    EXPECT_EQ(m.bindings[0].primvar, "displayColor");
    EXPECT_FALSE(m.bindings[0].texture);
    EXPECT_FLOAT_EQ(m.bindings[0].primvarFallback[2], 0.3f);
    const render::MeshDesc* quad = p.mesh("/Quad");
    ASSERT_EQ(quad->primvars.size(), 1u);
    EXPECT_EQ(quad->primvars[0].name, "displayColor");
    EXPECT_EQ(quad->primvars[0].values[0], 1.0f);
}

TEST(ShadingNetwork, UnsupportedNodesWarnAndKeepTheInputsValue) {
    auto p = populate(quadWith(R"(
        token outputs:surface.connect = </Looks/M/S.outputs:surface>
        def Shader "S"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor = (0.2, 0.4, 0.6)
            color3f inputs:diffuseColor.connect = </Looks/M/Noise.outputs:out>
        }
        def Shader "Noise"
        {
            uniform token info:id = "ND_noise2d_color3"
            color3f outputs:out
        }
)"));
    const render::MaterialDesc& m = p.result.scene.materials.at(0);
    EXPECT_TRUE(m.bindings.empty());
    EXPECT_EQ(m.diffuse, RGB(0.2f, 0.4f, 0.6f));
    EXPECT_TRUE(std::any_of(p.warnings.begin(), p.warnings.end(),
                            [](const std::string& w) { return w.find("ND_noise2d_color3") != std::string::npos; }));
}

}  // namespace
}  // namespace fluence::delegate
