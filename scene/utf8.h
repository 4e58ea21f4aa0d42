// UTF-8 decoding for the USDA reader (internal to the scene library).
//
// USD text is UTF-8. The reader decodes it only where a character's class matters (names outside
// strings, prim names, variant names, paths) and rejects malformed sequences there: stray
// continuation bytes, overlong forms, surrogates (U+D800..U+DFFF), code points past U+10FFFF and
// truncated sequences, following the well-formed byte sequences of Unicode 15, table 3-7.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fluence::usd::detail {

struct Utf8Char {
    char32_t codePoint = 0;
    std::size_t length = 0;  // bytes; 0 when the bytes at the position are not well-formed UTF-8
};

// The character starting at text[pos] (pos < text.size()).
Utf8Char decodeUtf8(std::string_view text, std::size_t pos);

// How a character is named in messages: "U+222B '∫'" ("U+0001" for control characters).
std::string describeCodePoint(char32_t codePoint);
// What is wrong at text[pos] where decodeUtf8 failed: "malformed UTF-8 (byte 0xFF)".
std::string describeMalformedUtf8(std::string_view text, std::size_t pos);

}  // namespace fluence::usd::detail
