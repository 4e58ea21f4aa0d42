#include "output/exr_attributes.h"

#include <OpenImageIO/imageio.h>

#include <memory>

namespace fluence::output {

std::string readStringAttribute(const std::string& path, const std::string& name) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        (void)OIIO::geterror();  // not an error here: the caller only asks whether it is there
        return "";
    }
    return in->spec().get_string_attribute(name);
}

}  // namespace fluence::output
