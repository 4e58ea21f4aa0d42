#include "output/image_file.h"

#include "output/atomic_file.h"

namespace fluence::output {

void writeImageFile(const std::string& path, const char* format, const OIIO::ImageSpec& spec, const void* pixels,
                    OIIO::TypeDesc pixelFormat) {
    AtomicFile file(path);
    auto out = OIIO::ImageOutput::create(format);
    if (!out) file.fail(std::string("OpenImageIO has no ") + format + " writer (" + OIIO::geterror() + ")");
    if (!out->open(file.tempPath(), spec)) file.fail(out->geterror());
    // Per-channel formats: the pixels are in each channel's own type (OIIO's "native" layout).
    if (pixelFormat == OIIO::TypeUnknown && spec.channelformats.empty()) pixelFormat = spec.format;
    if (!out->write_image(pixelFormat, pixels)) {
        const std::string error = out->geterror();
        out->close();
        file.fail(error);
    }
    if (!out->close()) file.fail(out->geterror());
    out.reset();
    file.commit();
}

}  // namespace fluence::output
