// Reading back one string attribute of an image file's header (OpenImageIO), such as the
// "fluence/fingerprint" that `fluence render --resume` compares to know an output is already
// rendered (apps/render_command.cpp).
#pragma once

#include <string>

namespace fluence::output {

// The string attribute `name` of the header of the image at `path`; "" when the file cannot be
// read or has no such attribute.
std::string readStringAttribute(const std::string& path, const std::string& name);

}  // namespace fluence::output
