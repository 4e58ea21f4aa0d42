#include "core/film_state.h"

#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "core/binary_stream.h"

namespace fluence {

namespace {

constexpr std::uint32_t kMaxLayerNameLength = 4096;

template <typename Pixel>
void writePixel(std::ostream& out, const Pixel& p) {
    writeBinary(out, p.radiance, 3);
    writeBinary(out, p.luminance);
    writeBinary(out, p.luminanceSquared);
    writeBinary(out, p.albedo, 3);
    writeBinary(out, p.normal, 3);
    writeBinary(out, p.coverage);
    writeBinary(out, p.cost);
    writeBinary(out, p.minDepth);
    writeBinary(out, static_cast<std::uint8_t>(p.anyHit));
    writeBinary(out, p.samples);
}

template <typename Pixel>
void readPixel(std::istream& in, Pixel& p) {
    readBinary(in, p.radiance, 3);
    readBinary(in, &p.luminance, 1);
    readBinary(in, &p.luminanceSquared, 1);
    readBinary(in, p.albedo, 3);
    readBinary(in, p.normal, 3);
    readBinary(in, &p.coverage, 1);
    readBinary(in, &p.cost, 1);
    readBinary(in, &p.minDepth, 1);
    p.anyHit = readBinary<std::uint8_t>(in) != 0;
    readBinary(in, &p.samples, 1);
}

}  // namespace

void writeFilmState(const Film& film, std::ostream& out) {
    // A field added to Film or Film::Pixel changes these sizes: save it here and in readFilmState,
    // bump kFilmStateVersion, and update the size.
    static_assert(sizeof(Film::Pixel) == 120, "Film::Pixel changed: write and read the new field in film_state.cpp");
    static_assert(sizeof(Film) == 120, "Film changed: write and read the new state in film_state.cpp");
    writeBinary(out, kFilmStateVersion);
    writeBinary(out, static_cast<std::int32_t>(film.width_));
    writeBinary(out, static_cast<std::int32_t>(film.height_));
    writeBinary(out, film.farDepth_);
    writeBinary(out, static_cast<std::uint32_t>(film.lightPathLayers_.size()));
    for (const std::string& name : film.lightPathLayers_) writeBinaryString(out, name);
    for (const Film::Pixel& p : film.pixels_) writePixel(out, p);
    writeBinary(out, film.lightPathSums_.data(), film.lightPathSums_.size());
    // The splat film (light tracing, core/splat_film.h), when the render made one: its fixed-point sums.
    writeBinary(out, static_cast<std::uint8_t>(film.splats_ != nullptr));
    if (film.splats_) {
        const std::vector<std::int64_t> sums = film.splats_->fixedSums();
        writeBinary(out, sums.data(), sums.size());
    }
    // The denoiser's buffers (version 3; their prefix sums from version 5), when the render keeps them.
    writeBinary(out, static_cast<std::uint8_t>(film.hasDenoiseBuffers()));
    writeBinary(out, film.denoiseSums_.data(), film.denoiseSums_.size());
}

void readFilmState(std::istream& in, Film& film) {
    try {
        if (const auto version = readBinary<std::uint32_t>(in); version != kFilmStateVersion)
            throw FilmStateError("film state version " + std::to_string(version) + " (this build reads version " +
                                 std::to_string(kFilmStateVersion) +
                                 ": it was saved by another build of Fluence; render it again without resuming)");
        const auto width = readBinary<std::int32_t>(in), height = readBinary<std::int32_t>(in);
        if (width != film.width_ || height != film.height_)
            throw FilmStateError("the saved film is " + std::to_string(width) + "x" + std::to_string(height) +
                                 ", this one " + std::to_string(film.width_) + "x" + std::to_string(film.height_));
        if (const auto farDepth = readBinary<float>(in); farDepth != film.farDepth_)
            throw FilmStateError("the saved film's far depth is " + std::to_string(farDepth) + ", this one's " +
                                 std::to_string(film.farDepth_));
        const auto layers = readBinary<std::uint32_t>(in);
        std::vector<std::string> names;
        for (std::uint32_t l = 0; l < layers && l <= std::uint32_t(kMaxLightPathLayers); ++l)
            names.push_back(readBinaryString(in, kMaxLayerNameLength));
        if (names != film.lightPathLayers_) {
            auto list = [](const std::vector<std::string>& v) {
                std::string s;
                for (const std::string& n : v) s += (s.empty() ? "" : ", ") + n;
                return "(" + s + ")";
            };
            throw FilmStateError("the saved film's light path layers are " + list(names) + ", this one's " +
                                 list(film.lightPathLayers_));
        }
        for (Film::Pixel& p : film.pixels_) readPixel(in, p);
        readBinary(in, film.lightPathSums_.data(), film.lightPathSums_.size());
        if (readBinary<std::uint8_t>(in) != 0) {
            std::vector<std::int64_t> sums(film.pixels_.size() * 3 * (film.lightPathLayers_.size() + 1));
            readBinary(in, sums.data(), sums.size());
            film.enableSplats().restore(sums);
        }
        const bool savedBuffers = readBinary<std::uint8_t>(in) != 0;
        if (savedBuffers != film.hasDenoiseBuffers())
            throw FilmStateError(savedBuffers
                                     ? "the saved film keeps the denoiser's buffers, this one does not"
                                     : "the saved film has no denoiser's buffers (rendered without --denoise), "
                                       "this one needs them");
        readBinary(in, film.denoiseSums_.data(), film.denoiseSums_.size());
    } catch (const BinaryReadError& e) {
        throw FilmStateError("damaged film state: " + std::string(e.what()));
    }
}

}  // namespace fluence
