#include "output/tile_assembly.h"

#include <OpenImageIO/imageio.h>

#include <memory>

#include "output/cryptomatte.h"
#include "output/image_file.h"

namespace fluence::output {

namespace {

struct Tile {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;
};

Tile readTile(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw TileReadError("cannot read tile " + path + ": " + OIIO::geterror());
    Tile tile{in->spec(), {}};
    tile.pixels.resize(std::size_t(tile.spec.width) * std::size_t(tile.spec.height) * std::size_t(tile.spec.nchannels));
    if (!in->read_image(0, 0, 0, tile.spec.nchannels, OIIO::TypeDesc::FLOAT, tile.pixels.data()))
        throw TileReadError("cannot read tile " + path + ": " + in->geterror());
    return tile;
}

std::string window(const OIIO::ImageSpec& s) {
    return std::to_string(s.full_width) + "x" + std::to_string(s.full_height) + "+" + std::to_string(s.full_x) + "+" +
           std::to_string(s.full_y);
}

// Adds the names of `tile`'s Cryptomatte manifests (output/cryptomatte.h) to `whole`'s: each tile
// lists only the names its own pixels hold.
void mergeManifests(OIIO::ImageSpec& whole, const OIIO::ImageSpec& tile, const std::string& path) {
    for (const OIIO::ParamValue& p : tile.extra_attribs) {
        const std::string name = p.name().string();
        if (!name.starts_with("cryptomatte/") || !name.ends_with("/manifest")) continue;
        try {
            whole.attribute(name, mergeCryptomatteManifests(whole.get_string_attribute(name, "{}"), p.get_string()));
        } catch (const std::invalid_argument& e) {
            throw TileMismatchError("tile " + path + ": " + name + ": " + e.what());
        }
    }
}

}  // namespace

void assembleTiles(const std::vector<std::string>& tiles, const std::string& path) {
    if (tiles.empty()) throw TileMismatchError("no tiles to assemble");
    OIIO::ImageSpec whole;
    std::vector<float> pixels;
    std::vector<unsigned char> covered;
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        const Tile tile = readTile(tiles[t]);
        const OIIO::ImageSpec& s = tile.spec;
        if (t == 0) {
            whole = s;
            whole.x = whole.full_x;
            whole.y = whole.full_y;
            whole.width = whole.full_width;
            whole.height = whole.full_height;
            whole.erase_attribute("fluence/tile");
            pixels.assign(std::size_t(whole.width) * std::size_t(whole.height) * std::size_t(whole.nchannels), 0.0f);
            covered.assign(std::size_t(whole.width) * std::size_t(whole.height), 0);
        } else if (window(s) != window(whole) || s.channelnames != whole.channelnames) {
            throw TileMismatchError("tile " + tiles[t] + " is not a part of the same image as " + tiles[0] +
                                    " (display window " + window(s) + " against " + window(whole) +
                                    ", or other channels)");
        } else {
            mergeManifests(whole, s, tiles[t]);
        }
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x) {
                const int X = s.x + x - whole.x, Y = s.y + y - whole.y;
                if (X < 0 || Y < 0 || X >= whole.width || Y >= whole.height)
                    throw TileMismatchError("tile " + tiles[t] + " reaches outside its display window");
                const std::size_t at = std::size_t(Y) * std::size_t(whole.width) + std::size_t(X);
                if (covered[at]++)
                    throw TileMismatchError("tile " + tiles[t] + " overlaps another at pixel (" + std::to_string(X) +
                                            ", " + std::to_string(Y) + ")");
                std::copy_n(tile.pixels.data() +
                                (std::size_t(y) * std::size_t(s.width) + std::size_t(x)) * std::size_t(s.nchannels),
                            s.nchannels, pixels.data() + at * std::size_t(whole.nchannels));
            }
    }
    for (std::size_t at = 0; at < covered.size(); ++at)
        if (!covered[at])
            throw TileMismatchError("no tile covers pixel (" + std::to_string(at % std::size_t(whole.width)) + ", " +
                                    std::to_string(at / std::size_t(whole.width)) + "): a tile is missing");
    // Read as float, written in the tiles' own channel types (half, float, uint) and compression.
    writeImageFile(path, "openexr", whole, pixels.data(), OIIO::TypeFloat);
}

}  // namespace fluence::output
