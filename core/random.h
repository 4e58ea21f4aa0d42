// Counter-based random numbers: every sample value is a pure function of
// (seed, pixel, sample index, dimension).
//
// Two samplers draw them (SamplerKind). Independent: each value hashed from the four counters.
// Sobol (the renderer's default): each call of next() or next2D() takes the next "slot" of the
// sample, and a slot's values over a pixel's sample indices are an Owen-scrambled Sobol sequence
// (core/owen_sobol.h) with a scramble hashed from (seed, pixel, slot): the samples of one pixel
// stratify every 1D and 2D decision that lands in the same slot, different pixels and slots are
// decorrelated. The integrators draw in a fixed order, so the slots follow the path: the pixel
// position, the hero wavelength, then per bounce the light choice and light point, the BSDF lobe
// and direction, Russian roulette and the medium events (docs/USER_GUIDE.md, "Sampling"). Walks
// that draw a varying number of values (majorant tracking) draw them from independentStream(),
// or, where their steps should stay stratified (a guided subsurface walk), from fork(), so the
// slots after them stay the same in every sample of a pixel.
//
// Nothing is carried between pixels or threads, so an image is bit-identical at any thread count
// and any tile can be re-rendered alone (farm splits, checkpoints). The hash is SplitMix64's
// finaliser (Steele, Lea & Flood 2014), applied to a key built from the four counters; its
// output passes BigCrush when fed a counter, which is how it is used here.
//
// A slot's scramble depends on (seed, pixel, slot) only, the same in every sample of the pixel. A
// renderer that takes a pixel's samples one after another gives their streams one
// PixelSlotScrambles, which hashes each of the first kCachedSlots slots' scrambles once, when the
// first sample draws it, instead of once per sample (two SplitMix64 finalisers per 2D draw, a
// dependent chain of six multiplications in front of the scramble itself). The values are those of
// a stream without it, bit for bit (tests/core/random_test.cpp).
#pragma once

#include <cstdint>

#include "core/owen_sobol.h"
#include "core/vec.h"

namespace fluence {

constexpr std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// A uniform float in [0, 1) from the top 24 bits (every value exactly representable).
constexpr float toUnitFloat(std::uint64_t bits) { return static_cast<float>(bits >> 40) * 0x1p-24f; }

enum class SamplerKind { Independent, Sobol };

// The key of (seed, pixel) every stream of the pixel derives its values from.
constexpr std::uint64_t pixelStreamKey(std::uint64_t seed, std::uint64_t pixelIndex) {
    return mix64(mix64(seed ^ 0x5851f42d4c957f2dull) ^ pixelIndex);
}

// The scrambles of one slot of a pixel's Sobol sequences: `x`'s halves shuffle the index and
// scramble the first value, `y`'s low half scrambles a 2D slot's second value (owenSobol2D).
struct SlotScramble {
    std::uint64_t x, y;
};
// Slot 0 is the shutter time's, slots 1, 2, ... next()'s and next2D()'s, and the lens its own.
constexpr std::uint64_t slotScrambleX(std::uint64_t pixelKey, std::uint32_t slot) {
    return mix64(pixelKey + 0x9fb21c651e98df25ull * (std::uint64_t(slot) + 1));
}

// The scrambles of the first kCachedSlots slots of one pixel (see the top of this file), each
// hashed when a sample first asks for it. For one thread at a time: the samples of a pixel, in turn.
class PixelSlotScrambles {
public:
    // Enough for nearly every path: a subsurface walk's steps take seven slots each.
    static constexpr std::uint32_t kCachedSlots = 256;
    PixelSlotScrambles(std::uint64_t seed, std::uint64_t pixelIndex) : pixelKey_(pixelStreamKey(seed, pixelIndex)) {}
    PixelSlotScrambles(const PixelSlotScrambles&) = delete;
    PixelSlotScrambles& operator=(const PixelSlotScrambles&) = delete;

    std::uint64_t pixelKey() const { return pixelKey_; }
    // Slot `slot` < kCachedSlots.
    const SlotScramble& at(std::uint32_t slot) {
        std::uint64_t& word = hashed_[slot / 64];
        const std::uint64_t bit = std::uint64_t(1) << (slot % 64);
        if (!(word & bit)) {
            const std::uint64_t x = slotScrambleX(pixelKey_, slot);
            scrambles_[slot] = {x, mix64(x)};
            word |= bit;
        }
        return scrambles_[slot];
    }

private:
    std::uint64_t pixelKey_;
    std::uint64_t hashed_[kCachedSlots / 64] = {};  // bit k % 64 of word k / 64: scrambles_[k] is hashed
    SlotScramble scrambles_[kCachedSlots];          // left uninitialised until hashed
};

// The random stream of one camera sample. Dimensions are consumed in order; the same
// (seed, pixel, sample) always yields the same sequence. A 2D decision draws next2D() (one
// stratified pair under Sobol), never next() twice.
class SampleStream {
public:
    constexpr SampleStream(std::uint64_t seed, std::uint64_t pixelIndex, std::uint64_t sampleIndex,
                           SamplerKind kind = SamplerKind::Independent)
        : SampleStream(pixelStreamKey(seed, pixelIndex), sampleIndex, kind, nullptr) {}
    // The same stream, its slots' scrambles taken from (and hashed once into) `pixel`, the table of
    // the (seed, pixel) it is made for, which must outlive it.
    SampleStream(PixelSlotScrambles& pixel, std::uint64_t sampleIndex, SamplerKind kind)
        : SampleStream(pixel.pixelKey(), sampleIndex, kind, &pixel) {}

    constexpr float next() {
        ++dimension_;
        if (kind_ == SamplerKind::Sobol) return owenSobol1D(sobolIndex_, firstScramble(dimension_));
        return toUnitFloat(mix64(key_ + 0x632be59bd9b4e019ull * dimension_));
    }
    constexpr Vec2f next2D() {
        if (kind_ == SamplerKind::Sobol) {
            ++dimension_;
            const SlotScramble s = slotScramble(dimension_);
            return owenSobol2D(sobolIndex_, s.x, s.y);
        }
        float a = next();
        return {a, next()};
    }
    // Take the dimensions of next() and of next2D() without computing their values: the numbers of
    // a decision a vertex does not take, which it still draws so that the later ones keep their
    // dimensions (the values after a skip are those after the draw, bit for bit).
    constexpr void skip() { ++dimension_; }
    constexpr void skip2D() { dimension_ += kind_ == SamplerKind::Sobol ? 1 : 2; }
    constexpr std::uint32_t dimension() const { return dimension_; }
    // A stream of hashed independent values for a walk inside the sample that draws a varying
    // number of them (majorant tracking's exponential steps, a shadow ray's transmittance): drawn
    // from it, they take no slot of this stream, so the decisions after the walk keep the same
    // slots in every sample of the pixel (and their stratification). Each call gives another
    // stream, a pure function of (seed, pixel, sample, the calls before it).
    constexpr SampleStream independentStream() {
        SampleStream s = *this;
        s.kind_ = SamplerKind::Independent;
        s.key_ = mix64(key_ ^ (0xd1b54a32d192ed03ull * ++independentStreams_));
        s.dimension_ = 0;
        s.independentStreams_ = 0;
        return s;
    }
    // A stream of its own for a walk inside the sample that draws a varying number of values which
    // should stay stratified step by step over the pixel's samples (a guided subsurface walk,
    // integrators/path_tracer.cpp): its values take no slot of this stream, so the decisions after
    // the walk keep the same slots in every sample; under Sobol it is a Sobol stream from its first
    // slot, whose slots' scrambles are hashed from this stream's pixel key and dimension (the same
    // in every sample of the pixel that forks at that dimension), so its k-th value is stratified
    // over the samples that fork there. Two forks of one stream at different dimensions, and forks
    // of different streams, are decorrelated. Its scrambles are not cached (PixelSlotScrambles).
    constexpr SampleStream fork() const {
        SampleStream s = *this;
        const std::uint64_t at = std::uint64_t(dimension_) + 1;
        s.pixelKey_ = mix64(pixelKey_ ^ (0x2545f4914f6cdd1dull * at));
        s.key_ = mix64(key_ ^ (0x9e6c63d0676a9a99ull * at));
        s.dimension_ = 0;
        s.independentStreams_ = 0;
        s.pixel_ = nullptr;
        return s;
    }
    // The point of the camera's aperture (render/thin_lens.h): two values of their own, outside the
    // sequence next() walks, so depth of field changes no other dimension of a sample (a pinhole
    // camera's images stay as they were) and a tile draws the same lens point on any thread.
    // Under Sobol the lens point is a stratified pair of its own (slot kLensSlot).
    constexpr Vec2f lens() const {
        if (kind_ == SamplerKind::Sobol) {
            const SlotScramble s = slotScramble(kLensSlot);
            return owenSobol2D(sobolIndex_, s.x, s.y);
        }
        return {toUnitFloat(mix64(key_ ^ 0xa0761d6478bd642full)), toUnitFloat(mix64(key_ ^ 0xe7037ed1a0b428dbull))};
    }
    // The sample's time in the shutter interval, uniform in [0, 1): its own dimension (0, which
    // next() never draws), so drawing it or not changes no other value of the stream; under Sobol
    // stratified over the pixel's samples.
    constexpr float shutterTime() const {
        if (kind_ == SamplerKind::Sobol) return owenSobol1D(sobolIndex_, firstScramble(0));
        return toUnitFloat(mix64(key_));
    }
    // The sample index the stream was made for: methods that keep per-sample-index state (the
    // photon map of each sample index, integrators/sppm.h) look theirs up by it.
    constexpr std::uint64_t sampleIndex() const { return sampleIndex_; }

private:
    constexpr SampleStream(std::uint64_t pixelKey, std::uint64_t sampleIndex, SamplerKind kind,
                           PixelSlotScrambles* pixel)
        : pixelKey_(pixelKey),
          key_(pixelKey_ ^ mix64(sampleIndex + 0x14057b7ef767814full)),
          sampleIndex_(sampleIndex),
          sobolIndex_(static_cast<std::uint32_t>(sampleIndex)),
          kind_(kind),
          pixel_(pixel) {}

    static constexpr std::uint32_t kLensSlot = 0xffffffffu;
    // The scramble of one slot of this pixel's Sobol sequences.
    constexpr std::uint64_t slotSeed(std::uint32_t slot) const { return slotScrambleX(pixelKey_, slot); }
    constexpr bool cached(std::uint32_t slot) const {
        return pixel_ != nullptr && slot < PixelSlotScrambles::kCachedSlots;
    }
    // A 1D slot's scramble: slotScramble(slot).x, without hashing the y it does not use.
    constexpr std::uint64_t firstScramble(std::uint32_t slot) const {
        return cached(slot) ? pixel_->at(slot).x : slotSeed(slot);
    }
    constexpr SlotScramble slotScramble(std::uint32_t slot) const {
        if (cached(slot)) return pixel_->at(slot);
        const std::uint64_t x = slotSeed(slot);
        return {x, mix64(x)};
    }
    std::uint64_t pixelKey_;  // (seed, pixel)
    std::uint64_t key_;       // (seed, pixel, sample index)
    std::uint64_t sampleIndex_;
    SobolIndex sobolIndex_;  // the Sobol index (the sample index's low 32 bits), as the draws take it
    SamplerKind kind_;
    std::uint32_t dimension_ = 0;
    std::uint64_t independentStreams_ = 0;  // streams handed out by independentStream()
    PixelSlotScrambles* pixel_;             // the pixel's table of slot scrambles, or none
};

}  // namespace fluence
