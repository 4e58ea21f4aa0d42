// usd::Value accessors and printing, and the Layer/PrimSpec lookups.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/layer.h"
#include "scene/usda_parser.h"
#include "scene/value.h"

namespace fluence::usd {
namespace {

TEST(Value, SizesAndScalarAccessors) {
    Value blocked;
    EXPECT_TRUE(blocked.isBlocked());
    EXPECT_EQ(blocked.size(), 0u);
    EXPECT_EQ(blocked.asDouble(), std::nullopt);

    Value points = Value::numeric("point3f[]", {0, 1, 2, 3, 4, 5}, 3, true);
    EXPECT_TRUE(points.isNumeric());
    EXPECT_EQ(points.size(), 2u);
    EXPECT_EQ(points.asDouble(), 0.0);
    EXPECT_EQ(points.asString(), std::nullopt);

    Value tokens = Value::string("token[]", ValueKind::Token, {"a", "b"}, true);
    EXPECT_TRUE(tokens.isStringLike());
    EXPECT_EQ(tokens.size(), 2u);
    EXPECT_EQ(tokens.asString(), "a");
    EXPECT_EQ(tokens.asDouble(), std::nullopt);
    EXPECT_EQ(tokens.find("a"), nullptr);
}

TEST(Value, ToStringIsCloseToUsdaSyntax) {
    EXPECT_EQ(Value().toString(), "None");
    EXPECT_EQ(Value::numeric("double", {2.5}, 1, false).toString(), "2.5");
    EXPECT_EQ(Value::numeric("float3", {1, -2, 0.125}, 3, false).toString(), "(1, -2, 0.125)");
    EXPECT_EQ(Value::numeric("double", {-std::numeric_limits<double>::infinity()}, 1, false).toString(), "-inf");
    EXPECT_EQ(Value::numeric("matrix2d", {1, 0, 0, 1}, 4, false).toString(), "((1, 0), (0, 1))");
    EXPECT_EQ(Value::numeric("int[]", {1, 2, 3}, 1, true).toString(), "[1, 2, 3]");
    EXPECT_EQ(Value::numeric("int[]", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}, 1, true).toString(),
              "[0, 1, 2, 3, 4, 5, 6, 7, ... (10 elements)]");
    EXPECT_EQ(Value::string("string", ValueKind::String, {"say \"hi\"\n"}, false).toString(), "\"say \\\"hi\\\"\\n\"");
    EXPECT_EQ(Value::string("asset", ValueKind::Asset, {"a.png"}, false).toString(), "@a.png@");
    EXPECT_EQ(Value::string("", ValueKind::Path, {"/A", "/B"}, true).toString(), "[</A>, </B>]");
}

TEST(Value, CopiesShareTheirNumbers) {
    Value points = Value::numeric("point3f[]", {0, 1, 2, 3, 4, 5}, 3, true);
    Value copy = points;
    EXPECT_EQ(copy.numbers.data(), points.numbers.data());
    EXPECT_EQ(copy.numbers, points.numbers);
    copy.numbers = std::vector<double>{7, 8, 9};  // a new array; the original keeps its own
    EXPECT_EQ(points.numbers, (std::vector<double>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(copy.numbers, (std::vector<double>{7, 8, 9}));
    const std::vector<double>& asVector = points.numbers;
    EXPECT_EQ(asVector.data(), points.numbers.data());
    double sum = 0;
    for (double x : points.numbers) sum += x;
    EXPECT_EQ(sum, 15.0);
    EXPECT_EQ(points.numbers.front(), 0.0);
    EXPECT_EQ(points.numbers.back(), 5.0);

    NumberArray empty;
    EXPECT_TRUE(empty.empty());
    EXPECT_EQ(empty.data(), nullptr);
    EXPECT_EQ(empty.begin(), empty.end());
    EXPECT_TRUE(empty.vector().empty());
    EXPECT_EQ(NumberArray(std::vector<double>{}).data(), nullptr);  // no storage for nothing
}

TEST(Value, ParsedValuesPrint) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P" (
    references = @a.usda@</A> (offset = 1; scale = 2)
    customData = {
        int n = 1
        string s = "x"
    }
    tuple = (1, "a")
)
{
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    EXPECT_EQ(findMetadata(prim->metadata, "references")->value.toString(), "@a.usda@</A> (offset = 1; scale = 2)");
    EXPECT_EQ(findMetadata(prim->metadata, "customData")->value.toString(), "{ int n = 1, string s = \"x\" }");
    EXPECT_EQ(findMetadata(prim->metadata, "tuple")->value.toString(), "(1, \"a\")");
}

TEST(Layer, LookupsAndLocations) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "A" (
    kind = "group"
    kind = "component"
)
{
    double x = 1
    rel r
    def "B"
    {
    }
}
)",
                                 "lookups.usda");
    const PrimSpec* a = layer->primAtPath("/A");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(findMetadata(a->metadata, "kind")->value.asString(), "component");  // the last one
    EXPECT_EQ(findMetadata(a->metadata, "kind")->location.str(), "lookups.usda:4:5");
    EXPECT_EQ(findMetadata(a->metadata, "missing"), nullptr);
    EXPECT_NE(a->attribute("x"), nullptr);
    EXPECT_EQ(a->attribute("r"), nullptr);
    EXPECT_NE(a->relationship("r"), nullptr);
    EXPECT_EQ(a->relationship("x"), nullptr);
    EXPECT_EQ(a->child("B"), layer->primAtPath("/A/B"));
    EXPECT_EQ(a->child("C"), nullptr);
    EXPECT_EQ(layer->primAtPath("/"), nullptr);
    EXPECT_EQ(layer->primAtPath(""), nullptr);
    EXPECT_EQ(layer->primAtPath("/A/"), nullptr);
    EXPECT_EQ(layer->primAtPath("/A/B/C"), nullptr);
    EXPECT_EQ((SourceLocation{"f.usda", 3, 7}.str()), "f.usda:3:7");
}

}  // namespace
}  // namespace fluence::usd
