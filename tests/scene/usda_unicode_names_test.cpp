// UTF-8 names in USDA layers: the UTF-8 decoder, the Unicode XID classes, names in every script
// that USD accepts, and names, bytes and characters it rejects (with their line:column; columns
// count bytes).
#include <gtest/gtest.h>

#include <string>

#include "scene/unicode_xid.h"
#include "scene/usda_parser.h"
#include "scene/utf8.h"
#include "tests/scene/expect_parse_error.h"

namespace fluence::usd {
namespace {

using detail::decodeUtf8;
using detail::isXidContinue;
using detail::isXidStart;
using test::expectParseError;

TEST(Utf8, DecodesWellFormedSequences) {
    struct Case {
        std::string bytes;
        char32_t codePoint;
    };
    for (const Case& c : {Case{"A", U'A'}, Case{"\xC3\xA9", U'é'}, Case{"\xE3\xA4\xBC", U'㤼'},
                          Case{"\xF0\x9D\x94\x98", U'𝔘'}, Case{"\xF4\x8F\xBF\xBF", 0x10FFFF}}) {
        detail::Utf8Char decoded = decodeUtf8(c.bytes + "x", 0);
        EXPECT_EQ(decoded.codePoint, c.codePoint) << c.bytes;
        EXPECT_EQ(decoded.length, c.bytes.size()) << c.bytes;
    }
}

TEST(Utf8, RejectsMalformedSequences) {
    for (std::string bytes : {
             "\x80",              // a continuation byte first
             "\xC0\xAF",          // overlong '/'
             "\xC1\xBF",          // overlong
             "\xE0\x80\xAF",      // overlong '/'
             "\xF0\x80\x80\xAF",  // overlong '/'
             "\xED\xA0\x80",      // surrogate U+D800
             "\xF4\x90\x80\x80",  // U+110000
             "\xF5\x80\x80\x80",  // lead byte past U+10FFFF
             "\xFF",              // never in UTF-8
             "\xE3\xA4",          // truncated
             "\xC3x",             // not a continuation byte
         }) {
        EXPECT_EQ(decodeUtf8(bytes, 0).length, 0u)
            << "byte 0x" << std::hex << int(static_cast<unsigned char>(bytes[0]));
    }
}

TEST(Utf8, DescribesCodePoints) {
    EXPECT_EQ(detail::describeCodePoint(U'∫'), "U+222B '∫'");
    EXPECT_EQ(detail::describeCodePoint(U'𝔘'), "U+1D518 '𝔘'");
    EXPECT_EQ(detail::describeCodePoint(0x85), "U+0085");
}

TEST(UnicodeXid, ClassesFollowUnicode) {
    for (char32_t letter : {U'a', U'Z', U'é', U'ß', U'Ж', U'ج', U'す', U'㤼', U'響', U'ⅈ', U'𝔘'}) {
        EXPECT_TRUE(isXidStart(letter)) << std::hex << unsigned(letter);
        EXPECT_TRUE(isXidContinue(letter)) << std::hex << unsigned(letter);
    }
    // Digits, '_', combining marks and the middle dot continue a name but do not start one.
    for (char32_t mark : {U'0', U'_', U'৪', U'\u0301', U'·'}) {
        EXPECT_FALSE(isXidStart(mark)) << std::hex << unsigned(mark);
        EXPECT_TRUE(isXidContinue(mark)) << std::hex << unsigned(mark);
    }
    for (char32_t other : {U' ', U'-', U'$', U'∫', U'€', U'\u00A0', U'。', U'😀', char32_t(0x10FFFF)}) {
        EXPECT_FALSE(isXidContinue(other)) << std::hex << unsigned(other);
    }
}

TEST(UsdaUnicodeNames, NamesInEveryScriptParse) {
    auto layer = parseUsdaString(R"(#usda 1.0
def Xform "Café" (
    customData = {
        int "存在する" = 7
    }
)
{
    string utf8_情報 = "._جيد"
    float 材料:粗さ = 0.5
    rel 関係 = </Café/球.radius>

    def Sphere "球"
    {
        double radius = 2
    }
    def 立方体 "ⅈ573"
    {
    }
    def Scope "_Süßigkeiten" (
        variants = {
            string 様式 = "赤-1"
        }
    )
    {
    }
}
)",
                                 "names.usda");
    const PrimSpec* cafe = layer->primAtPath("/Café");
    ASSERT_NE(cafe, nullptr);
    EXPECT_EQ(cafe->attribute("utf8_情報")->defaultValue.asString(), "._جيد");
    EXPECT_EQ(cafe->attribute("材料:粗さ")->defaultValue.asDouble(), 0.5);
    EXPECT_EQ(cafe->relationship("関係")->targets, (std::vector<std::string>{"/Café/球.radius"}));
    EXPECT_NE(layer->primAtPath("/Café/球"), nullptr);
    ASSERT_NE(layer->primAtPath("/Café/ⅈ573"), nullptr);
    EXPECT_EQ(layer->primAtPath("/Café/ⅈ573")->typeName, "立方体");
    EXPECT_NE(layer->primAtPath("/Café/_Süßigkeiten"), nullptr);
}

TEST(UsdaUnicodeNames, InvalidNamesFailAtTheirPosition) {
    // OpenUSD's 218_utf8_bad_identifier.sdf and 219_utf8_bad_type_name.sdf: '㤼' starts a name,
    // '0', '1' and '৪' continue one, '∫' is neither.
    expectParseError("#usda 1.0\ndef Xform \"㤼01৪∫\" {\n}\n", 2, 11,
                     "invalid prim name \"㤼01৪∫\": U+222B '∫' cannot be part of a name");
    expectParseError("#usda 1.0\ndef \"A\" {\n    custom 㤼01৪∫ x = 1\n}\n", 3, 20,
                     "invalid character U+222B '∫' in the name '㤼01৪'");
    expectParseError("#usda 1.0\ndef \"৪\" {\n}\n", 2, 5, "U+09EA '৪' cannot start a name");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double ৪x = 1\n}\n", 3, 12,
                     "invalid character U+09EA '৪' (a name cannot start with it)");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double x = 1 ∫\n}\n", 3, 18, "invalid character U+222B '∫'");
    expectParseError("#usda 1.0\ndef \"A\" {\n    rel r = </A∫>\n}\n", 3, 13,
                     "invalid character U+222B '∫' in path </A∫>");
}

TEST(UsdaUnicodeNames, MalformedUtf8InNamesFails) {
    expectParseError("#usda 1.0\ndef \"A\" {\n    double caf\xC3 = 1\n}\n", 3, 15, "malformed UTF-8 (byte 0xC3)");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double \xC0\xAF = 1\n}\n", 3, 12, "malformed UTF-8 (byte 0xC0)");
    expectParseError("#usda 1.0\ndef \"A\" {\n    double xformOp:\xFF = 1\n}\n", 3, 20, "malformed UTF-8 (byte 0xFF)");
    expectParseError("#usda 1.0\ndef \"\xED\xA0\x80\" {\n}\n", 2, 5,
                     "invalid prim name \"\xED\xA0\x80\": malformed UTF-8 (byte 0xED)");
    expectParseError("#usda 1.0\ndef \"A\" {\n    rel r = </A\xFF>\n}\n", 3, 13, "malformed UTF-8 (byte 0xFF) in path");
}

}  // namespace
}  // namespace fluence::usd
