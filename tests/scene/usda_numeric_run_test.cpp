// The lexer's bulk path for numeric arrays (Lexer::scanNumericRun) against the token path: the
// same numbers, and the same errors at the same line:column, wherever in an array they are.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "scene/usda_parser.h"
#include "tests/scene/expect_parse_error.h"

namespace fluence::usd {
namespace {

using test::expectParseError;

// The default value of attribute "a" of prim "/P" in `body`.
NumberArray parseArray(const std::string& declaration) {
    auto layer = parseUsdaString("#usda 1.0\ndef \"P\"\n{\n    " + declaration + "\n}\n", "t.usda");
    return layer->primAtPath("/P")->attribute("a")->defaultValue.numbers;
}

std::vector<std::uint64_t> bits(const NumberArray& numbers) {
    std::vector<std::uint64_t> out;
    for (double x : numbers) out.push_back(std::bit_cast<std::uint64_t>(x));
    return out;
}

// Random elements of `components` numbers (1: bare numbers), as USD writes them.
std::vector<std::string> randomElements(int components, bool integers, std::mt19937& random) {
    std::vector<std::string> elements;
    for (int e = 0; e < 300; ++e) {
        std::string element = components > 1 ? "(" : "";
        for (int c = 0; c < components; ++c) {
            if (c) element += ", ";
            double x = std::uniform_real_distribution<double>(-1e4, 1e4)(random);
            element += integers ? std::to_string(static_cast<int>(x)) : std::to_string(static_cast<float>(x) / 7.0f);
        }
        elements.push_back(element + (components > 1 ? ")" : ""));
    }
    return elements;
}

std::string join(const std::vector<std::string>& elements, const std::string& separator) {
    std::string out;
    for (const std::string& element : elements) out += (out.empty() ? "" : separator) + element;
    return out;
}

// A comment after every ',' sends every element through the token path.
TEST(UsdaNumericRun, SameNumbersAsTheTokenPath) {
    std::mt19937 random(7u);
    for (auto [type, components, integers] : {std::tuple{"float3[]", 3, false},
                                              {"int[]", 1, true},
                                              {"double[]", 1, false},
                                              {"texCoord2f[]", 2, false},
                                              {"quath[]", 4, false},
                                              {"int2[]", 2, true}}) {
        std::vector<std::string> elements = randomElements(components, integers, random);
        NumberArray bulk = parseArray(std::string(type) + " a = [" + join(elements, ", ") + "]");
        NumberArray tokens =
            parseArray(std::string(type) + " a = [# all\n" + join(elements, ", # by the token path\n") + "]");
        ASSERT_EQ(bulk.size(), elements.size() * components) << type;
        EXPECT_EQ(bits(bulk), bits(tokens)) << type;
    }
}

TEST(UsdaNumericRun, LayoutsTheTokenPathAccepts) {
    EXPECT_EQ(parseArray("float[] a = []"), std::vector<double>{});
    EXPECT_EQ(parseArray("float[] a = [1, 2,]"), (std::vector<double>{1, 2}));
    EXPECT_EQ(parseArray("float[] a = [\n  1,\n\n  2\n]"), (std::vector<double>{1, 2}));
    EXPECT_EQ(parseArray("float[] a = [1,\r\n 2]"), (std::vector<double>{1, 2}));
    EXPECT_EQ(parseArray("float2[] a = [( 1 ,2 ),(\n3, 4\n)]"), (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(parseArray("float2[] a = [(1, 2,), (3, 4)]"), (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(parseArray("float[] a = [1, 2 /* two */, 3]"), (std::vector<double>{1, 2, 3}));
    NumberArray special = parseArray("double[] a = [1, inf, -inf, 2, nan, 3]");
    ASSERT_EQ(special.size(), 6u);
    EXPECT_EQ(special[1], std::numeric_limits<double>::infinity());
    EXPECT_EQ(special[2], -std::numeric_limits<double>::infinity());
    EXPECT_EQ(special[3], 2.0);
    EXPECT_TRUE(std::isnan(special[4]));
    EXPECT_EQ(special[5], 3.0);
    EXPECT_EQ(parseArray("bool[] a = [1, 0, true]"), (std::vector<double>{1, 0, 1}));
    EXPECT_EQ(parseArray("matrix2d[] a = [((1, 0), (0, 1))]"), (std::vector<double>{1, 0, 0, 1}));
}

TEST(UsdaNumericRun, ErrorsInsideLongArraysKeepTheirPosition) {
    const std::string head = "#usda 1.0\ndef \"A\" {\n";
    expectParseError(head + "    int[] a = [1, 2, inf, 4]\n}\n", 3, 22, "expected an integer for 'int[]', found 'inf'");
    expectParseError(head + "    uchar[] a = [1, 255, 256]\n}\n", 3, 26, "value 256 is out of range for 'uchar[]'");
    expectParseError(head + "    float3[] a = [(1, 2, 3),\n        (4, 5),\n        (7, 8, 9)]\n}\n", 4, 9,
                     "expected 3 components for 'float3[]', found 2");
    expectParseError(head + "    float[] a = [1, 2,\n        3\n        , 4]\n}\n", 5, 9,
                     "unexpected line break before ','");
    expectParseError(head + "    float2[] a = [(1, 2), (3\n    , 4)]\n}\n", 4, 5, "unexpected line break before ','");
    expectParseError(head + "    float[] a = [1, 2, 2.5.1]\n}\n", 3, 24, "malformed number '2.5.1'");
    expectParseError(head + "    double[] a = [1, 2, 1e999]\n}\n", 3, 25, "number 1e999 is out of range");
    expectParseError(head + "    float[] a = [1, 2 3]\n}\n", 3, 23,
                     "expected ',' or ']' in the 'float[]' array, found number 3");
    expectParseError(head + "    float[] a = [1, 2,\n", 4, 1,
                     "unexpected end of file, expected ']' to close the 'float[]' array opened "
                     "at 3:17");
    // Lines counted inside the bulk path: the error two lines after a multi-line array.
    expectParseError(head + "    float[] a = [1,\n2,\n3]\n    float b = (\n}\n", 6, 15,
                     "expected a number for 'float'");
}

}  // namespace
}  // namespace fluence::usd
