// OpenEXR output of resolved images (through OpenImageIO; no OIIO header here).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "color/color_management.h"
#include "core/image.h"

namespace fluence::output {

struct ExrHeader {
    // Colour space of the colour channels: written as the "colorSpace" string attribute and as
    // OIIO's "oiio:ColorSpace".
    std::string colorSpace = color::ColorManagement::kRenderingSpace;
    // {Rx, Ry, Gx, Gy, Bx, By, Wx, Wy}: written as the standard EXR 'chromaticities' attribute.
    std::array<float, 8> chromaticities = color::ColorManagement::renderingChromaticities();
    // Width / height of one pixel: the standard EXR 'pixelAspectRatio' attribute.
    float pixelAspectRatio = 1.0f;
    // Extra attributes, e.g. {"fluence/version", "0.1.0"}, {"fluence/scene", path}, {"fluence/renderTime", 12.5}.
    std::vector<std::pair<std::string, std::string>> strings;
    std::vector<std::pair<std::string, float>> floats;
    // Channels holding data rather than colour (N.X, Z, sampleCount, ...): listed, comma-separated,
    // in the "fluence/dataChannels" string attribute.
    std::vector<std::string> dataChannels;
    // A tile of a larger image: the image's pixels are the data window at (x, y) of a display window
    // of fullWidth x fullHeight (0: the image is the whole display window).
    int x = 0, y = 0, fullWidth = 0, fullHeight = 0;
};

// Writes every channel of `image` as 32-bit float, ZIP-compressed scanlines, channel names as given
// (in the Image's order; Nuke-style layer names such as "albedo.R"), row 0 at the top. The file
// is replaced atomically (see output/atomic_file.h). Throws OutputError, naming `path`, if the
// image is inconsistent (pixel buffer size != width*height*channels, empty or duplicate channel
// names; checked before anything is written) or the file cannot be written.
void writeExr(const std::string& path, const Image& image, const ExrHeader& header = {});

}  // namespace fluence::output
