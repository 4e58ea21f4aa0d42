// MaterialX looks through the delegate (scene/mtlx_reader.h, delegate/shading_network.h): a USD
// layer references a .mtlx document's materials, binds one, and the render core gets a Standard
// Surface whose textured inputs are bindings — base colour from an sRGB image, a tangent-space
// normal map decoded from [0, 1] — while a node Fluence does not evaluate is named in a warning and
// the input keeps its own value. The Open Chess Set's looks, from the shared corpus, do the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "delegate/scene_delegate.h"
#include "scene/stage.h"
#include "tests/support/shared_data.h"

namespace fs = std::filesystem;

namespace fluence::delegate {
namespace {

struct Loaded {
    std::unique_ptr<usd::Stage> stage;
    DelegateResult result;
    std::vector<std::string> warnings;
};

Loaded load(const std::string& path) {
    Loaded l;
    l.stage = usd::Stage::open(path);
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&l](const std::string& where, const std::string& message) {
        l.warnings.push_back(where + ": " + message);
    };
    l.result = populateScene(*l.stage, options);
    return l;
}

const render::MaterialDesc* material(const Loaded& l, const std::string& name) {
    for (const render::MaterialDesc& m : l.result.scene.materials)
        if (m.name == name) return &m;
    return nullptr;
}

const render::InputBinding* binding(const render::MaterialDesc& m, render::MaterialInput input) {
    auto it = std::find_if(m.bindings.begin(), m.bindings.end(),
                           [&](const render::InputBinding& b) { return b.input == input; });
    return it == m.bindings.end() ? nullptr : &*it;
}

class MaterialXLooks : public ::testing::Test {
protected:
    fs::path dir_ = fs::temp_directory_path() / ("fluence_materialx_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(dir_); }
    void TearDown() override { fs::remove_all(dir_); }
};

TEST_F(MaterialXLooks, ImagesAndNormalMapsBecomeBindingsAndUnknownNodesAreNamed) {
    std::ofstream(dir_ / "look.mtlx") << R"(<?xml version="1.0"?>
<materialx version="1.38" colorspace="lin_rec709">
  <nodegraph name="NG">
    <image name="albedo" type="color3">
      <input name="file" type="filename" value="base.png" colorspace="srgb_texture" />
      <input name="uaddressmode" type="string" value="clamp" />
    </image>
    <image name="tint" type="color3">
      <input name="file" type="filename" value="tint.exr" colorspace="acescg" />
    </image>
    <image name="bumps" type="vector3">
      <input name="file" type="filename" value="normal.png" />
    </image>
    <normalmap name="nm" type="vector3">
      <input name="in" type="vector3" nodename="bumps" />
      <input name="scale" type="float" value="0.5" />
    </normalmap>
    <noise3d name="grain" type="float" />
    <output name="base" type="color3" nodename="albedo" />
    <output name="normal" type="vector3" nodename="nm" />
    <output name="rough" type="float" nodename="grain" />
    <output name="coat" type="color3" nodename="tint" />
  </nodegraph>
  <standard_surface name="S" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="NG" output="base" />
    <input name="normal" type="vector3" nodegraph="NG" output="normal" />
    <input name="specular_roughness" type="float" nodegraph="NG" output="rough" />
    <input name="metalness" type="float" value="0.25" />
    <input name="coat_color" type="color3" nodegraph="NG" output="coat" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>
)";
    std::ofstream(dir_ / "scene.usda") << R"(#usda 1.0
def Scope "Looks" (
    references = @./look.mtlx@</MaterialX/Materials>
)
{
}
def Mesh "Quad" (
    prepend apiSchemas = ["MaterialBindingAPI"]
)
{
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)] (interpolation = "vertex")
    rel material:binding = </Looks/M>
}
def Camera "Cam"
{
}
)";
    const Loaded l = load((dir_ / "scene.usda").string());
    const render::MaterialDesc* m = material(l, "/Looks/M");
    ASSERT_NE(m, nullptr);
    EXPECT_FLOAT_EQ(m->metallic, 0.25f);

    const render::InputBinding* base = binding(*m, render::MaterialInput::Diffuse);
    ASSERT_NE(base, nullptr);
    ASSERT_TRUE(base->texture);
    EXPECT_EQ(fs::path(base->texture->file).filename(), "base.png");
    EXPECT_EQ(base->texture->colorSpace, texture::SourceColorSpace::SRGB);
    EXPECT_EQ(base->texture->wrapS, texture::Wrap::Clamp);
    EXPECT_EQ(base->texture->wrapT, texture::Wrap::Repeat);
    EXPECT_EQ(base->channels, 3);

    const render::InputBinding* coat = binding(*m, render::MaterialInput::CoatColor);
    ASSERT_NE(coat, nullptr);
    EXPECT_EQ(coat->texture->colorSpaceName, "acescg") << "converted from the config's acescg when opened";
    EXPECT_EQ(base->texture->colorSpaceName, "") << "srgb_texture is the SRGB conversion";

    const render::InputBinding* normal = binding(*m, render::MaterialInput::Normal);
    ASSERT_NE(normal, nullptr);
    ASSERT_TRUE(normal->texture);
    EXPECT_EQ(normal->texture->colorSpace, texture::SourceColorSpace::Raw);
    EXPECT_FLOAT_EQ(normal->texture->scale[0], 1.0f);  // 2 x 0.5
    EXPECT_FLOAT_EQ(normal->texture->bias[0], -0.5f);
    EXPECT_FLOAT_EQ(normal->texture->scale[2], 2.0f);
    EXPECT_FLOAT_EQ(normal->texture->bias[2], -1.0f);

    EXPECT_EQ(binding(*m, render::MaterialInput::Roughness), nullptr) << "noise3d is not evaluated";
    const bool named = std::any_of(l.warnings.begin(), l.warnings.end(), [](const std::string& w) {
        return w.find("/Looks/M/NG/grain") != std::string::npos && w.find("ND_noise3d_float") != std::string::npos &&
               w.find("look.mtlx") != std::string::npos;
    });
    EXPECT_TRUE(named) << "the unevaluated node is named, with its document";
}

TEST(MaterialXChessSet, TheBishopsLooksReachStandardSurfaceWithTheirTextures) {
    const fs::path bishop =
        test::sharedPath("usd_corpus/usd-wg-assets/full_assets/OpenChessSet/assets/Bishop/Bishop.usd");
    FLUENCE_REQUIRE_SHARED(bishop);
    const Loaded l = load(bishop.string());
    const render::MaterialDesc* m = material(l, "/Bishop/Materials/M_Bishop_B");
    ASSERT_NE(m, nullptr);
    const render::InputBinding* base = binding(*m, render::MaterialInput::Diffuse);
    ASSERT_NE(base, nullptr);
    ASSERT_TRUE(base->texture);
    EXPECT_EQ(fs::path(base->texture->file).filename(), "bishop_black_base_color.jpg");
    EXPECT_TRUE(fs::exists(base->texture->file)) << base->texture->file;
    EXPECT_EQ(base->texture->colorSpace, texture::SourceColorSpace::SRGB);
    for (render::MaterialInput input :
         {render::MaterialInput::Metallic, render::MaterialInput::Roughness, render::MaterialInput::Normal}) {
        const render::InputBinding* b = binding(*m, input);
        ASSERT_NE(b, nullptr) << int(input);
        EXPECT_EQ(b->texture->colorSpace, texture::SourceColorSpace::Raw) << int(input);
    }
    for (const std::string& w : l.warnings) EXPECT_EQ(w.find("Bishop_mat"), std::string::npos) << w;
}

}  // namespace
}  // namespace fluence::delegate
