// USDA number text: the syntax the lexer accepts, and values bit-identical to std::from_chars
// whichever way parseNumber takes (the exact fast path or from_chars itself).
#include "scene/usda_number.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace fluence::usd {
namespace {

using detail::parseNumber;

detail::ParsedNumber parse(const std::string& text) { return parseNumber(text.data(), text.data() + text.size()); }

std::size_t lengthOf(const std::string& text) { return static_cast<std::size_t>(parse(text).end - text.data()); }

TEST(UsdaNumber, Syntax) {
    EXPECT_EQ(lengthOf("12"), 2u);
    EXPECT_EQ(lengthOf("-12.5e+3,"), 8u);
    EXPECT_EQ(lengthOf(".25)"), 3u);
    EXPECT_EQ(lengthOf("-.25"), 4u);
    EXPECT_EQ(lengthOf("7."), 2u);
    EXPECT_EQ(lengthOf("1e"), 1u);  // no digits after 'e': not an exponent
    EXPECT_EQ(lengthOf("1e+x"), 1u);
    EXPECT_EQ(lengthOf("1.2.3"), 3u);  // the lexer reports what follows
    EXPECT_EQ(lengthOf("-"), 0u);
    EXPECT_EQ(lengthOf("."), 0u);
    EXPECT_EQ(lengthOf("-inf"), 0u);
    EXPECT_TRUE(parse("42").integral);
    EXPECT_FALSE(parse("42.").integral);
    EXPECT_FALSE(parse("42e0").integral);
    EXPECT_TRUE(parse("42e").integral);
}

TEST(UsdaNumber, ValuesAndRange) {
    EXPECT_EQ(parse("-12.5e+3").value, -12500.0);
    EXPECT_EQ(parse("0.1").value, 0.1);
    EXPECT_TRUE(std::signbit(parse("-0").value));
    EXPECT_TRUE(std::signbit(parse("-0.0e999").value));
    EXPECT_EQ(parse("18446744073709551615").value, 18446744073709551615.0);
    EXPECT_EQ(parse("1e308").value, 1e308);
    EXPECT_FALSE(parse("1e400").inRange);
    EXPECT_FALSE(parse("-1e400").inRange);
    EXPECT_TRUE(parse("1e300").inRange);
}

// Random decimals of every shape the fast path and its fallback meet: up to 25 digits, leading
// and trailing zeros, fractions, exponents up to +-340.
TEST(UsdaNumber, BitIdenticalToFromChars) {
    std::mt19937_64 random(20261127u);
    auto below = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
    for (int i = 0; i < 200000; ++i) {
        std::string text = below(2) ? "-" : "";
        int integerDigits = below(4) == 0 ? 0 : 1 + below(12);
        for (int d = 0; d < integerDigits; ++d) text += static_cast<char>('0' + below(10));
        if (integerDigits == 0 || below(2)) {
            text += '.';
            int fractionDigits = (integerDigits == 0 ? 1 : 0) + below(14);
            for (int d = 0; d < fractionDigits; ++d) text += static_cast<char>('0' + below(10));
        }
        if (below(3) == 0) {
            text += below(2) ? 'e' : 'E';
            if (below(2)) text += below(2) ? '-' : '+';
            text += std::to_string(below(4) == 0 ? below(341) : below(30));
        }
        detail::ParsedNumber number = parse(text);
        ASSERT_EQ(number.end, text.data() + text.size()) << text;
        double expected = 0.0;
        auto result = std::from_chars(text.data(), text.data() + text.size(), expected);
        ASSERT_EQ(number.inRange, result.ec != std::errc::result_out_of_range) << text;
        if (number.inRange) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(number.value), std::bit_cast<std::uint64_t>(expected)) << text;
        }
    }
}

}  // namespace
}  // namespace fluence::usd
