// USD crate integer coding (internal to the scene library): OpenUSD's Usd_IntegerCompression,
// used for compressed int arrays, the index lists of the structural sections and the indexes of
// compressed float arrays.
//
// Encoding of n integers of width W (32 or 64 bits): the values are deltas from the previous
// value (starting at 0). The encoded buffer holds the most common delta (a signed W-bit int), then
// ceil(n / 4) code bytes with a 2-bit code per value (lowest bits first: 0 = the common delta,
// 1 = small, 2 = medium, 3 = large), then the non-common deltas in order, each a signed int of
// W/4, W/2 or W bits (int8/int16/int32 for 32-bit values, int16/int32/int64 for 64-bit ones).
// Zero integers encode as an empty buffer (an empty crate's FIELDS section holds one).
// On disk the encoded buffer is LZ4-compressed (crate_compression.h) and preceded by its
// compressed size as a uint64.
//
// Truncated or inconsistent input throws CrateFormatError; nothing is read out of bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fluence::usd::detail {

// Decodes `count` integers from an (uncompressed) encoded buffer.
std::vector<std::int32_t> decodeIntegers32(std::span<const char> encoded, std::size_t count);
std::vector<std::int64_t> decodeIntegers64(std::span<const char> encoded, std::size_t count);

// Decompresses and decodes `count` integers from an LZ4-compressed encoded buffer.
std::vector<std::int32_t> decompressIntegers32(std::span<const char> compressed, std::size_t count);
std::vector<std::int64_t> decompressIntegers64(std::span<const char> compressed, std::size_t count);

// The largest encoded size of `count` integers `width` bytes wide (common value, codes, values).
std::size_t encodedIntegersMaxSize(std::size_t count, std::size_t width);

}  // namespace fluence::usd::detail
