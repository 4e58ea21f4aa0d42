#include "output/preview_writer.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "output/atomic_file.h"
#include "output/image_file.h"

namespace fluence::output {

void writePreviewPng(const std::string& path, const Image& image, const color::ColorManagement& cm,
                     const std::string& display, const std::string& view) {
    if (image.width <= 0 || image.height <= 0)
        throw outputError(
            path, "image has no pixels (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    const std::size_t count = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    if (image.pixels.size() != count * image.channels.size())
        throw outputError(path, "image pixel buffer holds " + std::to_string(image.pixels.size()) +
                                    " floats, expected " + std::to_string(count * image.channels.size()));
    const int rgbIndex[3] = {image.channelIndex("R"), image.channelIndex("G"), image.channelIndex("B")};
    if (rgbIndex[0] < 0 || rgbIndex[1] < 0 || rgbIndex[2] < 0)
        throw outputError(path, "image has no R, G, B channels for a preview");

    std::vector<float> rgb(3 * count);
    const std::size_t stride = image.channels.size();
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + c] = image.pixels[i * stride + rgbIndex[c]];

    try {
        cm.applyDisplayView(display, view, rgb.data(), count);  // display-encoded, in [0, 1]
    } catch (const std::exception& e) {
        throw outputError(path, e.what());
    }

    std::vector<std::uint8_t> bytes(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const float v = rgb[i];  // already clamped, NaN-free
        bytes[i] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    }

    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    writeImageFile(path, "png", spec, bytes.data());
}

}  // namespace fluence::output
