#include "scene/utf8.h"

namespace fluence::usd::detail {

namespace {

const char* const kHex = "0123456789ABCDEF";

}  // namespace

Utf8Char decodeUtf8(std::string_view text, std::size_t pos) {
    auto byte = [&](std::size_t i) -> unsigned {
        return pos + i < text.size() ? static_cast<unsigned char>(text[pos + i]) : 0u;
    };
    unsigned lead = byte(0);
    if (lead < 0x80) return {lead, 1};
    // The lead byte fixes the length, the first payload bits and the range of the second byte
    // (narrower than 80..BF where that excludes overlong forms, surrogates and > U+10FFFF).
    std::size_t length = 0;
    char32_t codePoint = 0;
    unsigned low = 0x80, high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2, codePoint = lead & 0x1F;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3, codePoint = lead & 0x0F;
        if (lead == 0xE0) low = 0xA0;
        if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4, codePoint = lead & 0x07;
        if (lead == 0xF0) low = 0x90;
        if (lead == 0xF4) high = 0x8F;
    } else {
        return {};
    }
    for (std::size_t i = 1; i < length; ++i) {
        unsigned next = byte(i);
        if (next < low || next > high) return {};
        codePoint = (codePoint << 6) | (next & 0x3F);
        low = 0x80, high = 0xBF;
    }
    return {codePoint, length};
}

std::string describeCodePoint(char32_t codePoint) {
    std::string digits;
    for (char32_t rest = codePoint; rest || digits.size() < 4; rest >>= 4) {
        digits.insert(digits.begin(), kHex[rest & 15]);
    }
    std::string out = "U+" + digits;
    if (codePoint < 0x20 || (codePoint >= 0x7F && codePoint < 0xA0)) return out;
    // Append the character itself, encoded back to UTF-8.
    out += " '";
    if (codePoint < 0x80) {
        out += static_cast<char>(codePoint);
    } else {
        int continuation = codePoint < 0x800 ? 1 : codePoint < 0x10000 ? 2 : 3;
        static const unsigned kLeadMarks[] = {0, 0xC0, 0xE0, 0xF0};
        out += static_cast<char>(kLeadMarks[continuation] | (codePoint >> (6 * continuation)));
        for (int i = continuation - 1; i >= 0; --i) {
            out += static_cast<char>(0x80 | ((codePoint >> (6 * i)) & 0x3F));
        }
    }
    return out + "'";
}

std::string describeMalformedUtf8(std::string_view text, std::size_t pos) {
    unsigned byte = static_cast<unsigned char>(text[pos]);
    return std::string("malformed UTF-8 (byte 0x") + kHex[byte >> 4] + kHex[byte & 15] + ")";
}

}  // namespace fluence::usd::detail
