#include "output/cryptomatte.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

namespace fluence::output {

namespace {

std::uint32_t mixBlock(std::uint32_t k) {
    k *= 0xcc9e2d51u;
    k = std::rotl(k, 15);
    return k * 0x1b873593u;
}

// A JSON string literal of UTF-8 text.
std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

// The entries of a manifest, {"name":"hex",...}, in order, their JSON escapes kept.
std::vector<std::pair<std::string, std::string>> manifestEntries(const std::string& json) {
    std::size_t i = 0;
    const auto fail = [&] {
        throw std::invalid_argument("not a Cryptomatte manifest (a JSON object of strings): " + json.substr(0, 80));
    };
    const auto skipSpace = [&] {
        while (i < json.size() && (json[i] == ' ' || json[i] == '\n' || json[i] == '\t' || json[i] == '\r')) ++i;
    };
    const auto expect = [&](char c) {
        skipSpace();
        if (i >= json.size() || json[i] != c) fail();
        ++i;
    };
    const auto readString = [&] {
        expect('"');
        const std::size_t start = i;
        for (; i < json.size() && json[i] != '"'; ++i)
            if (json[i] == '\\') ++i;
        if (i >= json.size()) fail();
        return json.substr(start, i++ - start);
    };
    std::vector<std::pair<std::string, std::string>> entries;
    expect('{');
    skipSpace();
    if (i < json.size() && json[i] == '}') return entries;
    while (true) {
        std::string name = readString();
        expect(':');
        entries.emplace_back(std::move(name), readString());
        skipSpace();
        if (i < json.size() && json[i] == '}') return entries;
        expect(',');
    }
}

std::string twoDigits(int n) { return n < 10 ? "0" + std::to_string(n) : std::to_string(n); }

}  // namespace

std::uint32_t murmurHash3_x86_32(std::string_view data, std::uint32_t seed) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    const std::size_t length = data.size(), blocks = length / 4;
    std::uint32_t h = seed;
    for (std::size_t i = 0; i < blocks; ++i) {
        const unsigned char* b = bytes + 4 * i;
        const std::uint32_t k =
            std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
        h ^= mixBlock(k);
        h = std::rotl(h, 13) * 5u + 0xe6546b64u;
    }
    const unsigned char* tail = bytes + 4 * blocks;
    std::uint32_t k = 0;
    for (std::size_t i = length & 3; i > 0; --i) k |= std::uint32_t(tail[i - 1]) << (8 * (i - 1));
    if ((length & 3) != 0) h ^= mixBlock(k);
    h ^= static_cast<std::uint32_t>(length);
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    return h ^ (h >> 16);
}

std::uint32_t cryptomatteId(std::string_view name) {
    std::uint32_t id = murmurHash3_x86_32(name);
    const std::uint32_t exponent = (id >> 23) & 0xffu;
    if (exponent == 0 || exponent == 0xffu) id ^= 1u << 23;
    return id;
}

float cryptomatteIdFloat(std::uint32_t id) { return std::bit_cast<float>(id); }

std::string cryptomatteHex(std::uint32_t id) {
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", id);
    return hex;
}

std::string mergeCryptomatteManifests(const std::string& a, const std::string& b) {
    std::vector<std::pair<std::string, std::string>> entries = manifestEntries(a);
    std::set<std::string> names;
    for (const auto& entry : entries) names.insert(entry.first);
    for (auto& entry : manifestEntries(b))
        if (names.insert(entry.first).second) entries.push_back(std::move(entry));
    std::string out = "{";
    for (const auto& [name, hex] : entries) out += (out.size() > 1 ? ",\"" : "\"") + name + "\":\"" + hex + "\"";
    return out + "}";
}

std::string cryptomatteKey(std::string_view typeName) { return cryptomatteHex(cryptomatteId(typeName)).substr(0, 7); }

void appendCryptomatte(Image& image, ExrHeader& header, const CryptomatteFilm& film,
                       const std::vector<CryptomatteLayer>& layers, int depth) {
    if (layers.size() != film.layers().size())
        throw std::invalid_argument("appendCryptomatte: one description per film layer");
    if (depth < 1) throw std::invalid_argument("appendCryptomatte: depth must be at least 1");
    if (film.width() != image.width || film.height() != image.height)
        throw std::invalid_argument("appendCryptomatte: the film and the image differ in size");
    const int groups = (depth + 1) / 2;
    std::vector<std::string> added;
    for (const CryptomatteLayer& layer : layers)
        for (int g = 0; g < groups; ++g)
            for (const char* c : {".R", ".G", ".B", ".A"}) added.push_back(layer.typeName + twoDigits(g) + c);

    const std::size_t oldCount = image.channels.size(), newCount = oldCount + added.size();
    Image out(image.width, image.height, image.channels);
    out.channels.insert(out.channels.end(), added.begin(), added.end());
    out.pixels.assign(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * newCount, 0.0f);
    // Per layer, the names its channels hold (ordered by index, so the manifest is deterministic).
    std::vector<std::map<std::uint32_t, std::uint32_t>> written(layers.size());  // name index -> id
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            std::copy_n(image.pixel(x, y), oldCount, out.pixel(x, y));
            float* channels = out.pixel(x, y) + oldCount;
            for (std::size_t l = 0; l < layers.size(); ++l) {
                std::vector<CryptomatteFilm::Coverage> ranks = film.ranked(x, y, l);
                ranks.resize(std::min(ranks.size(), static_cast<std::size_t>(depth)));
                float* layerChannels = channels + l * static_cast<std::size_t>(4 * groups);
                for (std::size_t r = 0; r < ranks.size(); ++r) {
                    const std::uint32_t id = cryptomatteId(layers[l].names->name(ranks[r].name));
                    written[l].emplace(ranks[r].name, id);
                    layerChannels[2 * r] = cryptomatteIdFloat(id);
                    layerChannels[2 * r + 1] = ranks[r].coverage;
                }
            }
        }
    image = std::move(out);

    header.dataChannels.insert(header.dataChannels.end(), added.begin(), added.end());
    if (!header.channelTypes.empty())
        header.channelTypes.insert(header.channelTypes.end(), added.size(), PixelType::Float);
    const std::string method = header.compression.substr(0, header.compression.find(':'));
    if (method != "none" && method != "rle" && method != "zips" && method != "zip" && method != "piz")
        header.compression = "zip";
    for (std::size_t l = 0; l < layers.size(); ++l) {
        std::string manifest = "{";
        for (const auto& [name, id] : written[l]) {
            if (manifest.size() > 1) manifest += ",";
            manifest += jsonString(layers[l].names->name(name)) + ":" + jsonString(cryptomatteHex(id));
        }
        manifest += "}";
        const std::string prefix = "cryptomatte/" + cryptomatteKey(layers[l].typeName) + "/";
        header.strings.insert(header.strings.end(), {{prefix + "name", layers[l].typeName},
                                                     {prefix + "hash", "MurmurHash3_32"},
                                                     {prefix + "conversion", "uint32_to_float32"},
                                                     {prefix + "manifest", manifest}});
    }
}

}  // namespace fluence::output
