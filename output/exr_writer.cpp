#include "output/exr_writer.h"

#include <OpenImageIO/half.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>

#include "output/atomic_file.h"
#include "output/image_file.h"

namespace fluence::output {

namespace {

void checkImage(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        throw outputError(
            path, "image has no pixels (" + std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
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

OIIO::TypeDesc oiioType(PixelType type) {
    switch (type) {
        case PixelType::Half: return OIIO::TypeDesc::HALF;
        case PixelType::Uint: return OIIO::TypeDesc::UINT;
        case PixelType::Float: break;
    }
    return OIIO::TypeDesc::FLOAT;
}

// The pixels packed in each channel's own type (OIIO's "native" per-channel layout). Integers are
// converted here because OIIO's float-to-integer conversion normalises (1.0 -> 2^32 - 1).
std::vector<unsigned char> nativePixels(const Image& image, const std::vector<PixelType>& types) {
    std::size_t pixelBytes = 0;
    for (PixelType t : types) pixelBytes += t == PixelType::Half ? 2 : 4;
    std::vector<unsigned char> out(pixelBytes * std::size_t(image.width) * std::size_t(image.height));
    unsigned char* at = out.data();
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const float v = image.pixels[i];
        switch (types[i % types.size()]) {
            case PixelType::Half: {
                const half h(v);
                std::memcpy(at, &h, 2);
                at += 2;
                break;
            }
            case PixelType::Float:
                std::memcpy(at, &v, 4);
                at += 4;
                break;
            case PixelType::Uint: {
                const std::uint32_t u = !(v > 0.0f)          ? 0u
                                        : v >= 4294967295.0f ? 4294967295u
                                                             : std::uint32_t(std::lround(double(v)));
                std::memcpy(at, &u, 4);
                at += 4;
                break;
            }
        }
    }
    return out;
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
    if (!header.channelTypes.empty() && header.channelTypes.size() != image.channels.size())
        throw outputError(path, "image has " + std::to_string(image.channels.size()) + " channels but " +
                                    std::to_string(header.channelTypes.size()) + " pixel types");
    const bool allFloat = std::all_of(header.channelTypes.begin(), header.channelTypes.end(),
                                      [](PixelType t) { return t == PixelType::Float; });

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
    if (!allFloat)
        for (PixelType t : header.channelTypes) spec.channelformats.push_back(oiioType(t));
    spec.attribute("compression", header.compression);
    spec.attribute("openexr:lineOrder", "increasingY");
    // float[8] named "chromaticities" is written by OIIO as the standard EXR Imf::Chromaticities.
    spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), header.chromaticities.data());
    spec.attribute("PixelAspectRatio", header.pixelAspectRatio);  // OIIO's name for EXR's pixelAspectRatio
    if (!header.colorSpace.empty()) {
        spec.attribute("colorSpace", header.colorSpace);
        spec.attribute("oiio:ColorSpace", header.colorSpace);
    }
    if (!header.colorInteropId.empty()) spec.attribute("colorInteropID", header.colorInteropId);
    for (const auto& [name, value] : header.matrices) spec.attribute(name, OIIO::TypeMatrix44, value.data());
    for (const auto& [name, value] : header.strings) spec.attribute(name, value);
    for (const auto& [name, value] : header.floats) spec.attribute(name, value);
    if (!header.dataChannels.empty()) spec.attribute("fluence/dataChannels", join(header.dataChannels, ","));

    if (allFloat) {
        writeImageFile(path, "openexr", spec, image.pixels.data());
        return;
    }
    const std::vector<unsigned char> native = nativePixels(image, header.channelTypes);
    writeImageFile(path, "openexr", spec, native.data());
}

}  // namespace fluence::output
