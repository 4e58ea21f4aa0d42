#include "scene/layer_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "scene/crate_reader.h"
#include "scene/mtlx_reader.h"
#include "scene/usda_parser.h"

namespace fluence::usd {

bool isMaterialXPath(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension == ".mtlx";
}

std::unique_ptr<Layer> readLayerFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    char start[8] = {};
    file.read(start, sizeof start);
    if (isCrateHeader(std::string_view(start, static_cast<std::size_t>(file.gcount())))) return readCrateFile(path);
    if (isMaterialXPath(path)) return readMaterialXFile(path);
    return parseUsdaFile(path);
}

}  // namespace fluence::usd
