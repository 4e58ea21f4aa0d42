// 8-bit PNG previews of resolved images, display-transformed through OCIO.
#pragma once

#include <string>

#include "color/color_management.h"
#include "core/image.h"

namespace fluence::output {

// Takes the R, G, B channels of `image` (scene-linear, rendering space), applies the display/view
// transform of `cm` ("" = the config's default display, and its default view), quantises to 8 bits
// with rounding (round(v * 255)) and writes an RGB PNG atomically, row 0 at the top. Throws
// OutputError naming `path` if the image lacks R, G or B, is inconsistent, the display or view is
// unknown, or the file cannot be written.
void writePreviewPng(const std::string& path, const Image& image, const color::ColorManagement& cm,
                     const std::string& display = "", const std::string& view = "");

}  // namespace fluence::output
