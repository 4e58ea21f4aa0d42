// MaterialX documents read as USD layers (scene/mtlx_reader.h): the Open Chess Set's looks as
// usdMtlx lays them out, connections kept inside each material, colour spaces on colour inputs
// only, and clear errors for what is not a MaterialX document.
#include "scene/mtlx_reader.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/usda_parser.h"
#include "tests/support/shared_data.h"

namespace fluence::usd {
namespace {

const std::string kBishop =
    test::sharedPath("usd_corpus/usd-wg-assets/full_assets/OpenChessSet/assets/Bishop/Bishop_mat.mtlx").string();

std::string connectionOf(const PrimSpec& prim, const std::string& attribute) {
    const AttributeSpec* a = prim.attribute(attribute);
    return a && a->connections.size() == 1 ? a->connections.front() : "";
}

std::string tokenOf(const PrimSpec& prim, const std::string& attribute) {
    const AttributeSpec* a = prim.attribute(attribute);
    return a && a->hasDefault ? a->defaultValue.asString().value_or("") : "";
}

std::string colorSpaceOf(const PrimSpec& prim, const std::string& attribute) {
    const AttributeSpec* a = prim.attribute(attribute);
    const MetadataEntry* m = a ? findMetadata(a->metadata, "colorSpace") : nullptr;
    return m ? m->value.asString().value_or("") : "";
}

TEST(MaterialXReader, ReadsTheChessSetsLooksAsUsdMtlxLaysThemOut) {
    FLUENCE_REQUIRE_SHARED(kBishop);
    std::unique_ptr<Layer> layer = readMaterialXFile(kBishop);
    EXPECT_TRUE(layer->warnings.empty());
    const PrimSpec* material = layer->primAtPath("/MaterialX/Materials/M_Bishop_B");
    ASSERT_NE(material, nullptr);
    EXPECT_EQ(material->typeName, "Material");
    EXPECT_EQ(connectionOf(*material, "outputs:mtlx:surface"), "/MaterialX/Materials/M_Bishop_B/Bishop_B.outputs:out");

    const PrimSpec* shader = layer->primAtPath("/MaterialX/Materials/M_Bishop_B/Bishop_B");
    ASSERT_NE(shader, nullptr);
    EXPECT_EQ(shader->typeName, "Shader");
    EXPECT_EQ(tokenOf(*shader, "info:id"), "ND_standard_surface_surfaceshader");
    EXPECT_EQ(connectionOf(*shader, "inputs:base_color"),
              "/MaterialX/Materials/M_Bishop_B/NG_BishopBlack.outputs:base_color_output");
    EXPECT_EQ(shader->attribute("inputs:base_color")->typeName, "color3f");
    EXPECT_EQ(shader->attribute("inputs:normal")->typeName, "vector3f");

    const PrimSpec* graph = layer->primAtPath("/MaterialX/Materials/M_Bishop_B/NG_BishopBlack");
    ASSERT_NE(graph, nullptr);
    EXPECT_EQ(graph->typeName, "NodeGraph");
    EXPECT_EQ(connectionOf(*graph, "outputs:normal_output"),
              "/MaterialX/Materials/M_Bishop_B/NG_BishopBlack/mtlxnormalmap4.outputs:out");

    const PrimSpec* image = graph->child("diffuse2");
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(tokenOf(*image, "info:id"), "ND_image_color3");
    EXPECT_EQ(image->attribute("inputs:file")->typeName, "asset");
    EXPECT_EQ(tokenOf(*image, "inputs:file"), "tex/bishop_black_base_color.jpg");
    EXPECT_EQ(colorSpaceOf(*image, "inputs:file"), "srgb_texture");
    EXPECT_EQ(colorSpaceOf(*graph->child("metallic2"), "inputs:file"), "") << "data images carry no colour space";
    EXPECT_EQ(colorSpaceOf(*graph->child("normal2"), "inputs:file"), "");

    const PrimSpec* normalMap = graph->child("mtlxnormalmap4");
    ASSERT_NE(normalMap, nullptr);
    EXPECT_EQ(tokenOf(*normalMap, "info:id"), "ND_normalmap");
    EXPECT_EQ(connectionOf(*normalMap, "inputs:in"),
              "/MaterialX/Materials/M_Bishop_B/NG_BishopBlack/normal2.outputs:out");

    // The white look has its own copy of its own graph.
    EXPECT_NE(layer->primAtPath("/MaterialX/Materials/M_Bishop_W/NG_BishopWhite/diffuse3"), nullptr);
    EXPECT_EQ(layer->primAtPath("/MaterialX/Materials/M_Bishop_W/NG_BishopBlack"), nullptr);
}

TEST(MaterialXReader, ReadsValuesDocumentLevelNodesAndGraphInterfaces) {
    const std::string text = R"(<?xml version="1.0"?>
<materialx version="1.38" colorspace="lin_rec709">
  <nodegraph name="NG">
    <input name="tint" type="color3" value="0.5, 0.25, 1" />
    <multiply name="mul" type="color3">
      <input name="in1" type="color3" interfacename="tint" />
      <input name="in2" type="color3" value="2, 2, 2" />
    </multiply>
    <output name="out" type="color3" nodename="mul" />
  </nodegraph>
  <constant name="rough" type="float">
    <input name="value" type="float" value="0.25" />
  </constant>
  <standard_surface name="S" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="NG" output="out" />
    <input name="specular_roughness" type="float" nodename="rough" />
    <input name="thin_walled" type="boolean" value="true" />
    <input name="coat_color" type="color3" value="0.9, 0.8, 0.7" colorspace="srgb_texture" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
  <look name="L" />
  <look name="L2" />
</materialx>)";
    std::unique_ptr<Layer> layer = readMaterialX(text, "inline.mtlx");
    const PrimSpec* shader = layer->primAtPath("/MaterialX/Materials/M/S");
    ASSERT_NE(shader, nullptr);
    EXPECT_EQ(connectionOf(*shader, "inputs:specular_roughness"), "/MaterialX/Materials/M/rough.outputs:out");
    ASSERT_NE(layer->primAtPath("/MaterialX/Materials/M/rough"), nullptr);
    EXPECT_EQ(tokenOf(*layer->primAtPath("/MaterialX/Materials/M/rough"), "info:id"), "ND_constant_float");
    EXPECT_EQ(shader->attribute("inputs:thin_walled")->defaultValue.asDouble(), 1.0);
    EXPECT_EQ(colorSpaceOf(*shader, "inputs:coat_color"), "srgb_texture");
    const AttributeSpec* coat = shader->attribute("inputs:coat_color");
    ASSERT_EQ(coat->defaultValue.numbers.size(), 3u);
    EXPECT_EQ(coat->defaultValue.numbers[2], 0.7);

    const PrimSpec* graph = layer->primAtPath("/MaterialX/Materials/M/NG");
    ASSERT_NE(graph, nullptr);
    EXPECT_EQ(graph->attribute("inputs:tint")->defaultValue.numbers[1], 0.25);
    const PrimSpec* mul = graph->child("mul");
    ASSERT_NE(mul, nullptr);
    EXPECT_EQ(tokenOf(*mul, "info:id"), "ND_multiply_color3");
    EXPECT_EQ(connectionOf(*mul, "inputs:in1"), "/MaterialX/Materials/M/NG.inputs:tint");
    EXPECT_EQ(colorSpaceOf(*mul, "inputs:in2"), "lin_rec709") << "the document's colour space";

    ASSERT_EQ(layer->warnings.size(), 1u) << "one warning per element kind not read";
    EXPECT_NE(layer->warnings[0].message.find("<look>"), std::string::npos);
}

TEST(MaterialXReader, RejectsWhatIsNotAMaterialXDocument) {
    EXPECT_THROW(readMaterialX("<materialx><nodegraph></materialx>", "broken.mtlx"), ParseError);
    EXPECT_THROW(readMaterialX("<?xml version=\"1.0\"?><svg/>", "other.mtlx"), ParseError);
    EXPECT_THROW(readMaterialXFile("/nonexistent/none.mtlx"), FileError);
    try {
        readMaterialX("<materialx><nodegraph></materialx>", "broken.mtlx");
    } catch (const ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.mtlx"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fluence::usd
