#include "output/exr_channels.h"

#include <OpenImageIO/imageio.h>

#include <memory>

#include "output/atomic_file.h"
#include "output/image_file.h"

namespace fluence::output {

namespace {

std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw ImageReadError("cannot read " + path + ": " + OIIO::geterror());
    return in;
}

}  // namespace

Image readImageChannels(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = openImage(path);
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height, std::vector<std::string>(spec.channelnames.begin(), spec.channelnames.end()));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw ImageReadError("cannot read " + path + ": " + in->geterror());
    return image;
}

void writeExrLike(const std::string& source, const std::string& path, const Image& image) {
    OIIO::ImageSpec spec = openImage(source)->spec();
    if (spec.width != image.width || spec.height != image.height)
        throw OutputError("cannot write " + path + ": the image is not the size of " + source);
    spec.nchannels = int(image.channelCount());
    spec.channelnames = image.channels;
    spec.channelformats.clear();
    spec.set_format(OIIO::TypeDesc::FLOAT);
    spec.alpha_channel = image.channelIndex("A");
    spec.z_channel = image.channelIndex("Z");
    writeImageFile(path, "openexr", spec, image.pixels.data(), OIIO::TypeDesc::FLOAT);
}

}  // namespace fluence::output
