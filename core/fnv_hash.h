// 64-bit FNV-1a (Fowler, Noll & Vo): a fast, stable hash of bytes, for keys and fingerprints that
// must come out the same in every process and build (file caches, checkpoint fingerprints). Not
// for security. Hashes are continued by passing the previous one as `hash`.
#pragma once

#include <cstdint>
#include <string_view>

namespace fluence {

inline constexpr std::uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;

constexpr std::uint64_t fnv1a(std::string_view bytes, std::uint64_t hash = kFnv1aOffsetBasis) {
    for (unsigned char c : bytes) hash = (hash ^ c) * 0x100000001b3ull;
    return hash;
}

}  // namespace fluence
