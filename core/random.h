// Counter-based random numbers: every sample value is a pure function of
// (seed, pixel, sample index, dimension).
//
// Nothing is carried between pixels or threads, so an image is bit-identical at any thread count
// and any tile can be re-rendered alone (farm splits, checkpoints). The hash is SplitMix64's
// finaliser (Steele, Lea & Flood 2014), applied to a key built from the four counters; its
// output passes BigCrush when fed a counter, which is how it is used here.
#pragma once

#include <cstdint>

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

// The random stream of one camera sample. Dimensions are consumed in order; the same
// (seed, pixel, sample) always yields the same sequence.
class SampleStream {
public:
    constexpr SampleStream(std::uint64_t seed, std::uint64_t pixelIndex, std::uint64_t sampleIndex)
        : key_(mix64(mix64(seed ^ 0x5851f42d4c957f2dull) ^ pixelIndex) ^ mix64(sampleIndex + 0x14057b7ef767814full)),
          sampleIndex_(sampleIndex) {}

    constexpr float next() { return toUnitFloat(mix64(key_ + 0x632be59bd9b4e019ull * ++dimension_)); }
    constexpr Vec2f next2D() {
        float a = next();
        return {a, next()};
    }
    constexpr std::uint32_t dimension() const { return dimension_; }
    // The point of the camera's aperture (render/thin_lens.h): two values of their own, outside the
    // sequence next() walks, so depth of field changes no other dimension of a sample (a pinhole
    // camera's images stay as they were) and a tile draws the same lens point on any thread.
    constexpr Vec2f lens() const {
        return {toUnitFloat(mix64(key_ ^ 0xa0761d6478bd642full)), toUnitFloat(mix64(key_ ^ 0xe7037ed1a0b428dbull))};
    }
    // The sample's time in the shutter interval, uniform in [0, 1): its own dimension (0, which
    // next() never draws), so drawing it or not changes no other value of the stream.
    constexpr float shutterTime() const { return toUnitFloat(mix64(key_)); }
    // The sample index the stream was made for: methods that keep per-sample-index state (the
    // photon map of each sample index, integrators/sppm.h) look theirs up by it.
    constexpr std::uint64_t sampleIndex() const { return sampleIndex_; }

private:
    std::uint64_t key_;
    std::uint64_t sampleIndex_;
    std::uint32_t dimension_ = 0;
};

}  // namespace fluence
