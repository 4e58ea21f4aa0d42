// `fluence assemble`: tiles rendered apart (`fluence render --tile-count X Y --tile-index N`) back
// into the whole image. Each tile is an EXR whose data window is its part of the display window
// (output/exr_writer.h, ExrHeader::x/y/fullWidth/fullHeight); the assembled EXR has the tiles'
// channels and header attributes (the first tile's, with the Cryptomatte manifests of every tile
// merged) and the display window as its data window.
// Since every pixel's samples draw from the same random streams whatever the tiling
// (integrators/renderer.h), the result is bit-identical to the render done in one piece.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::output {

// A tile that cannot be read (missing or not an image).
class TileReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};
// Tiles that do not make one image: display windows or channels that differ, tiles that overlap,
// or pixels no tile covers (the message names the first such pixel).
class TileMismatchError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads `tiles` and writes the whole image to `path` (atomically). Throws TileReadError,
// TileMismatchError, or OutputError when `path` cannot be written.
void assembleTiles(const std::vector<std::string>& tiles, const std::string& path);

}  // namespace fluence::output
