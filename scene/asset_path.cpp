#include "scene/asset_path.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "scene/usdz_package.h"

namespace fluence::usd {

namespace fs = std::filesystem;

namespace {

// "http://...", "omniverse://...", "anon:...": a scheme of two or more characters (one letter
// would be a Windows drive) made of letters, digits, '+', '-' and '.', then ':'.
bool isUri(const std::string& path) {
    std::size_t colon = path.find(':');
    if (colon == std::string::npos || colon < 2 || !std::isalpha(static_cast<unsigned char>(path[0]))) return false;
    return std::all_of(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    });
}

fs::path absoluteOf(const fs::path& path) {
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    return error ? path : absolute;
}

}  // namespace

std::string normalizedAbsolutePath(const std::string& path) {
    return absoluteOf(fs::path(path)).lexically_normal().generic_string();
}

std::string anchorAssetPath(const std::string& layerIdentifier, const std::string& authored) {
    if (authored.empty() || isUri(authored)) return authored;
    std::string path = authored;
    std::replace(path.begin(), path.end(), '\\', '/');
    fs::path asset(path);
    if (asset.is_absolute()) return asset.lexically_normal().generic_string();
    if (auto packaged = splitInnermostPackagePath(layerIdentifier)) {  // a layer inside a USDZ package
        auto file = splitPackagePath(packaged->package);               // the outer package file of a nested package
        const std::string outerFile = normalizedAbsolutePath(file ? file->package : packaged->package);
        const std::string package = file ? packagePath(outerFile, file->entry) : outerFile;
        auto besideEntry = [&](const std::string& entry) {
            return packagePath(package, (fs::path(entry).parent_path() / asset).lexically_normal().generic_string());
        };
        const std::string anchored = besideEntry(packaged->entry);
        if (path.front() == '.' || packagedEntryExists(anchored)) return anchored;
        // A search-relative path (SdfComputeAssetPathRelativeToLayer): beside the package's root
        // layer, then beside the package file, else (not found) as anchored.
        if (std::string root = packageRootLayer(package); !root.empty())
            if (std::string besideRoot = besideEntry(root); packagedEntryExists(besideRoot)) return besideRoot;
        std::error_code error;
        const fs::path besidePackage = (fs::path(outerFile).parent_path() / asset).lexically_normal();
        return fs::is_regular_file(besidePackage, error) ? besidePackage.generic_string() : anchored;
    }
    fs::path directory = absoluteOf(fs::path(layerIdentifier)).parent_path();
    return (directory / asset).lexically_normal().generic_string();
}

bool assetExists(const std::string& resolved) {
    if (resolved.empty()) return false;
    if (splitPackagePath(resolved)) return packagedEntryProblem(resolved).empty();  // there, and readable
    std::error_code error;
    std::size_t udim = resolved.find("<UDIM>");
    if (udim == std::string::npos) return fs::is_regular_file(resolved, error);
    for (int tile = 1001; tile <= 1100; ++tile) {
        std::string candidate = resolved;
        candidate.replace(udim, 6, std::to_string(tile));
        if (fs::is_regular_file(candidate, error)) return true;
    }
    return false;
}

}  // namespace fluence::usd
