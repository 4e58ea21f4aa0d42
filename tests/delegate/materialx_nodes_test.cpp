// MaterialX multiply, mix, constant and tiledimage nodes (delegate/shading_graph.h) between
// Standard Surface inputs and images, from a .mtlx document and as UsdShade Shader prims in
// .usda: the material the render core evaluates at given st, exactly, on 2x2 textures written
// here (texel centres are exact under bilinear filtering); constants folded into the parameters;
// a node Fluence does not evaluate beneath a mix named, its input keeping its own value.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::delegate {
namespace {

// The unit quad of testing::quadBoundTo (st = (x, y)) hit from above at st.
render::MaterialParams materialAt(const render::RenderScene& scene, float s, float t) {
    std::optional<render::SurfaceHit> hit = scene.intersect(render::Ray{{s, t, 1.0f}, {0.0f, 0.0f, -1.0f}});
    EXPECT_TRUE(hit);
    return hit ? hit->material : render::MaterialParams{};
}

const render::MaterialDesc& onlyMaterial(const testing::Populated& p) {
    EXPECT_EQ(p.result.scene.materials.size(), 1u);
    return p.result.scene.materials.front();
}

bool hasBinding(const render::MaterialDesc& m, render::MaterialInput input) {
    return std::any_of(m.bindings.begin(), m.bindings.end(),
                       [&](const render::InputBinding& b) { return b.input == input; });
}

class MaterialXNodes : public ::testing::Test {
protected:
    void SetUp() override {
        // Colour: top-left red, top-right green, bottom-left blue, bottom-right white.
        test::writeImage<float>(dir.file("colour.exr"), 2, 2, 3, OIIO::TypeDesc::FLOAT,
                                {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
        // Mask: top-left 0.25, top-right 0.5, bottom-left 0.75, bottom-right 1.
        test::writeImage<float>(dir.file("mask.exr"), 2, 2, 1, OIIO::TypeDesc::FLOAT, {0.25f, 0.5f, 0.75f, 1.0f});
    }
    // The quad, bound to /Looks/M: the material `name` of `document` (written beside the textures).
    testing::Populated quadWithLook(const std::string& document, const std::string& name = "M") {
        std::ofstream(dir.file("look.mtlx")) << document;
        return testing::populate(R"(
def Mesh "Quad"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "vertex")
    rel material:binding = </Looks/)" +
                                 name + R"(>
}
def Scope "Looks" (
    references = @)" + dir.file("look.mtlx") +
                                 R"(@</MaterialX/Materials>
)
{
}
)");
    }
    test::TempDir dir;
};

const char* const kGraphs = R"(<?xml version="1.0"?>
<materialx version="1.38" colorspace="lin_rec709">
  <nodegraph name="NG">
    <image name="colour" type="color3">
      <input name="file" type="filename" value="colour.exr" />
    </image>
    <image name="mask" type="float">
      <input name="file" type="filename" value="mask.exr" />
    </image>
    <multiply name="tinted" type="color3">
      <input name="in1" type="color3" nodename="colour" />
      <input name="in2" type="color3" value="0.5, 0.25, 1" />
    </multiply>
    <mix name="blend" type="color3">
      <input name="fg" type="color3" nodename="tinted" />
      <input name="bg" type="color3" value="0, 0.5, 0" />
      <input name="mix" type="float" nodename="mask" />
    </mix>
    <multiply name="squared" type="float">
      <input name="in1" type="float" nodename="mask" />
      <input name="in2" type="float" nodename="mask" />
    </multiply>
    <mix name="maskedColour" type="color3">
      <input name="fg" type="color3" nodename="colour" />
      <input name="bg" type="color3" value="0.5, 0.5, 0.5" />
      <input name="mix" type="float" nodename="squared" />
    </mix>
    <multiply name="scaled" type="color3">
      <input name="in1" type="color3" nodename="maskedColour" />
      <input name="in2" type="float" value="2" />
    </multiply>
    <tiledimage name="tiles" type="color3">
      <input name="file" type="filename" value="colour.exr" />
      <input name="uvtiling" type="vector2" value="2, 2" />
      <input name="uvoffset" type="vector2" value="0.5, 0" />
    </tiledimage>
    <image name="nearest" type="color3">
      <input name="file" type="filename" value="colour.exr" />
      <input name="filtertype" type="string" value="closest" />
    </image>
    <constant name="low" type="float">
      <input name="value" type="float" value="0.2" />
    </constant>
    <mix name="metal" type="float">
      <input name="fg" type="float" nodename="low" />
      <input name="bg" type="float" value="0.6" />
      <input name="mix" type="float" value="0.25" />
    </mix>
    <output name="base" type="color3" nodename="blend" />
    <output name="rough" type="float" nodename="squared" />
    <output name="sheen" type="color3" nodename="scaled" />
    <output name="coat" type="color3" nodename="tiles" />
    <output name="specular" type="color3" nodename="nearest" />
    <output name="metal" type="float" nodename="metal" />
  </nodegraph>
  <standard_surface name="S" type="surfaceshader">
    <input name="base" type="float" value="1" />
    <input name="base_color" type="color3" nodegraph="NG" output="base" />
    <input name="specular_roughness" type="float" nodegraph="NG" output="rough" />
    <input name="sheen_color" type="color3" nodegraph="NG" output="sheen" />
    <input name="coat_color" type="color3" nodegraph="NG" output="coat" />
    <input name="specular_color" type="color3" nodegraph="NG" output="specular" />
    <input name="metalness" type="float" nodegraph="NG" output="metal" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>
)";

TEST_F(MaterialXNodes, MultiplyMixAndTiledImagesEvaluateExactlyAtTexelCentres) {
    const testing::Populated p = quadWithLook(kGraphs);
    for (const std::string& w : p.warnings) ADD_FAILURE() << w;
    const render::MaterialDesc& m = onlyMaterial(p);
    // mix(0.2, 0.6, 0.25) = 0.6 * 0.75 + 0.2 * 0.25, folded into the parameter.
    EXPECT_FLOAT_EQ(m.metallic, 0.5f);
    EXPECT_FALSE(hasBinding(m, render::MaterialInput::Metallic));

    const render::RenderScene scene(p.result.scene);
    EXPECT_TRUE(scene.warnings().empty());
    struct Texel {
        float s, t;
        RGB colour;
        float mask;
    };
    const Texel texels[] = {{0.25f, 0.75f, RGB(1, 0, 0), 0.25f},
                            {0.75f, 0.75f, RGB(0, 1, 0), 0.5f},
                            {0.25f, 0.25f, RGB(0, 0, 1), 0.75f},
                            {0.75f, 0.25f, RGB(1, 1, 1), 1.0f}};
    for (const Texel& x : texels) {
        SCOPED_TRACE(::testing::Message() << "st " << x.s << ", " << x.t);
        const render::MaterialParams at = materialAt(scene, x.s, x.t);
        // base_color = mix(fg = colour * (0.5, 0.25, 1), bg = (0, 0.5, 0), mix = mask)
        const RGB tinted = x.colour * RGB(0.5f, 0.25f, 1.0f), bg(0.0f, 0.5f, 0.0f);
        EXPECT_EQ(at.diffuse, bg * (1.0f - x.mask) + tinted * x.mask);
        // specular_roughness = mask * mask
        EXPECT_EQ(at.roughness, x.mask * x.mask);
        // sheen_color = mix(colour, 0.5, mask * mask) * 2
        const float m2 = x.mask * x.mask;
        EXPECT_EQ(at.sheenColor, (RGB(0.5f) * (1.0f - m2) + x.colour * m2) * 2.0f);
        EXPECT_FLOAT_EQ(at.metallic, 0.5f);
    }
    // specular_color, nearest texel: st (0.4, 0.25) lies in the bottom-left (blue) texel, between
    // its centre and the white one's.
    EXPECT_EQ(materialAt(scene, 0.4f, 0.25f).specularColor, RGB(0, 0, 1));
    EXPECT_EQ(materialAt(scene, 0.25f, 0.25f).specularColor, RGB(0, 0, 1));
    // coat_color, tiled: st' = (2 s - 0.5, 2 t), repeating. st (0.125, 0.125) -> (-0.25, 0.25):
    // the bottom-right texel; (0.375, 0.375) -> (0.25, 0.75): the top-left one.
    EXPECT_EQ(materialAt(scene, 0.125f, 0.125f).coatColor, RGB(1, 1, 1));
    EXPECT_EQ(materialAt(scene, 0.375f, 0.375f).coatColor, RGB(1, 0, 0));
    EXPECT_EQ(materialAt(scene, 0.875f, 0.625f).coatColor, RGB(0, 0, 1));  // (1.25, 1.25): bottom-left
}

TEST_F(MaterialXNodes, ConstantTimesTextureFoldsIntoTheTexture) {
    const testing::Populated p = quadWithLook(kGraphs);
    const render::MaterialDesc& m = onlyMaterial(p);
    for (const render::InputBinding& b : m.bindings) {
        if (b.input == render::MaterialInput::Diffuse) {
            // mix(colour * constant, constant, mask): the colour's scale holds the constant.
            ASSERT_EQ(b.nodes.size(), 4u);
            ASSERT_EQ(b.sources.size(), 2u);
            EXPECT_FLOAT_EQ(b.sources[0].texture->scale[1], 0.25f);
            EXPECT_EQ(b.nodes.back().op, render::ShadingNode::Op::Mix);
        }
        if (b.input == render::MaterialInput::CoatColor) {
            EXPECT_TRUE(b.nodes.empty()) << "a tiled image is one texture";
            EXPECT_FLOAT_EQ(b.texture->uvTransform.scale[0], 2.0f);
            EXPECT_FLOAT_EQ(b.texture->uvTransform.translation[0], -0.5f);
        }
    }
}

TEST_F(MaterialXNodes, UsdShadeNodesInUsdaEvaluateTheSame) {
    std::ofstream(dir.file("scene.usda"))
        << "#usda 1.0\n"
        << testing::kCamera
        << testing::quadBoundTo(
               R"(
        token outputs:mtlx:surface.connect = </Looks/M/S.outputs:out>
        def Shader "S"
        {
            uniform token info:id = "ND_standard_surface_surfaceshader"
            float inputs:base = 1
            color3f inputs:base_color.connect = </Looks/M/Blend.outputs:out>
            token outputs:out
        }
        def Shader "Colour"
        {
            uniform token info:id = "ND_image_color3"
            asset inputs:file = @colour.exr@
            color3f outputs:out
        }
        def Shader "Mask"
        {
            uniform token info:id = "ND_image_float"
            asset inputs:file = @mask.exr@
            float outputs:out
        }
        def Shader "Product"
        {
            uniform token info:id = "ND_multiply_color3"
            color3f inputs:in1.connect = </Looks/M/Colour.outputs:out>
            color3f inputs:in2.connect = </Looks/M/Colour.outputs:out>
            color3f outputs:out
        }
        def Shader "Blend"
        {
            uniform token info:id = "ND_mix_color3"
            color3f inputs:fg.connect = </Looks/M/Product.outputs:out>
            color3f inputs:bg = (0.25, 0.25, 0.25)
            float inputs:mix.connect = </Looks/M/Mask.outputs:out>
            color3f outputs:out
        }
)",
               R"(    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "vertex")
)");
    std::unique_ptr<usd::Stage> stage = usd::Stage::open(dir.file("scene.usda"));
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    std::vector<std::string> warnings;
    options.warn = [&](const std::string& where, const std::string& what) { warnings.push_back(where + ": " + what); };
    const DelegateResult result = populateScene(*stage, options);
    for (const std::string& w : warnings) ADD_FAILURE() << w;
    const render::RenderScene scene(result.scene);
    // mix(colour * colour, 0.25, mask) at the top-right (green, 0.5) and bottom-left (blue, 0.75) texels.
    EXPECT_EQ(materialAt(scene, 0.75f, 0.75f).diffuse, RGB(0.25f) * 0.5f + RGB(0, 1, 0) * 0.5f);
    EXPECT_EQ(materialAt(scene, 0.25f, 0.25f).diffuse, RGB(0.25f) * 0.25f + RGB(0, 0, 1) * 0.75f);
}

TEST_F(MaterialXNodes, AnUnevaluatedNodeBeneathAMixIsNamedAndTheInputKeepsItsValue) {
    const testing::Populated p = quadWithLook(R"(<?xml version="1.0"?>
<materialx version="1.38">
  <nodegraph name="NG">
    <noise2d name="grain" type="float" />
    <mix name="blend" type="color3">
      <input name="fg" type="color3" value="1, 0, 0" />
      <input name="bg" type="color3" value="0, 0, 1" />
      <input name="mix" type="float" nodename="grain" />
    </mix>
    <output name="base" type="color3" nodename="blend" />
  </nodegraph>
  <standard_surface name="S" type="surfaceshader">
    <input name="base" type="float" value="0.5" />
    <input name="base_color" type="color3" nodegraph="NG" output="base" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>
)");
    const render::MaterialDesc& m = onlyMaterial(p);
    EXPECT_TRUE(m.bindings.empty());
    EXPECT_EQ(m.diffuse, RGB(0.5f)) << "base_color keeps its own value (the fallback, 1), times base";
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("/Looks/M/NG/grain"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("ND_noise2d_float"), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("look.mtlx"), std::string::npos) << p.warnings[0];
}

TEST_F(MaterialXNodes, ConstantMixesFoldIntoTheParameters) {
    const testing::Populated p = quadWithLook(R"(<?xml version="1.0"?>
<materialx version="1.38">
  <mix name="blend" type="color3">
    <input name="fg" type="color3" value="1, 0, 0.5" />
    <input name="bg" type="color3" value="0, 1, 0.5" />
    <input name="mix" type="float" value="0.25" />
  </mix>
  <multiply name="glow" type="color3">
    <input name="in1" type="color3" nodename="blend" />
    <input name="in2" type="float" value="4" />
  </multiply>
  <standard_surface name="S" type="surfaceshader">
    <input name="base" type="float" value="0.5" />
    <input name="base_color" type="color3" nodename="blend" />
    <input name="emission" type="float" value="2" />
    <input name="emission_color" type="color3" nodename="glow" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>
)");
    for (const std::string& w : p.warnings) ADD_FAILURE() << w;
    const render::MaterialDesc& m = onlyMaterial(p);
    EXPECT_TRUE(m.bindings.empty());
    EXPECT_EQ(m.diffuse, RGB(0.25f, 0.75f, 0.5f) * 0.5f) << "times base";
    EXPECT_EQ(m.emission, RGB(0.25f, 0.75f, 0.5f) * 4.0f * 2.0f) << "times emission: a constant is a light";
}

// emission_color from a graph over an image, times emission: textured emission, which rays see
// (and the emitter's triangles sample) at each point.
TEST_F(MaterialXNodes, EmissionColorFromAGraphOverAnImageIsTexturedEmission) {
    const testing::Populated p = quadWithLook(R"(<?xml version="1.0"?>
<materialx version="1.38" colorspace="lin_rec709">
  <nodegraph name="NG">
    <image name="colour" type="color3">
      <input name="file" type="filename" value="colour.exr" />
    </image>
    <multiply name="glow" type="color3">
      <input name="in1" type="color3" nodename="colour" />
      <input name="in2" type="float" value="3" />
    </multiply>
    <output name="glow" type="color3" nodename="glow" />
  </nodegraph>
  <standard_surface name="S" type="surfaceshader">
    <input name="base" type="float" value="0" />
    <input name="emission" type="float" value="2" />
    <input name="emission_color" type="color3" nodegraph="NG" output="glow" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>
)");
    for (const std::string& w : p.warnings) ADD_FAILURE() << w;
    EXPECT_TRUE(hasBinding(onlyMaterial(p), render::MaterialInput::Emission));
    render::RenderScene scene(p.result.scene);
    auto emissionAt = [&](float s, float t) {
        return scene.intersect(render::Ray{{s, t, 1.0f}, {0.0f, 0.0f, -1.0f}})->emission;
    };
    EXPECT_EQ(emissionAt(0.25f, 0.75f), RGB(6, 0, 0)) << "red x 3 x emission";
    EXPECT_EQ(emissionAt(0.75f, 0.25f), RGB(6, 6, 6)) << "white x 3 x emission";
}

}  // namespace
}  // namespace fluence::delegate
