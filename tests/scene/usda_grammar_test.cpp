// The USDA reader against OpenUSD's own text grammar (v24.08, pxr/usd/sdf: textFileFormat.yy and
// .ll, parserHelpers.h, parserValueContext.cpp, schema.cpp): what Sdf accepts is read with the
// value Sdf gives it, what Sdf refuses is a syntax error at the offending token.
//
// | Form                                              | Sdf       | Rule                                    |
// |---------------------------------------------------|-----------|-----------------------------------------|
// | asset value as a quoted string (scalar, [], time  | accepted  | _GetImpl<SdfAssetPath>: string -> asset |
// |   samples): asset f = "a.png"                     |           |                                         |
// | path value for a typed attribute, dictionary      | accepted  | typed_value: TOK_PATHREF                |
// |   entry or time sample: token x = </M.outputs:o>  |           |   (_ValueSetCurrentToSdfPath, any type) |
// | a list of paths for a typed array: [</a>]         | refused   | typed_value_list_item has no TOK_PATHREF|
// | bool from any number, true/false/yes/no in any    | accepted  | _GetImpl<bool>, Sdf_BoolFromString      |
// |   case, bare or quoted; also active/hidden/...    |           |                                         |
// | bool from other words (on, maybe)                 | refused   | Sdf_BoolFromString parseOk = false      |
// | integer from a finite non-integral number         | accepted, | _GetImpl<int>: GfNumericCast truncates  |
// |   (int i = 1.9)                                   | truncated |                                         |
// | integer from inf / out of range after truncation  | refused   | GfNumericCast fails                     |
// | float from "inf" "-inf" "nan" (quoted) or inf nan | accepted  | _GetImpl<float>::_FromString            |
// | token from a bare word or an asset; string from a | refused   | MakeScalarValueImpl(TfToken/string):    |
// |   number                                          |           |   Get<std::string> is exact             |
// | trailing ',' in tuples and lists, "1." numbers    | accepted  | listsep_opt; lexer's number rule        |
// | legacy type names (PointFloat, Schema, ...)       | accepted  | _MakeFactoryMap aliases                 |
// | unknown type in a dictionary entry                | refused   | _DictionaryInitScalarFactory            |
// | prim type name joined by '.' (def A.B "p")        | accepted  | prim_type_name                          |
// | 'config' variability                              | accepted  | prim_attr_variability (as uniform)      |
// | 'varying' attribute                               | refused   | prim_attr_variability: uniform, config  |
// | 'varying' relationship                            | accepted  | prim_relationship_type                  |
// | custom float x.timeSamples / x.connect            | refused   | prim_attribute_time_samples/_connect    |
// |                                                   |           |   take prim_attribute_full_type only    |
// | property names with '::' (float a::b)             | refused   | namespaced_name has no CXX identifier   |
// | prim name "bora::dora"                            | refused   | prim_stmt_int: IsValidIdentifier        |
// | relative prim path in references/payload          | refused   | IsValidReference / IsValidPayload       |
// | </> as a reference or inherit path; @@</A>        | refused   | _PathSetPrim: IsPrimPath; empty asset   |
// | relative target, connection and inherit paths     | accepted  | made absolute at the prim (MakeAbsolute)|
// | variant selection in a connection or target path  | refused   | _PathSetPrimOrPropertyScenePath,        |
// |                                                   |           |   IsValidRelationshipTargetPath         |
// | time sample of the wrong shape for the type       | refused   | time_sample: typed_value, value factory |
// | rel r.default = </a>; a list, None, a list op or  | accepted; | prim_relationship_default: TOK_PATHREF  |
// |   metadata with it                                | refused   |   only, prim_relationship_type          |
// | malformed paths: <./a>, </a/../b>, </a/>, <a/.b>  | refused   | pathParser.h: Path                      |
// | list op with an empty list of arcs                | refused   | _PrimSet{Reference,Inherit,...}ListItems|
// |   (append references = [])                        |           |                                         |
// | kind on a prim or variant not a quoted string     | refused   | prim_metadata: TOK_KIND '=' TOK_STRING  |
// |   (kind = None)                                   |           |                                         |
// | kind = None on a layer, attribute or relationship | accepted  | no field of those specs: unregistered   |
// | metadata after a list-op relationship statement   | refused   | prim_relationship: only the explicit    |
// |   (add rel r = </a> (doc = "x"))                  |           |   form has relationship_metadata_list   |
// | dictionary-typed attribute with a {...} value     | refused   | no 'dictionary' value factory; a value  |
// |   (dictionary x = {int a = 1})                    |           |   of an unknown type is a typed_value   |
// | dictionary-typed attribute without a value, or    | accepted  | unknown type: value kept as text        |
// |   with a typed_value (dictionary x = 1)           |           |                                         |
// | time sample at inf, -inf (and nan, left out with  | accepted  | time_sample: extended_number (TOK_NUMBER|
// |   a warning: a map cannot order it); other words  | refused   |   or identifier read as double)         |
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "scene/usda_parser.h"
#include "scene/usda_writer.h"
#include "tests/scene/expect_parse_error.h"

namespace fluence::usd {
namespace {

using test::expectParseError;

// A layer holding `statements` in the body of the prim /P, the first statement on line 3 at
// column 5.
std::string inPrim(const std::string& statements) { return "#usda 1.0\ndef \"P\" {\n    " + statements + "\n}\n"; }

class UsdaGrammar : public ::testing::Test {
protected:
    const AttributeSpec& attribute(const std::string& statements, const std::string& name) {
        layer_ = parseUsdaString(inPrim(statements), "test.usda");
        const AttributeSpec* spec = layer_->primAtPath("/P")->attribute(name);
        if (!spec) throw std::runtime_error("no attribute " + name);
        return *spec;
    }
    std::unique_ptr<Layer> layer_;
};

const double kInf = std::numeric_limits<double>::infinity();

TEST_F(UsdaGrammar, AssetValuesMayBeQuotedStrings) {
    const Value& file = attribute("asset inputs:texture:file = \"testImage.png\"", "inputs:texture:file").defaultValue;
    EXPECT_EQ(file.kind, ValueKind::Asset);
    EXPECT_EQ(file.asString(), "testImage.png");
    const Value& list = attribute("asset[] maps = [\"a.png\", @b.png@]", "maps").defaultValue;
    EXPECT_EQ(list.kind, ValueKind::Asset);
    EXPECT_EQ(list.strings, (std::vector<std::string>{"a.png", "b.png"}));
    const AttributeSpec& animated = attribute("asset f.timeSamples = {1: \"x.png\", 2: @y.png@}", "f");
    ASSERT_EQ(animated.timeSamples.size(), 2u);
    EXPECT_EQ(animated.timeSamples[0].second.kind, ValueKind::Asset);
    EXPECT_EQ(animated.timeSamples[0].second.asString(), "x.png");
    EXPECT_EQ(animated.timeSamples[1].second.asString(), "y.png");
}

TEST_F(UsdaGrammar, PathValuesStandForValuesOfAnyType) {
    const Value& out = attribute("token x = </Materials/a.outputs:out>", "x").defaultValue;
    EXPECT_EQ(out.kind, ValueKind::Path);
    EXPECT_EQ(out.typeName, "token");
    EXPECT_EQ(out.asString(), "/Materials/a.outputs:out");
    EXPECT_EQ(attribute("string s = <relative/Path>", "s").defaultValue.asString(), "relative/Path");
    const AttributeSpec& animated = attribute("token t.timeSamples = {1: </A>, 2: \"b\"}", "t");
    EXPECT_EQ(animated.timeSamples[0].second.kind, ValueKind::Path);
    EXPECT_EQ(animated.timeSamples[1].second.kind, ValueKind::Token);
    auto layer = parseUsdaString("#usda 1.0\n(\n    customLayerData = {\n        token o = </M.outputs:x>\n    }\n)\n",
                                 "test.usda");
    const Value* entry = findMetadata(layer->metadata, "customLayerData")->value.find("o");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->kind, ValueKind::Path);
    EXPECT_EQ(entry->asString(), "/M.outputs:x");
    // Written back as the path it was.
    auto reread = parseUsdaString(writeUsda(*parseUsdaString(inPrim("token x = </M.outputs:o>"), "a.usda")), "b.usda");
    const Value& again = reread->primAtPath("/P")->attribute("x")->defaultValue;
    EXPECT_EQ(again.kind, ValueKind::Path);
    EXPECT_EQ(again.asString(), "/M.outputs:o");
    // A list of paths is no typed value.
    expectParseError(inPrim("token[] t = [</a>]"), 3, 18, "expected a quoted string for 'token[]', found path </a>");
}

TEST_F(UsdaGrammar, BoolsTakeAnyNumberAndSdfsWords) {
    EXPECT_EQ(attribute("bool b = 2", "b").defaultValue.numbers, (std::vector<double>{1}));
    EXPECT_EQ(attribute("bool b = 0.0", "b").defaultValue.numbers, (std::vector<double>{0}));
    EXPECT_EQ(attribute("bool[] b = [yes, No, TRUE, \"false\", \"1\", -0.5]", "b").defaultValue.numbers,
              (std::vector<double>{1, 0, 1, 0, 1, 1}));
    auto layer =
        parseUsdaString("#usda 1.0\ndef \"A\" (\n    active = no\n    instanceable = 1\n)\n{\n}\n", "test.usda");
    const PrimSpec* prim = layer->primAtPath("/A");
    EXPECT_EQ(findMetadata(prim->metadata, "active")->value.asDouble(), 0.0);
    EXPECT_EQ(findMetadata(prim->metadata, "instanceable")->value.asDouble(), 1.0);
    expectParseError(inPrim("bool b = on"), 3, 14,
                     "expected a bool (a number, true, false, yes or no) for 'bool', found 'on'");
    expectParseError(inPrim("bool b = \"maybe\""), 3, 14, "for 'bool', found string \"maybe\"");
    expectParseError("#usda 1.0\ndef \"A\" (\n    active = None\n)\n{\n}\n", 3, 14,
                     "expected a bool (a number, true, false, yes or no) for 'active', found 'None'");
}

TEST_F(UsdaGrammar, IntegersTakeFiniteNumbersTruncatedTowardZero) {
    EXPECT_EQ(attribute("int i = 1.9", "i").defaultValue.numbers, (std::vector<double>{1}));
    EXPECT_EQ(attribute("int[] i = [-2.7, 1e3, 3]", "i").defaultValue.numbers, (std::vector<double>{-2, 1000, 3}));
    EXPECT_EQ(attribute("int3 v = (1.5, 2, 3)", "v").defaultValue.numbers, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(attribute("uchar c = 255.9", "c").defaultValue.numbers, (std::vector<double>{255}));
    expectParseError(inPrim("uchar c = 256.0"), 3, 15, "value 256.0 is out of range for 'uchar'");
    expectParseError(inPrim("int i = -inf"), 3, 13, "expected an integer for 'int', found number -inf");
    expectParseError(inPrim("int i = nan"), 3, 13, "expected an integer for 'int', found 'nan'");
}

TEST_F(UsdaGrammar, FloatsTakeInfAndNanBareOrQuoted) {
    const Value& values = attribute("float[] f = [\"inf\", \"-inf\", inf, -inf, 1., -.5,]", "f").defaultValue;
    EXPECT_EQ(values.numbers, (std::vector<double>{kInf, -kInf, kInf, -kInf, 1, -0.5}));
    EXPECT_TRUE(std::isnan(*attribute("half h = \"nan\"", "h").defaultValue.asDouble()));
    EXPECT_TRUE(std::isnan(*attribute("double d = nan", "d").defaultValue.asDouble()));
    expectParseError(inPrim("float f = \"1.5\""), 3, 15, "expected a number for 'float', found string \"1.5\"");
}

TEST_F(UsdaGrammar, StringsAndTokensAreQuoted) {
    expectParseError(inPrim("token t = foo"), 3, 15, "expected a quoted string for 'token', found 'foo'");
    expectParseError(inPrim("token t = @a.png@"), 3, 15, "found asset path @a.png@");
    expectParseError(inPrim("string s = 1"), 3, 16, "expected a quoted string for 'string', found number 1");
}

TEST_F(UsdaGrammar, TrailingCommasAndLegacyTypeNames) {
    EXPECT_EQ(attribute("float3 v = (1, 2, 3,)", "v").defaultValue.numbers, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(attribute("PointFloat p = (1, 2, 3)", "p").defaultValue.numbers, (std::vector<double>{1, 2, 3}));
    const Value& schema = attribute("Schema s = \"UsdGeomMesh\"", "s").defaultValue;
    EXPECT_EQ(schema.kind, ValueKind::Token);
    EXPECT_EQ(schema.asString(), "UsdGeomMesh");
}

TEST_F(UsdaGrammar, DictionaryEntriesNeedAKnownType) {
    expectParseError("#usda 1.0\n(\n    customLayerData = {\n        madeUp x = 1\n    }\n)\n", 4, 9,
                     "unknown value type 'madeUp' in a dictionary entry");
}

TEST_F(UsdaGrammar, PrimTypeNamesMayBeQualifiedWithDots) {
    auto layer = parseUsdaString("#usda 1.0\ndef Some.Python.Type \"A\" {\n}\n", "test.usda");
    EXPECT_EQ(layer->primAtPath("/A")->typeName, "Some.Python.Type");
}

TEST_F(UsdaGrammar, VariabilityKeywords) {
    EXPECT_TRUE(attribute("config float x = 1", "x").uniform);
    EXPECT_TRUE(attribute("custom uniform token t = \"a\"", "t").uniform);
    auto layer = parseUsdaString(inPrim("custom varying rel r = </A>"), "test.usda");
    EXPECT_TRUE(layer->primAtPath("/P")->relationship("r")->custom);
    expectParseError(inPrim("varying float x = 1"), 3, 5, "attributes cannot be declared 'varying'");
    expectParseError(inPrim("custom varying float x = 1"), 3, 12, "attributes cannot be declared 'varying'");
}

TEST_F(UsdaGrammar, CustomOnlyDeclaresAnAttributeWithoutAField) {
    expectParseError(inPrim("custom float x.timeSamples = {1: 2}"), 3, 5,
                     "'custom' cannot be used with 'x.timeSamples'");
    expectParseError(inPrim("custom float x.connect = </A.y>"), 3, 5, "'custom' cannot be used with 'x.connect'");
    expectParseError(inPrim("prepend custom float x.connect = </A.y>"), 3, 13,
                     "'custom' cannot be used with 'x.connect'");
    // The declaration and the samples in two statements are fine, and are written back so.
    const AttributeSpec& x = attribute("custom float x\n    float x.timeSamples = {1: 2}", "x");
    EXPECT_TRUE(x.custom);
    EXPECT_EQ(x.timeSamples.size(), 1u);
    std::string text = writeUsda(*layer_);
    EXPECT_NE(text.find("custom float x\n"), std::string::npos) << text;
    EXPECT_EQ(text.find("custom float x.timeSamples"), std::string::npos) << text;
    auto rereadLayer = parseUsdaString(text, "b.usda");
    const AttributeSpec* reread = rereadLayer->primAtPath("/P")->attribute("x");
    ASSERT_NE(reread, nullptr);
    EXPECT_TRUE(reread->custom);
    EXPECT_EQ(reread->timeSamples.size(), 1u);
}

TEST_F(UsdaGrammar, PropertyNamesJoinNamespacesWithOneColon) {
    EXPECT_EQ(attribute("float a:b:c = 1", "a:b:c").defaultValue.asDouble(), 1.0);
    expectParseError(inPrim("float a::b = 1"), 3, 11, "invalid attribute name 'a::b'");
    expectParseError(inPrim("rel a::b"), 3, 9, "invalid relationship name 'a::b'");
    expectParseError("#usda 1.0\ndef \"bora::dora\" {\n}\n", 2, 5, "invalid prim name \"bora::dora\"");
}

TEST_F(UsdaGrammar, ReferencePathsAreAbsolutePrimPaths) {
    auto arcs = [](const std::string& arc) { return "#usda 1.0\ndef \"A\" (\n    " + arc + "\n)\n{\n}\n"; };
    expectParseError(arcs("references = @a.usda@<Foo>"), 3, 26, "<Foo> must be an absolute path");
    expectParseError(arcs("prepend payload = <Foo>"), 3, 23, "<Foo> must be an absolute path");
    expectParseError(arcs("references = </>"), 3, 18, "</> is not a prim path");
    expectParseError(arcs("inherits = </>"), 3, 16, "</> is not a prim path");
    expectParseError(arcs("references = @@</B>"), 3, 18, "empty asset path in a reference");
    // Relative inherits and relationship targets are anchored at the prim.
    auto layer = parseUsdaString(arcs("inherits = <../B>"), "test.usda");
    EXPECT_EQ(findMetadata(layer->primAtPath("/A")->metadata, "inherits")->value.asString(), "../B");
    EXPECT_EQ(parseUsdaString(arcs("references = <>"), "test.usda")->primAtPath("/A")->metadata.size(), 1u);
}

TEST_F(UsdaGrammar, ConnectionsAndTargetsHoldNoVariantSelection) {
    expectParseError(inPrim("float inputs:x.connect = </A{v=red}B.outputs:o>"), 3, 30,
                     "variant selections are not allowed in path");
    expectParseError(inPrim("rel r = </A{v=red}B>"), 3, 13, "variant selections are not allowed in path");
}

TEST_F(UsdaGrammar, PathsFollowSdfPathSyntax) {
    expectParseError(inPrim("rel r = <./dora>"), 3, 13, "<./dora> is not a valid path");
    expectParseError(inPrim("rel r = </dora/../muda>"), 3, 13, "</dora/../muda> is not a valid path");
    expectParseError(inPrim("rel r = <../dora/../muda>"), 3, 13, "is not a valid path");
    expectParseError(inPrim("rel r = </a/>"), 3, 13, "</a/> is not a valid path");
    expectParseError(inPrim("rel r = <a/.b>"), 3, 13, "<a/.b> is not a valid path");
    expectParseError(inPrim("rel r = </a.b.c>"), 3, 13, "</a.b.c> is not a valid path");
    expectParseError(inPrim("float x.connect = </a{v=x}/b.c>"), 3, 23, "is not a valid path");
    auto layer = parseUsdaString(inPrim("rel r = [<.>, <../A.b:c>, <B/C>, <.d>, </>]"), "test.usda");
    EXPECT_EQ(layer->primAtPath("/P")->relationship("r")->targets,
              (std::vector<std::string>{".", "../A.b:c", "B/C", ".d", "/"}));
    // Well-formed variant selections, refused for another reason (see
    // ConnectionsAndTargetsHoldNoVariantSelection).
    expectParseError(inPrim("rel r = </A{v=.y|z-w}B{w=}.c>"), 3, 13, "variant selections are not allowed");
}

TEST_F(UsdaGrammar, ListOpsNeedArcsToEdit) {
    auto arcs = [](const std::string& arc) { return "#usda 1.0\ndef \"A\" (\n    " + arc + "\n)\n{\n}\n"; };
    expectParseError(arcs("append references = []"), 3, 25, "an empty list cannot be used with 'append references'");
    expectParseError(arcs("prepend inherits = []"), 3, 24, "an empty list cannot be used with 'prepend inherits'");
    EXPECT_EQ(
        findMetadata(parseUsdaString(arcs("references = []"), "test.usda")->primAtPath("/A")->metadata, "references")
            ->value.size(),
        0u);
}

TEST_F(UsdaGrammar, RelationshipDefaultIsOnePath) {
    auto layer = parseUsdaString(inPrim("varying rel r.default = </A>"), "test.usda");
    EXPECT_EQ(layer->primAtPath("/P")->relationship("r")->targets, (std::vector<std::string>{"/A"}));
    expectParseError(inPrim("rel r.default = [</A>]"), 3, 21, "expected a path <...> for 'r.default', found '['");
    expectParseError(inPrim("rel r.default = None"), 3, 21, "found 'None'");
    expectParseError(inPrim("add rel r.default = </A>"), 3, 5, "'add' cannot be used with 'r.default'");
    expectParseError(inPrim("rel r.default = </A> (doc = \"x\")"), 3, 26,
                     "expected a line break or ';' after relationship 'r', found '('");
}

TEST_F(UsdaGrammar, TimeSamplesHoldValuesOfTheDeclaredShape) {
    expectParseError(inPrim("float3 x.timeSamples = {1: 5}"), 3, 32,
                     "expected a tuple of 3 numbers for 'float3', found number 5");
    expectParseError(inPrim("float x.timeSamples = {1: (1, 2)}"), 3, 31, "expected a number for 'float', found '('");
    expectParseError(inPrim("float[] x.timeSamples = {1: 1}"), 3, 33,
                     "expected '[' to start a 'float[]' array, found number 1");
    expectParseError(inPrim("int x.timeSamples = {1: \"a\"}"), 3, 29, "expected an integer for 'int'");
}

TEST_F(UsdaGrammar, KindIsAQuotedStringOnlyOnPrims) {
    auto prim = [](const std::string& metadata) { return "#usda 1.0\ndef \"A\" (\n    " + metadata + "\n)\n{\n}\n"; };
    expectParseError(prim("kind = None"), 3, 12, "expected a quoted string for 'kind', found 'None'");
    expectParseError(prim("kind = model"), 3, 12, "expected a quoted string for 'kind', found 'model'");
    expectParseError(
        "#usda 1.0\ndef \"A\" {\n    variantSet \"v\" = {\n        \"a\" (kind = None) {\n        }\n    }\n}\n", 4, 21,
        "expected a quoted string for 'kind', found 'None'");
    // Not a field of a layer or a property: any value, kept as it is.
    auto layer = parseUsdaString("#usda 1.0\n(\n    kind = None\n)\n", "test.usda");
    EXPECT_TRUE(findMetadata(layer->metadata, "kind")->value.isBlocked());
    EXPECT_TRUE(findMetadata(attribute("float x = 1 (kind = None)", "x").metadata, "kind")->value.isBlocked());
    auto rel = parseUsdaString(inPrim("rel r (kind = 3)"), "test.usda");
    EXPECT_EQ(findMetadata(rel->primAtPath("/P")->relationship("r")->metadata, "kind")->value.asDouble(), 3.0);
}

TEST_F(UsdaGrammar, ListEditedRelationshipsTakeNoMetadata) {
    expectParseError(inPrim("add rel r = </a> (doc = \"x\")"), 3, 22,
                     "metadata cannot follow 'add' on relationship 'r'");
    expectParseError(inPrim("prepend custom rel r = [</a>, </b>] (\n    )"), 3, 41,
                     "metadata cannot follow 'prepend' on relationship 'r'");
    expectParseError(inPrim("delete rel r = </a> ()"), 3, 25, "metadata cannot follow 'delete'");
    // Metadata and list-edited targets in two statements; written back so.
    auto layer = parseUsdaString(inPrim("append rel r = </a>\n    rel r (doc = \"x\")"), "test.usda");
    const std::string text = writeUsda(*layer);
    EXPECT_NE(text.find("append rel r = </a>\n"), std::string::npos) << text;
    auto reread = parseUsdaString(text, "b.usda");
    const RelationshipSpec* r = reread->primAtPath("/P")->relationship("r");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->op, ListOpKind::Append);
    EXPECT_EQ(r->targets, (std::vector<std::string>{"/a"}));
    EXPECT_EQ(findMetadata(r->metadata, "doc")->value.asString(), "x");
}

TEST_F(UsdaGrammar, DictionaryIsNoAttributeValueType) {
    expectParseError(inPrim("dictionary x = {int a = 1}"), 3, 20,
                     "a value of type 'dictionary' cannot be a dictionary {...}");
    expectParseError(inPrim("madeUp x = {int a = 1}"), 3, 16, "a value of type 'madeUp' cannot be a dictionary");
    // An attribute of an unknown type, 'dictionary' included, keeps a typed_value untyped.
    EXPECT_FALSE(attribute("dictionary x", "x").hasDefault);
    EXPECT_EQ(attribute("dictionary x = 1", "x").defaultValue.asDouble(), 1.0);
    // In a dictionary, 'dictionary' introduces a nested one, and nothing else.
    auto layer = parseUsdaString(
        "#usda 1.0\n(\n    customLayerData = {\n        dictionary d = {\n            int a = 1\n        }\n    }\n)\n",
        "test.usda");
    const Value* nested = findMetadata(layer->metadata, "customLayerData")->value.find("d");
    ASSERT_NE(nested, nullptr);
    EXPECT_EQ(nested->kind, ValueKind::Dictionary);
    expectParseError("#usda 1.0\n(\n    customData = {\n        dictionary d = None\n    }\n)\n", 4, 24,
                     "expected '{' to start a dictionary, found 'None'");
}

TEST_F(UsdaGrammar, TimeSampleTimesMayBeInfinite) {
    const AttributeSpec& x = attribute("float x.timeSamples = {inf: 2, -inf: 1, 4: inf, 5: nan}", "x");
    ASSERT_EQ(x.timeSamples.size(), 4u);
    EXPECT_EQ(x.timeSamples[0].first, -kInf);
    EXPECT_EQ(x.timeSamples[3].first, kInf);
    EXPECT_EQ(x.timeSamples[3].second.asDouble(), 2.0);
    EXPECT_EQ(x.timeSamples[1].second.asDouble(), kInf);
    EXPECT_TRUE(std::isnan(*x.timeSamples[2].second.asDouble()));
    // Written and read back the same.
    auto reread = parseUsdaString(writeUsda(*layer_), "b.usda");
    EXPECT_EQ(reread->primAtPath("/P")->attribute("x")->timeSamples.size(), 4u);
    // A sample at nan: read, warned about at its time, left out.
    const AttributeSpec& y = attribute("float y.timeSamples = {1: 1, nan: 2}", "y");
    ASSERT_EQ(y.timeSamples.size(), 1u);
    ASSERT_EQ(layer_->warnings.size(), 1u);
    EXPECT_EQ(layer_->warnings[0].location.column, 34);
    expectParseError(inPrim("float x.timeSamples = {foo: 1}"), 3, 28,
                     "expected a time code (a number, inf or nan) in time samples, found 'foo'");
    expectParseError(inPrim("rel r.timeSamples = {Inf: </A>}"), 3, 26, "found 'Inf'");
}

}  // namespace
}  // namespace fluence::usd
