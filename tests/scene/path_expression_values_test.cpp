// Issue #11: SdfPathExpression values (USDA type `pathExpression`, crate type PathExpression,
// stored as the expression's text) read from text and from crate files into String values typed
// "pathExpression", and written back as USDA `pathExpression` values that read back the same.
#include <gtest/gtest.h>

#include <string>

#include "scene/crate_reader.h"
#include "scene/usda_parser.h"
#include "scene/usda_writer.h"
#include "tests/support/crate_writer.h"

namespace fluence::usd {
namespace {

using test::CrateWriter;
namespace T = detail::crate_type;
using ST = detail::CrateSpecType;

void expectExpression(const Value& value, const std::string& text) {
    EXPECT_EQ(value.typeName, "pathExpression");
    EXPECT_EQ(value.kind, ValueKind::String);
    EXPECT_FALSE(value.isArray);
    EXPECT_EQ(value.asString(), text);
}

TEST(PathExpressionValues, TextToValueToText) {
    const std::string usda = R"(#usda 1.0

def "World"
{
    uniform pathExpression collection:lights:membershipExpression = "/World/** - /World/Debug//*"
    pathExpression[] patterns = ["/World/*", "//Light"]
}
)";
    std::unique_ptr<Layer> layer = parseUsdaString(usda, "expressions.usda");
    const PrimSpec* world = layer->primAtPath("/World");
    ASSERT_NE(world, nullptr);
    const AttributeSpec* membership = world->attribute("collection:lights:membershipExpression");
    ASSERT_NE(membership, nullptr);
    EXPECT_TRUE(membership->uniform);
    expectExpression(membership->defaultValue, "/World/** - /World/Debug//*");
    const AttributeSpec* patterns = world->attribute("patterns");
    ASSERT_NE(patterns, nullptr);
    EXPECT_EQ(patterns->defaultValue.typeName, "pathExpression[]");
    EXPECT_EQ(patterns->defaultValue.strings, (std::vector<std::string>{"/World/*", "//Light"}));

    const std::string text = writeUsda(*layer);
    EXPECT_NE(
        text.find("uniform pathExpression collection:lights:membershipExpression = \"/World/** - /World/Debug//*\"\n"),
        std::string::npos)
        << text;
    EXPECT_NE(text.find("pathExpression[] patterns = [\"/World/*\", \"//Light\"]\n"), std::string::npos) << text;
    EXPECT_EQ(writeUsda(*parseUsdaString(text, "written.usda")), text);
}

TEST(PathExpressionValues, CrateToValueToText) {
    CrateWriter w;
    w.spec("/", ST::PseudoRoot, {{"primChildren", w.tokenVector({"World"})}});
    w.spec("/World", ST::Prim,
           {{"specifier", CrateWriter::inlined(T::Specifier, 0)},
            {"properties", w.tokenVector({"collection:membershipExpression", "patterns"})},
            {"customData", w.dictionary({{"filter", w.pathExpression("//Sphere")}})}});
    w.spec("/World.collection:membershipExpression", ST::Attribute,
           {{"typeName", w.tokenValue("pathExpression")}, {"default", w.pathExpression("/World/**")}});
    w.spec("/World.patterns", ST::Attribute,
           {{"typeName", w.tokenValue("pathExpression[]")}, {"default", w.pathExpressionArray({"/A", "/B/*"})}});
    std::unique_ptr<Layer> layer = readCrateBytes(w.finish(), "expressions.usdc");

    const PrimSpec* world = layer->primAtPath("/World");
    ASSERT_NE(world, nullptr);
    const AttributeSpec* membership = world->attribute("collection:membershipExpression");
    ASSERT_NE(membership, nullptr);
    EXPECT_EQ(membership->typeName, "pathExpression");
    expectExpression(membership->defaultValue, "/World/**");
    const AttributeSpec* patterns = world->attribute("patterns");
    ASSERT_NE(patterns, nullptr);
    EXPECT_EQ(patterns->defaultValue.strings, (std::vector<std::string>{"/A", "/B/*"}));
    const MetadataEntry* customData = findMetadata(world->metadata, "customData");
    ASSERT_NE(customData, nullptr);
    const Value* filter = customData->value.find("filter");
    ASSERT_NE(filter, nullptr);
    expectExpression(*filter, "//Sphere");

    // Written as USDA, and read back from that text as the same values.
    const std::string text = writeUsda(*layer);
    EXPECT_NE(text.find("pathExpression collection:membershipExpression = \"/World/**\"\n"), std::string::npos) << text;
    EXPECT_NE(text.find("pathExpression[] patterns = [\"/A\", \"/B/*\"]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("pathExpression filter = \"//Sphere\"\n"), std::string::npos) << text;
    std::unique_ptr<Layer> again = parseUsdaString(text, "expressions.usda");
    expectExpression(again->primAtPath("/World")->attribute("collection:membershipExpression")->defaultValue,
                     "/World/**");
    EXPECT_EQ(writeUsda(*again), text);
}

}  // namespace
}  // namespace fluence::usd
