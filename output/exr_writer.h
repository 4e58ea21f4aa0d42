// OpenEXR output of resolved images (through OpenImageIO; no OIIO header here).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "color/color_management.h"
#include "core/image.h"

namespace fluence::output {

// EXR pixel types: 16-bit half, 32-bit float, 32-bit unsigned int.
enum class PixelType { Half, Float, Uint };

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
    // The colour space's ID in the ASWF Color Interop Forum's list (e.g. "lin_rec709_scene"),
    // written as the "colorInteropID" string attribute when not empty.
    std::string colorInteropId;
    // The pixel type of each channel, in the Image's order (empty: every channel Float). Pixels
    // are converted from the Image's floats; Uint clamps to [0, 2^32 - 1] and rounds.
    std::vector<PixelType> channelTypes;
    // The EXR compression ("zip", "piz", "dwaa:45", ...), as OpenImageIO names it.
    std::string compression = "zip";
    // m44f attributes (e.g. OpenEXR's standard "worldToCamera", "worldToNDC"), 16 values in
    // Imath's M44f order: row-major for row vectors (p' = p * M, translation in values 12..14).
    std::vector<std::pair<std::string, std::array<float, 16>>> matrices;
};

// Writes every channel of `image` (as header.channelTypes says, else 32-bit float; compressed as
// header.compression says, ZIP by default) as scanlines, channel names as given
// (in the Image's order; Nuke-style layer names such as "albedo.R"), row 0 at the top. The file
// is replaced atomically (see output/atomic_file.h). Throws OutputError, naming `path`, if the
// image is inconsistent (pixel buffer size != width*height*channels, empty or duplicate channel
// names, channelTypes of another length; checked before anything is written) or the file cannot be
// written.
void writeExr(const std::string& path, const Image& image, const ExrHeader& header = {});

}  // namespace fluence::output
