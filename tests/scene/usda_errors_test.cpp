// The USDA reader's syntax errors: each names the offending token's file:line:column and says
// precisely what was expected.
#include <gtest/gtest.h>

#include <string>

#include "scene/usda_lexer.h"
#include "scene/usda_parser.h"
#include "tests/scene/expect_parse_error.h"

namespace fluence::usd {
namespace {

using test::expectParseError;

TEST(UsdaErrors, BadHeader) {
    expectParseError("", 1, 1, "empty file");
    expectParseError("#usda\n", 1, 1, "expected a '#usda 1.0' header");
    expectParseError("def \"A\" {}\n", 1, 1, "expected a '#usda 1.0' header on the first line");
    expectParseError("#usda 1.0 junk\n", 1, 1, "found \"#usda 1.0 junk\"");
    expectParseError("PXR-USDC\x07\x00\x00", 1, 1,
                     "a binary USD crate file, not USDA text (usd::readLayerFile reads both)");
}

TEST(UsdaErrors, UnterminatedStrings) {
    expectParseError("#usda 1.0\n(\n    doc = \"no end\n)\n", 3, 11, "unterminated string");
    expectParseError("#usda 1.0\n(\n    doc = \"\"\"never\nclosed\n)\n", 3, 11, "unterminated string");
    expectParseError("#usda 1.0\n(\n    \"\\\"\n)\n", 3, 5, "unterminated string");
    expectParseError("#usda 1.0\ndef \"A\" {\n    asset a = @x.png\n}\n", 3, 15, "unterminated asset path");
    expectParseError("#usda 1.0\ndef \"A\" {\n    rel r = </B\n}\n", 3, 13, "unterminated path");
    expectParseError("#usda 1.0\n/* open\n", 2, 1, "unterminated '/*' comment");
}

TEST(UsdaErrors, MissingEquals) {
    expectParseError("#usda 1.0\ndef Sphere \"S\"\n{\n    double radius 2\n}\n", 4, 19,
                     "expected '=' after attribute name 'radius', found number 2");
    expectParseError("#usda 1.0\n(\n    upAxis \"Y\"\n)\n", 3, 12, "expected '=' after metadata key 'upAxis'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    rel r </B>\n}\n", 3, 11, "expected '=' after relationship name 'r'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double a.connect </B.c>\n}\n", 3, 22,
                     "expected '=' after 'a.connect'");
}

TEST(UsdaErrors, MissingCloseAtEndOfFile) {
    expectParseError("#usda 1.0\n\ndef Xform \"World\"\n{\n    def \"Child\"\n    {\n    }\n", 8, 1,
                     "unexpected end of file, expected '}' to close prim \"World\" opened at 3:1");
    expectParseError("#usda 1.0\n(\n    upAxis = \"Y\"\n", 4, 1,
                     "expected ')' to close the metadata of the layer opened at 2:1");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double3 v = (0, 1, 2", 3, 25,
                     "unexpected end of file, expected ')' to close the 'double3' tuple opened at 3:17");
    expectParseError("#usda 1.0\ndef \"A\" {\n    int[] v = [1, 2,\n", 4, 1,
                     "expected ']' to close the 'int[]' array opened at 3:15");
}

TEST(UsdaErrors, WrongTupleArityAndTypes) {
    expectParseError("#usda 1.0\ndef \"A\" {\n    float3 x = (1, 2)\n}\n", 3, 16,
                     "expected 3 components for 'float3', found 2");
    expectParseError("#usda 1.0\ndef \"A\" {\n    float3[] x = [(1, 2, 3), (1, 2, 3, 4)]\n}\n", 3, 30,
                     "expected 3 components for 'float3[]', found 4");
    expectParseError("#usda 1.0\ndef \"A\" {\n    matrix2d m = ((1, 0), (0, 1), (0, 0))\n}\n", 3, 18,
                     "expected 2 rows for 'matrix2d', found 3");
    expectParseError("#usda 1.0\ndef \"A\" {\n    float x = \"1.0\"\n}\n", 3, 15,
                     "expected a number for 'float', found string \"1.0\"");
    expectParseError("#usda 1.0\ndef \"A\" {\n    string s = 1.5\n}\n", 3, 16,
                     "expected a quoted string for 'string', found number 1.5");
    expectParseError("#usda 1.0\ndef \"A\" {\n    int i = \"1\"\n}\n", 3, 13, "expected an integer for 'int'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    uchar c = 256\n}\n", 3, 15, "out of range for 'uchar'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    bool b = off\n}\n", 3, 14,
                     "expected a bool (a number, true, false, yes or no)");
    expectParseError("#usda 1.0\ndef \"A\" {\n    int[] i = 1\n}\n", 3, 15, "expected '[' to start a 'int[]' array");
    expectParseError("#usda 1.0\ndef \"A\" {\n    token t = [\"a\"]\n}\n", 3, 15,
                     "expected a quoted string for 'token'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    opaque o = 1\n}\n", 3, 16, "cannot have a value");
}

TEST(UsdaErrors, BadNumbers) {
    expectParseError("#usda 1.0\ndef \"A\" {\n    float x = 1.2.3\n}\n", 3, 15, "malformed number '1.2.3'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    float x = 12abc\n}\n", 3, 15, "malformed number '12abc'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    float x = 1e\n}\n", 3, 15, "malformed number '1e'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x = 1e999\n}\n", 3, 16, "out of range");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x = - 1\n}\n", 3, 16, "invalid character '-'");
}

TEST(UsdaErrors, UnknownSpecifierPosition) {
    expectParseError("#usda 1.0\nXform def \"World\" {\n}\n", 2, 1,
                     "expected 'def', 'over' or 'class' to start a prim, found 'Xform'");
    expectParseError("#usda 1.0\ndef Xform World {\n}\n", 2, 11,
                     "expected a prim name (a quoted string) after 'def Xform'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    \"oops\"\n}\n", 3, 5,
                     "expected a prim, a property, 'variantSet' or '}'");
    expectParseError("#usda 1.0\ndef \"A\"\n", 3, 1, "expected '{' to open the body of prim \"A\", found end of file");
}

TEST(UsdaErrors, DuplicatePrims) {
    expectParseError("#usda 1.0\ndef \"A\"\n{\n}\ndef \"A\"\n{\n}\n", 5, 5,
                     "duplicate prim \"A\" (already defined at 2:5)");
    expectParseError("#usda 1.0\ndef \"A\"\n{\n    def \"B\" {\n    }\n    over \"B\" {\n    }\n}\n", 6, 10,
                     "duplicate prim \"B\"");
    // Same names in different parents or variants are fine.
    EXPECT_NO_THROW(
        parseUsdaString("#usda 1.0\ndef \"A\" {\n    def \"B\" {\n    }\n}\ndef \"C\" {\n"
                        "    def \"B\" {\n    }\n}\n",
                        "ok.usda"));
}

TEST(UsdaErrors, InvalidCharacters) {
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x = $1\n}\n", 3, 16, "invalid character '$'");
    expectParseError(std::string("#usda 1.0\ndef \"A\" {\n  \x01\n}\n"), 3, 3, "invalid character 0x01");
    expectParseError("#usda 1.0\ndef \"A\" (kind = \"x\" ? ) {\n}\n", 2, 21, "invalid character '?'");
}

TEST(UsdaErrors, StatementSeparation) {
    expectParseError("#usda 1.0\n(\n    upAxis = \"Y\" metersPerUnit = 1\n)\n", 3, 18,
                     "expected a line break or ';' between metadata entries, found 'metersPerUnit'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x = 1 }\n", 3, 18,
                     "expected a line break or ';' after attribute 'x', found '}'");
    expectParseError("#usda 1.0\ndef \"A\" {\n} def \"B\" {\n}\n", 3, 3,
                     "expected a line break or ';' after prim \"A\", found 'def'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x =\n        1\n}\n", 4, 9,
                     "expected a value after '=' on the same line");
}

TEST(UsdaErrors, MetadataShapes) {
    expectParseError("#usda 1.0\ndef \"A\" (kind = component) {\n}\n", 2, 17, "expected a quoted string for 'kind'");
    expectParseError("#usda 1.0\ndef \"A\" (active = maybe) {\n}\n", 2, 19,
                     "expected a bool (a number, true, false, yes or no) for 'active', found 'maybe'");
    expectParseError("#usda 1.0\ndef \"A\" (add reeferences = @x.usda@) {\n}\n", 2, 28,
                     "'add reeferences' needs a list value [...]");
    expectParseError("#usda 1.0\ndef \"A\" (delete inherits = None) {\n}\n", 2, 28,
                     "'None' cannot be used with 'delete'");
    expectParseError("#usda 1.0\ndef \"A\" (references = [@@]) {\n}\n", 2, 24, "empty asset path in a reference");
    expectParseError("#usda 1.0\ndef \"A\" (inherits = </A.prop>) {\n}\n", 2, 21, "</A.prop> is not a prim path");
    expectParseError("#usda 1.0\ndef \"A\" (inherits = <../../B>) {\n}\n", 2, 21, "climbs above the root");
    expectParseError("#usda 1.0\ndef \"A\" (variants = {string v = \"a:b\"}) {\n}\n", 2, 21,
                     "invalid variant selection");
    expectParseError("#usda 1.0\n(\n    customLayerData = 3\n)\n", 3, 23,
                     "expected a dictionary {...} for 'customLayerData'");
    expectParseError("#usda 1.0\n(\n    subLayers = [@a.usda@ (offset = 1; bogus = 2)]\n)\n", 3, 40,
                     "expected 'offset' or 'scale' in a layer offset");
    // OpenUSD's 89_bad_attribute_displayUnit.sdf: a unit name outside Sdf's registry.
    expectParseError("#usda 1.0\ndef \"A\" {\n    double a = 1 (displayUnit = badDisplayUnit)\n}\n", 3, 33,
                     "'badDisplayUnit' is not a valid display unit (one of mm, cm, dm, m, km,");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double a = 1 (displayUnit = \"mm\")\n}\n", 3, 33,
                     "expected a unit name for 'displayUnit', found string \"mm\"");
}

TEST(UsdaErrors, PropertyRules) {
    expectParseError("#usda 1.0\ndef \"A\" {\n    bool a\n    double a = 1\n}\n", 4, 12,
                     "attribute 'a' redeclared with type 'double' (declared 'bool' at 3:5)");
    expectParseError("#usda 1.0\ndef \"A\" {\n    rel r = [</B>, </C>, </B>]\n}\n", 3, 26, "duplicate path </B>");
    expectParseError("#usda 1.0\ndef \"A\" {\n    add rel r = []\n}\n", 3, 17,
                     "an empty list cannot be used with 'add'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    prepend double x = 1\n}\n", 3, 5,
                     "'prepend' can only edit connections");
    expectParseError("#usda 1.0\ndef \"A\" {\n    uniform rel r\n}\n", 3, 5, "relationships cannot be 'uniform'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x.spline = {}\n}\n", 3, 14, "splines");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x.timeSamples = { 1 2 }\n}\n", 3, 32,
                     "expected ':' after time code 1");
    expectParseError(
        "#usda 1.0\ndef \"A\" {\n    variantSet \"v\" = {\n        \"bad.name\" {\n        }\n    "
        "}\n}\n",
        4, 9, "invalid variant name \"bad.name\"");
}

TEST(UsdaErrors, NestingIsCapped) {
    std::string deepList = "#usda 1.0\n(\n    x = " + std::string(5000, '[') + "\n)\n";
    expectParseError(deepList, 3, 9 + detail::kMaxNesting, "nesting deeper than 256 levels");
    std::string deepDictionary = "#usda 1.0\n(\n    customData = ";
    for (int i = 0; i < 2000; ++i) deepDictionary += "{ dictionary d = ";
    expectParseError(deepDictionary, 3, 18 + 17 * detail::kMaxNesting, "nesting deeper than 256 levels");
}

TEST(UsdaErrors, DeepButBoundedNestingParses) {
    std::string text = "#usda 1.0\n";
    const int depth = detail::kMaxNesting - 1;
    for (int i = 0; i < depth; ++i) text += "def \"P\" {\n";
    for (int i = 0; i < depth; ++i) text += "}\n";
    auto layer = parseUsdaString(text, "deep.usda");
    const PrimSpec* prim = layer->rootPrims.front().get();
    int levels = 1;
    while (!prim->children.empty()) prim = prim->children.front().get(), ++levels;
    EXPECT_EQ(levels, depth);
}

}  // namespace
}  // namespace fluence::usd
