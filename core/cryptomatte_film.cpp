#include "core/cryptomatte_film.h"

#include <algorithm>
#include <array>
#include <istream>
#include <ostream>
#include <utility>

#include "core/binary_stream.h"
#include "core/film_state.h"

namespace fluence {

CryptomatteFilm::CryptomatteFilm(int width, int height, std::vector<CryptomatteSource> layers)
    : width_(width),
      height_(height),
      layers_(std::move(layers)),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}

void CryptomatteFilm::add(int x, int y, const FilmSample& s) {
    Pixel& p = pixels_[index(x, y)];
    ++p.samples;
    for (std::uint32_t layer = 0; layer < layers_.size(); ++layer) {
        const std::uint32_t name = layers_[layer] == CryptomatteSource::Object ? s.objectName : s.materialName;
        if (name == kNoName) continue;
        auto found = std::find_if(p.entries.begin(), p.entries.end(),
                                  [&](const Entry& e) { return e.layer == layer && e.name == name; });
        if (found != p.entries.end())
            ++found->count;
        else
            p.entries.push_back({layer, name, 1});
    }
}

std::vector<CryptomatteFilm::Coverage> CryptomatteFilm::ranked(int x, int y, std::size_t layer) const {
    const Pixel& p = pixels_[index(x, y)];
    std::vector<Entry> entries;
    for (const Entry& e : p.entries)
        if (e.layer == layer) entries.push_back(e);
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.count != b.count ? a.count > b.count : a.name < b.name; });
    std::vector<Coverage> out;
    out.reserve(entries.size());
    for (const Entry& e : entries) out.push_back({e.name, static_cast<float>(double(e.count) / double(p.samples))});
    return out;
}

void CryptomatteFilm::writeState(std::ostream& out) const {
    writeBinary(out, static_cast<std::int32_t>(width_));
    writeBinary(out, static_cast<std::int32_t>(height_));
    writeBinary(out, static_cast<std::uint32_t>(layers_.size()));
    for (CryptomatteSource layer : layers_) writeBinary(out, static_cast<std::uint32_t>(layer));
    for (const Pixel& p : pixels_) {
        writeBinary(out, p.samples);
        writeBinary(out, static_cast<std::uint32_t>(p.entries.size()));
        for (const Entry& e : p.entries) writeBinary(out, std::array<std::uint32_t, 3>{e.layer, e.name, e.count});
    }
}

void CryptomatteFilm::readState(std::istream& in) {
    try {
        const auto width = readBinary<std::int32_t>(in), height = readBinary<std::int32_t>(in);
        if (width != width_ || height != height_)
            throw FilmStateError("Cryptomatte layers of " + std::to_string(width) + "x" + std::to_string(height) +
                                 " pixels, not " + std::to_string(width_) + "x" + std::to_string(height_));
        const auto layers = readBinary<std::uint32_t>(in);
        bool same = layers == layers_.size();
        for (std::uint32_t i = 0; i < layers; ++i)
            same =
                readBinary<std::uint32_t>(in) == (i < layers_.size() ? static_cast<std::uint32_t>(layers_[i]) : ~0u) &&
                same;
        if (!same) throw FilmStateError("other Cryptomatte layers");
        for (Pixel& p : pixels_) {
            p.samples = readBinary<std::uint32_t>(in);
            const auto entries = readBinary<std::uint32_t>(in);
            if (entries > p.samples * std::max<std::size_t>(layers_.size(), 1))
                throw FilmStateError("damaged Cryptomatte counts");
            p.entries.resize(entries);
            for (Entry& e : p.entries) {
                const auto v = readBinary<std::array<std::uint32_t, 3>>(in);
                if (v[0] >= layers_.size() || v[2] == 0 || v[2] > p.samples)
                    throw FilmStateError("damaged Cryptomatte entry");
                e = {v[0], v[1], v[2]};
            }
        }
    } catch (const BinaryReadError& e) {
        throw FilmStateError(std::string("Cryptomatte state: ") + e.what());
    }
}

}  // namespace fluence
