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

// The first step of laineKarrasPermutation, which reads x alone: a sample's draws take it once for
// the index they all shuffle (SobolIndex).
constexpr std::uint32_t laineKarrasPremix(std::uint32_t x) { return x ^ x * 0x3d20adeau; }

// laineKarrasPermutation of x after its first step, given laineKarrasPremix(x).
constexpr std::uint32_t laineKarrasFromPremix(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// A bijection of 32-bit words in which bit k depends only on bits 0..k of x (and the seed).
constexpr std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    return laineKarrasFromPremix(laineKarrasPremix(x), seed);
}

// Owen's nested uniform scramble of a binary fraction (bit 31 its first digit).
constexpr std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits32(laineKarrasPermutation(reverseBits32(x), seed));
}

constexpr std::uint32_t sobolDimension0(std::uint32_t index) { return reverseBits32(index); }

// Dimension 1 with its bits reversed (bit j the digit of 2^-(j+1)), without a loop over the index's
// bits. Reversed, the direction numbers v_{k+1} = v_k ^ (v_k >> 1) read w_{k+1} = w_k ^ (w_k << 1),
// the polynomial (1 + x)^k over GF(2): bit j of w_{k+1} is C(k, j) mod 2, which is 1 exactly when
// the bits of j are a subset of those of k (Lucas' theorem). So bit j of the result is the parity of
// the index's bits k whose positions are supersets of j's: the superset-sum transform over GF(2),
// one shift-and-xor per bit of the position.
constexpr std::uint32_t sobolDimension1Reversed(std::uint32_t index) {
    index ^= (index >> 1) & 0x55555555u;
    index ^= (index >> 2) & 0x33333333u;
    index ^= (index >> 4) & 0x0f0f0f0fu;
    index ^= (index >> 8) & 0x00ff00ffu;
    index ^= (index >> 16) & 0x0000ffffu;
    return index;
}

constexpr std::uint32_t sobolDimension1(std::uint32_t index) { return reverseBits32(sobolDimension1Reversed(index)); }

// A 32-bit binary fraction as a float in [0, 1): its top 24 bits, so every elementary interval of
// up to 2^-24 keeps its points.
constexpr float fractionToFloat(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

// The draws below take the sample index with its bits reversed and the seedless first step of its
// shuffle's permutation taken (SobolIndex), which a sample's stream computes once for all its draws. Each scramble is written as
// nestedUniformScramble(x) = reverse(LK(reverse(x))) with the reversals that cancel left out:
// dimension 0 is reverse(shuffled), so its scrambled value is reverse(LK(shuffled)), and dimension
// 1's is reverse(LK(sobolDimension1Reversed(shuffled))). The values are those of the definition
// bit for bit (tests/core/owen_sobol_test.cpp).

// A Sobol index as the draws take it: laineKarrasPremix(reverseBits32(index)).
struct SobolIndex {
    constexpr explicit SobolIndex(std::uint32_t index) : premixedReversed(laineKarrasPremix(reverseBits32(index))) {}
    std::uint32_t premixedReversed;
};

// The index's Owen shuffle (Burley §4).
constexpr std::uint32_t shuffledSobolIndex(SobolIndex index, std::uint32_t seed) {
    return reverseBits32(laineKarrasFromPremix(index.premixedReversed, seed));
}

// Point `index` of a 2D Owen-scrambled Sobol sequence. The scramble is chosen by two 64-bit hashes:
// `seed`'s low half shuffles the index and its high half scrambles x; `ySeed`'s low half scrambles y.
constexpr Vec2f owenSobol2D(SobolIndex index, std::uint64_t seed, std::uint64_t ySeed) {
    const std::uint32_t shuffled = shuffledSobolIndex(index, static_cast<std::uint32_t>(seed));
    return {fractionToFloat(reverseBits32(laineKarrasPermutation(shuffled, static_cast<std::uint32_t>(seed >> 32)))),
            fractionToFloat(reverseBits32(
                laineKarrasPermutation(sobolDimension1Reversed(shuffled), static_cast<std::uint32_t>(ySeed))))};
}

// Point `index` of a 1D Owen-scrambled van der Corput sequence (stratified for any power-of-two
// prefix, as above); `seed`'s halves shuffle the index and scramble the value.
constexpr float owenSobol1D(SobolIndex index, std::uint64_t seed) {
    const std::uint32_t shuffled = shuffledSobolIndex(index, static_cast<std::uint32_t>(seed));
    return fractionToFloat(reverseBits32(laineKarrasPermutation(shuffled, static_cast<std::uint32_t>(seed >> 32))));
}

}  // namespace fluence
