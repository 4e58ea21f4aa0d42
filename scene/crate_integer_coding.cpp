#include "scene/crate_integer_coding.h"

#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

#include "scene/crate_compression.h"

namespace fluence::usd::detail {

namespace {

template <class T>
T readAt(std::span<const char> bytes, std::size_t& at) {
    if (at > bytes.size() || bytes.size() - at < sizeof(T)) throw CrateFormatError("compressed integers end early");
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return value;
}

template <class Int, class Small, class Medium>
std::vector<Int> decode(std::span<const char> encoded, std::size_t count) {
    using Unsigned = std::make_unsigned_t<Int>;
    if (count == 0) return {};  // OpenUSD encodes no integers as no bytes, not even the common value
    std::size_t at = 0;
    Int common = readAt<Int>(encoded, at);
    std::size_t codeBytes = (count * 2 + 7) / 8;
    if (encoded.size() - at < codeBytes) throw CrateFormatError("compressed integers end early");
    std::size_t codesAt = at;
    std::size_t valuesAt = at + codeBytes;
    std::vector<Int> out(count);
    Unsigned previous = 0;  // unsigned arithmetic: wrapping, as the encoder's deltas do
    for (std::size_t i = 0; i < count; ++i) {
        auto code = (static_cast<unsigned char>(encoded[codesAt + i / 4]) >> (2 * (i % 4))) & 3u;
        Int delta = common;
        if (code == 1) delta = readAt<Small>(encoded, valuesAt);
        if (code == 2) delta = readAt<Medium>(encoded, valuesAt);
        if (code == 3) delta = readAt<Int>(encoded, valuesAt);
        previous += static_cast<Unsigned>(delta);
        out[i] = static_cast<Int>(previous);
    }
    return out;
}

}  // namespace

std::size_t encodedIntegersMaxSize(std::size_t count, std::size_t width) {
    if (count > std::numeric_limits<std::size_t>::max() / (width + 1))
        throw CrateFormatError("integer count " + std::to_string(count) + " is too large");
    return width + (count * 2 + 7) / 8 + count * width;
}

std::vector<std::int32_t> decodeIntegers32(std::span<const char> encoded, std::size_t count) {
    return decode<std::int32_t, std::int8_t, std::int16_t>(encoded, count);
}

std::vector<std::int64_t> decodeIntegers64(std::span<const char> encoded, std::size_t count) {
    return decode<std::int64_t, std::int16_t, std::int32_t>(encoded, count);
}

std::vector<std::int32_t> decompressIntegers32(std::span<const char> compressed, std::size_t count) {
    return decodeIntegers32(decompressCrateBuffer(compressed, encodedIntegersMaxSize(count, 4)), count);
}

std::vector<std::int64_t> decompressIntegers64(std::span<const char> compressed, std::size_t count) {
    return decodeIntegers64(decompressCrateBuffer(compressed, encodedIntegersMaxSize(count, 8)), count);
}

}  // namespace fluence::usd::detail
