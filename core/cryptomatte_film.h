// Cryptomatte accumulation: per pixel, how many of its camera samples each name covered.
//
// A layer reads one of the names a camera sample carries (FilmSample::objectName or
// materialName, indices into the render scene's name tables). Each pixel keeps a short list of
// (layer, name, count) entries, one per name its samples named, and its sample count; the coverage
// of a name is count / samples, the box filter of the beauty (every camera sample weighs the same,
// and they are the beauty's own samples). A sample that names nothing (it missed, or its surface has
// no material in a material layer) counts towards the pixel's samples but no name, so a pixel's
// coverages sum to the fraction of its samples that named something.
//
// Deterministic: a pixel is owned by one task at a time (integrators/renderer.h) and only integer
// counts are kept, so neither the order of samples nor the thread count changes the result. Memory:
// built only when Cryptomatte layers are asked for; a pixel's list is empty (nothing allocated)
// until a sample names something, and holds one 12-byte entry per name seen. output/cryptomatte.h
// turns the ranked coverages into the specification's channels and metadata.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <vector>

#include "core/film.h"

namespace fluence {

enum class CryptomatteSource { Object, Material };

class CryptomatteFilm {
public:
    // One layer per entry of `layers`, in that order.
    CryptomatteFilm(int width, int height, std::vector<CryptomatteSource> layers);

    int width() const { return width_; }
    int height() const { return height_; }
    const std::vector<CryptomatteSource>& layers() const { return layers_; }

    void add(int x, int y, const FilmSample& s);

    struct Coverage {
        std::uint32_t name;  // index into the layer's name table
        float coverage;      // fraction of the pixel's samples, in (0, 1]
    };
    // The names layer `layer` saw in pixel (x, y), by decreasing coverage (equal coverages by
    // increasing name index, so the ranking is deterministic).
    std::vector<Coverage> ranked(int x, int y, std::size_t layer) const;
    std::uint32_t samples(int x, int y) const { return pixels_[index(x, y)].samples; }

    // Its whole state as bytes (render checkpoints, core/film_state.h): shape, layers, and per
    // pixel the sample count and the (layer, name, count) entries in the order they were made, so
    // a render that goes on from them ranks exactly as one never stopped. readState replaces the
    // counts of a film of the same shape and layers; throws FilmStateError otherwise, or when the
    // data is damaged.
    void writeState(std::ostream& out) const;
    void readState(std::istream& in);

private:
    struct Entry {
        std::uint32_t layer, name, count;
    };
    struct Pixel {
        std::vector<Entry> entries;
        std::uint32_t samples = 0;
    };
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
    }

    int width_, height_;
    std::vector<CryptomatteSource> layers_;
    std::vector<Pixel> pixels_;
};

}  // namespace fluence
