// Character classes of the USDA lexer (internal to the scene library): one table lookup per byte.
// Bytes from 0x80 up are in no class; the lexer decodes them as UTF-8 (scene/utf8.h).
#pragma once

#include <array>
#include <cstdint>

namespace fluence::usd::detail {

enum CharClass : std::uint8_t {
    kBlank = 1,    // ' ' '\t' '\r' '\f' '\v'
    kNewline = 2,  // '\n'
    kDigit = 4,    // 0-9
    kLetter = 8,   // A-Z a-z _
    kPunct = 16,   // ( ) [ ] { } = , : ; .
};

inline constexpr std::array<std::uint8_t, 256> kCharClasses = [] {
    std::array<std::uint8_t, 256> table{};
    for (unsigned char c : {' ', '\t', '\r', '\f', '\v'}) table[c] = kBlank;
    table['\n'] = kNewline;
    for (int c = '0'; c <= '9'; ++c) table[c] = kDigit;
    for (int c = 'a'; c <= 'z'; ++c) table[c] = kLetter;
    for (int c = 'A'; c <= 'Z'; ++c) table[c] = kLetter;
    table['_'] = kLetter;
    for (unsigned char c : {'(', ')', '[', ']', '{', '}', '=', ',', ':', ';', '.'}) table[c] = kPunct;
    return table;
}();

// True when `c` is in one of `classes` (a CharClass or several, or-ed).
inline bool isIn(char c, unsigned classes) { return kCharClasses[static_cast<unsigned char>(c)] & classes; }

}  // namespace fluence::usd::detail
