// Loading an OpenColorIO config the way every Fluence tool does: an explicit path, else $OCIO,
// else the built-in config embedded at build time. Internal to color/ (it includes OCIO).
#pragma once

#include <OpenColorIO/OpenColorIO.h>

#include <string>

namespace fluence::color::detail {

struct LoadedConfig {
    OCIO_NAMESPACE::ConstConfigRcPtr config;
    std::string description;  // "Fluence built-in config", a path, or "<path> (from $OCIO)"
};

// Loads and validates the config. Throws ColorError naming the file when it cannot be read or
// does not validate.
LoadedConfig loadOcioConfig(const std::string& configPath);

}  // namespace fluence::color::detail
