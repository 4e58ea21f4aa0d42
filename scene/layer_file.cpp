#include "scene/layer_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <vector>

#include "scene/crate_reader.h"
#include "scene/mtlx_reader.h"
#include "scene/usda_parser.h"
#include "scene/usdz_package.h"

namespace fluence::usd {

namespace {

std::string lowercaseExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return extension;
}

// The layer held by the entry `entryName` of `package`, identified as "<package>[<entry>]" so
// that asset paths authored in it resolve inside the package (scene/asset_path.h).
std::unique_ptr<Layer> readPackagedLayer(const UsdzPackage& package, const std::string& entryName) {
    const std::string identifier = packagePath(package.path(), entryName);
    std::string_view bytes = package.bytes(entryName);
    if (isCrateHeader(bytes.substr(0, 8)))
        return readCrateBytes(std::vector<char>(bytes.begin(), bytes.end()), identifier);
    if (isMaterialXPath(entryName)) return readMaterialX(std::string(bytes), identifier);
    const std::string extension = lowercaseExtension(entryName);
    if (extension != ".usda" && extension != ".usd")
        throw FileError("'" + identifier + "' is not a USD layer (neither a crate nor a .usda or .usd text file)");
    return parseUsdaString(bytes, identifier);
}

}  // namespace

bool isMaterialXPath(const std::string& path) { return lowercaseExtension(path) == ".mtlx"; }

std::string missingFormatPlugin(const std::string& path) {
    const std::optional<PackagePath> packaged = splitInnermostPackagePath(path);
    const std::string extension = lowercaseExtension(packaged ? packaged->entry : path);
    return extension == ".abc" ? "Alembic" : extension == ".drc" ? "Draco" : "";
}

std::string unsupportedFormatMessage(const std::string& path) {
    return "'" + path + "' needs the " + missingFormatPlugin(path) +
           " plugin (a USD file format plugin Fluence does not have)";
}

std::unique_ptr<Layer> readLayerFile(const std::string& path) {
    if (!missingFormatPlugin(path).empty()) throw UnsupportedFormatError(unsupportedFormatMessage(path));
    if (isUsdzPath(path)) {  // a package file, or a package inside one: its root layer
        UsdzPackage package = UsdzPackage::open(path);
        if (package.entries().empty()) throw FileError("'" + path + "': the USDZ package holds no layer");
        const std::string& root = package.entries().front().name;
        // A root that is itself a package, or in a format Fluence has no plugin for (an Alembic
        // root, as in OpenUSD's usdchecker tests), goes through the packaged path, which names it;
        // any other root is read from the package already open.
        if (isUsdzPath(root) || !missingFormatPlugin(root).empty()) return readLayerFile(packagePath(path, root));
        return readPackagedLayer(package, root);
    }
    if (std::optional<PackagePath> packaged = splitInnermostPackagePath(path))
        return readPackagedLayer(UsdzPackage::open(packaged->package), packaged->entry);
    std::ifstream file(path, std::ios::binary);
    char start[8] = {};
    file.read(start, sizeof start);
    if (isCrateHeader(std::string_view(start, static_cast<std::size_t>(file.gcount())))) return readCrateFile(path);
    if (isMaterialXPath(path)) return readMaterialXFile(path);
    return parseUsdaFile(path);
}

}  // namespace fluence::usd
