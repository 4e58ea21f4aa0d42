#include "color/ocio_config.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "color/color_management.h"

namespace OCIO = OCIO_NAMESPACE;

namespace fluence::color::detail {

// The text of config/ocio/fluence.ocio, generated at build time (see color/CMakeLists.txt).
extern const char kEmbeddedConfigText[];

namespace {
constexpr const char* kBuiltinDescription = "Fluence built-in config";
}  // namespace

LoadedConfig loadOcioConfig(const std::string& configPath) {
    std::string path = configPath;
    std::string where;
    if (!path.empty()) {
        where = path;
    } else if (const char* env = std::getenv("OCIO"); env != nullptr && *env != '\0') {
        path = env;
        where = path + " (from $OCIO)";
    }

    LoadedConfig loaded;
    try {
        if (path.empty()) {
            std::istringstream in{std::string(kEmbeddedConfigText)};
            loaded.config = OCIO::Config::CreateFromStream(in);
            loaded.description = kBuiltinDescription;
        } else {
            std::error_code ec;
            if (!std::filesystem::exists(path, ec))
                throw ColorError("cannot load OCIO config " + where + ": file does not exist");
            if (std::filesystem::is_directory(path, ec))
                throw ColorError("cannot load OCIO config " + where + ": is a directory");
            loaded.config = OCIO::Config::CreateFromFile(path.c_str());
            loaded.description = where;
        }
        loaded.config->validate();
    } catch (const ColorError&) {
        throw;
    } catch (const std::exception& e) {
        throw ColorError("cannot load OCIO config " + (path.empty() ? std::string(kBuiltinDescription) : where) + ": " +
                         e.what());
    }
    return loaded;
}

}  // namespace fluence::color::detail
