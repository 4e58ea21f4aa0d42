#include "texture/image_loader.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>

#include "scene/package_files.h"

namespace fluence::texture {

namespace {

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// How the colour channels of a file read in `space` are made linear.
std::function<float(float)> decoder(const OIIO::ImageSpec& spec, SourceColorSpace space) {
    if (space == SourceColorSpace::Raw) return {};
    if (space == SourceColorSpace::SRGB) return srgbToLinear;
    std::string name = lowercase(spec.get_string_attribute("oiio:ColorSpace"));
    if (name.find("srgb") != std::string::npos && name.find("lin") == std::string::npos) return srgbToLinear;
    if (name.starts_with("gamma")) {
        float gamma = spec.get_float_attribute("oiio:Gamma", 2.2f);
        return [gamma](float v) { return std::pow(std::max(v, 0.0f), gamma); };
    }
    if (name.empty() && !spec.format.is_floating_point()) return srgbToLinear;
    return {};  // linear
}

}  // namespace

float srgbToLinear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

Image loadImage(const std::string& path, SourceColorSpace colorSpace) {
    // Straight (unassociated) colour as stored: OIIO would otherwise premultiply PNG and TIFF colour
    // by alpha, before the sRGB decoding that must see the stored values.
    OIIO::ImageSpec hints;
    hints.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(usd::fileForAsset(path), &hints);  // inside a USDZ package: its extracted copy
    if (!in) throw ImageLoadError("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.depth > 1) throw ImageLoadError("cannot read image '" + path + "': volume images are not supported");
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.alphaChannel = spec.alpha_channel;
    image.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw ImageLoadError("cannot read image '" + path + "': " + in->geterror());
    if (auto decode = decoder(spec, colorSpace))
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            if (static_cast<int>(i % image.channels) != image.alphaChannel) image.pixels[i] = decode(image.pixels[i]);
    return image;
}

}  // namespace fluence::texture
