// USDZ packages: reading the zip archive a .usdz is, and USD's package-relative asset paths that
// address files inside one.
//
// Conventions:
//   - A package is a zip archive whose entries are stored uncompressed (the USDZ rule); its first
//     entry is the package's root layer. Compressed or encrypted entries, zip64 and multi-disk
//     archives are rejected. Every offset and size read from the archive is bounds-checked; a
//     damaged package throws FileError naming the package (and the entry when one is at fault).
//   - The file is memory-mapped read-only; entries are views into the mapping, which lives as
//     long as any copy of the UsdzPackage.
//   - A package-relative path is "<package>[<entry>]", e.g. "/assets/chair.usdz[textures/a.png]",
//     as USD's ArPackageUtils writes them; the entry is a path inside the archive with '/'
//     separators. Nested packages ("a.usdz[b.usdz[c.png]]") are not opened.
// Why: USD assets are shipped as .usdz files, whose layers and textures must be readable in place.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fluence::usd {

class UsdzPackage {
public:
    struct Entry {
        std::string name;         // the path inside the archive
        std::size_t offset = 0;   // where its bytes start in the package file
        std::size_t size = 0;
    };

    // Opens and indexes the package at `path`; throws FileError when it cannot be read or is not
    // a valid USDZ archive.
    static UsdzPackage open(const std::string& path);

    const std::string& path() const { return path_; }
    const std::vector<Entry>& entries() const { return entries_; }
    // The entry named `name`, or nullptr.
    const Entry* find(std::string_view name) const;
    std::string_view bytes(const Entry& entry) const;
    // The bytes of the entry named `name`; throws FileError naming the package and entry when
    // there is none.
    std::string_view bytes(std::string_view name) const;

private:
    std::string path_;
    std::shared_ptr<const std::string_view> mapping_;  // the whole file; unmapped with the last copy
    std::vector<Entry> entries_;
};

// A package-relative path split into its package file and the entry inside it.
struct PackagePath {
    std::string package;
    std::string entry;
};

// Splits "<package>[<entry>]"; nullopt for any other path.
std::optional<PackagePath> splitPackagePath(const std::string& path);

// "<package>[<entry>]".
std::string packagePath(const std::string& package, const std::string& entry);

// Whether `path` names a USDZ package file (by its extension, in any case).
bool isUsdzPath(const std::string& path);

// Whether the package-relative `path` names an entry of a readable package.
bool packagedEntryExists(const std::string& path);

}  // namespace fluence::usd
