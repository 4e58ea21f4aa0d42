#include "output/exr_writer.h"

#include <OpenImageIO/imageio.h>

#include <set>

#include "output/atomic_file.h"
#include "output/image_file.h"

namespace fluence::output {

namespace {

void checkImage(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        throw outputError(path, "image has no pixels (" + std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + ")");
    if (image.channels.empty()) throw outputError(path, "image has no channels");
    const std::size_t expected =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * image.channels.size();
    if (image.pixels.size() != expected)
        throw outputError(path, "image pixel buffer holds " + std::to_string(image.pixels.size()) +
                                    " floats, expected " + std::to_string(expected) + " (" +
                                    std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                                    std::to_string(image.channels.size()) + " channels)");
    std::set<std::string> seen;
    for (const auto& name : image.channels) {
        if (name.empty()) throw outputError(path, "image has a channel with an empty name");
        if (!seen.insert(name).second) throw outputError(path, "image has two channels named '" + name + "'");
    }
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const auto& item : items) {
        if (!out.empty()) out += separator;
        out += item;
    }
    return out;
}

}  // namespace

void writeExr(const std::string& path, const Image& image, const ExrHeader& header) {
    checkImage(path, image);

    OIIO::ImageSpec spec(image.width, image.height, static_cast<int>(image.channels.size()), OIIO::TypeDesc::FLOAT);
    spec.channelnames = image.channels;
    if (header.fullWidth > 0) {
        spec.x = header.x;
        spec.y = header.y;
        spec.full_width = header.fullWidth;
        spec.full_height = header.fullHeight;
    }
    // OIIO's alpha/z channel guesses from names ("A", "Z") only matter to OIIO's own compositing;
    // Fluence writes what it has, so leave them unset.
    spec.alpha_channel = -1;
    spec.z_channel = -1;
    spec.attribute("compression", "zip");
    spec.attribute("openexr:lineOrder", "increasingY");
    // float[8] named "chromaticities" is written by OIIO as the standard EXR Imf::Chromaticities.
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), header.chromaticities.data());
    spec.attribute("PixelAspectRatio", header.pixelAspectRatio);  // OIIO's name for EXR's pixelAspectRatio
    if (!header.colorSpace.empty()) {
        spec.attribute("colorSpace", header.colorSpace);
        spec.attribute("oiio:ColorSpace", header.colorSpace);
    }
    for (const auto& [name, value] : header.strings) spec.attribute(name, value);
    for (const auto& [name, value] : header.floats) spec.attribute(name, value);
    if (!header.dataChannels.empty()) spec.attribute("fluence/dataChannels", join(header.dataChannels, ","));

    writeImageFile(path, "openexr", spec, image.pixels.data());
}

}  // namespace fluence::output
