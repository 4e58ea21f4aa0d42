// Internal to output/: writes pixels through an OpenImageIO format plugin into a temporary
// file, then renames it into place (see atomic_file.h). Keeps the OIIO calls and their error
// handling in one place for every format Fluence writes.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>

namespace fluence::output {

// `format` is an OIIO plugin name ("openexr", "png"): the temporary file's name carries no
// extension, so the plugin is chosen by name. `pixels` are in `pixelFormat` (converted to each
// channel's type as written); by default in spec.format, or, when the spec has per-channel
// formats, packed in each channel's own type. Throws OutputError naming `path`.
void writeImageFile(const std::string& path, const char* format, const OIIO::ImageSpec& spec, const void* pixels,
                    OIIO::TypeDesc pixelFormat = OIIO::TypeUnknown);

}  // namespace fluence::output
