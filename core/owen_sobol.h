// Owen-scrambled Sobol points, each pair of dimensions scrambled on its own ("padded").
//
// The first two dimensions of Sobol's sequence form a (0,2)-sequence in base 2: every aligned
// block of 2^m consecutive points is a (0,m,2)-net (each of the 2^m elementary intervals of area
// 2^-m holds one point). Their generator matrices are the identity (van der Corput: the index's
// bits reversed) and the Pascal matrix mod 2 (each direction number v_{k+1} = v_k ^ (v_k >> 1));
// no further dimension is needed, so no direction-number table is.
//
// Scrambling follows Burley, "Practical Hash-based Owen Scrambling" (JCGT 2020): a nested uniform
// (Owen) scramble flips each binary digit by a hash of the digits above it. With the bits
// reversed, "the digits above" are the lower bits, which is what a hash built only of additions,
// multiplications and xor-with-a-product propagates into: the Laine–Karras construction, here with
// the constants of Vegdahl's improved variant ("Building a Better LK Hash", 2021). The same
// scramble applied to the sample index (Burley §4) shuffles the sequence: the first 2^m indices
// map to one aligned block of 2^m Sobol points, so every power-of-two prefix of a pixel's samples
// is still a (0,m,2)-net, and the sample count never has to be known in advance (adaptive sampling
// goes on adding samples).
#pragma once

#include <cstdint>

#include "core/vec.h"

namespace fluence {

constexpr std::uint32_t reverseBits32(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// A bijection of 32-bit words in which bit k depends only on bits 0..k of x (and the seed).
constexpr std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen's nested uniform scramble of a binary fraction (bit 31 its first digit).
constexpr std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits32(laineKarrasPermutation(reverseBits32(x), seed));
}

constexpr std::uint32_t sobolDimension0(std::uint32_t index) { return reverseBits32(index); }

constexpr std::uint32_t sobolDimension1(std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
        if (index & 1u) x ^= v;
    return x;
}

// A 32-bit binary fraction as a float in [0, 1): its top 24 bits, so every elementary interval of
// up to 2^-24 keeps its points.
constexpr float fractionToFloat(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

// Point `index` of a 2D Owen-scrambled Sobol sequence. The scramble is chosen by two 64-bit hashes:
// `seed`'s low half shuffles the index and its high half scrambles x; `ySeed`'s low half scrambles y.
constexpr Vec2f owenSobol2D(std::uint32_t index, std::uint64_t seed, std::uint64_t ySeed) {
    const std::uint32_t shuffled = nestedUniformScramble(index, static_cast<std::uint32_t>(seed));
    return {fractionToFloat(nestedUniformScramble(sobolDimension0(shuffled), static_cast<std::uint32_t>(seed >> 32))),
            fractionToFloat(nestedUniformScramble(sobolDimension1(shuffled), static_cast<std::uint32_t>(ySeed)))};
}

// Point `index` of a 1D Owen-scrambled van der Corput sequence (stratified for any power-of-two
// prefix, as above); `seed`'s halves shuffle the index and scramble the value.
constexpr float owenSobol1D(std::uint32_t index, std::uint64_t seed) {
    const std::uint32_t shuffled = nestedUniformScramble(index, static_cast<std::uint32_t>(seed));
    return fractionToFloat(nestedUniformScramble(sobolDimension0(shuffled), static_cast<std::uint32_t>(seed >> 32)));
}

}  // namespace fluence
