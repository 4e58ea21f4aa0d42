#include "scene/package_files.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string_view>
#include <system_error>

#include "core/fnv_hash.h"
#include "scene/usda_parser.h"
#include "scene/usdz_package.h"

namespace fluence::usd {

namespace fs = std::filesystem;

namespace {

std::string hex(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

// Writes `bytes` to `target` through a uniquely named file renamed into place.
bool writeAtomically(const fs::path& target, std::string_view bytes) {
    std::error_code error;
    fs::create_directories(target.parent_path(), error);
    fs::path partial = target;
    partial += ".part" + std::to_string(::getpid());
    {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out) return false;
    }
    fs::rename(partial, target, error);
    if (error) fs::remove(partial, error);
    return fs::is_regular_file(target, error);
}

}  // namespace

std::string fileForAsset(const std::string& asset) {
    std::optional<PackagePath> packaged = splitInnermostPackagePath(asset);
    if (!packaged) return asset;
    try {
        UsdzPackage package = UsdzPackage::open(packaged->package);
        const UsdzPackage::Entry* entry = package.find(packaged->entry);
        if (!entry) return asset;
        std::string_view bytes = package.bytes(*entry);
        std::uint64_t key = fnv1a(bytes, fnv1a(packaged->entry + '\0', fnv1a(packaged->package + '\0')));
        std::error_code error;
        fs::path target = fs::temp_directory_path(error) / "fluence-usdz" / hex(key) / fs::path(entry->name).filename();
        if (error) return asset;
        if (fs::is_regular_file(target, error) && fs::file_size(target, error) == bytes.size()) return target.string();
        return writeAtomically(target, bytes) ? target.string() : asset;
    } catch (const FileError&) {
        return asset;
    }
}

}  // namespace fluence::usd
