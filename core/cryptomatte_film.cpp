#include "core/cryptomatte_film.h"

#include <algorithm>
#include <utility>

namespace fluence {

CryptomatteFilm::CryptomatteFilm(int width, int height, std::vector<CryptomatteSource> layers)
    : width_(width), height_(height), layers_(std::move(layers)), pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}

void CryptomatteFilm::add(int x, int y, const FilmSample& s) {
    Pixel& p = pixels_[index(x, y)];
    ++p.samples;
    for (std::uint32_t layer = 0; layer < layers_.size(); ++layer) {
        const std::uint32_t name = layers_[layer] == CryptomatteSource::Object ? s.objectName : s.materialName;
        if (name == kNoName) continue;
        auto found = std::find_if(p.entries.begin(), p.entries.end(), [&](const Entry& e) { return e.layer == layer && e.name == name; });
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
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.count != b.count ? a.count > b.count : a.name < b.name; });
    std::vector<Coverage> out;
    out.reserve(entries.size());
    for (const Entry& e : entries) out.push_back({e.name, static_cast<float>(double(e.count) / double(p.samples))});
    return out;
}

}  // namespace fluence
