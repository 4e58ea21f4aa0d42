// USDZ packages: reading the zip archive a .usdz is, and USD's package-relative asset paths that
// address files inside one.
//
// Conventions:
//   - A package is a zip archive whose entries are stored uncompressed (the USDZ rule); its first
//     entry is the package's root layer. As in OpenUSD's usdz resolver, a compressed or encrypted
//     entry fails only when it is read (bytes() throws FileError naming the package and entry):
//     the package opens, and its other entries read. Zip64 and multi-disk archives are rejected.
//     Every offset and size read from the archive is bounds-checked; a damaged package throws
//     FileError naming the package (and the entry when one is at fault).
//   - The file is memory-mapped read-only; entries are views into the mapping, which lives as
//     long as any copy of the UsdzPackage.
//   - A package-relative path is "<package>[<entry>]", e.g. "/assets/chair.usdz[textures/a.png]",
//     as USD's ArPackageUtils writes them; the entry is a path inside the archive with '/'
//     separators. Packages nest: "a.usdz[b.usdz[c.png]]" is the entry c.png of the package b.usdz
//     stored in a.usdz, and "a.usdz[b.usdz]" opens as that inner package (a view into a.usdz's
//     mapping, no copy).
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
        std::string name;        // the path inside the archive
        std::size_t offset = 0;  // where its bytes start in the package file
        std::size_t size = 0;
        std::string unreadable;  // why its bytes cannot be read ("compressed", "encrypted"), or empty
    };

    // Opens and indexes the package at `path`, a file or a package-relative path naming a package
    // inside a package; throws FileError when it cannot be read or is not a valid USDZ archive.
    static UsdzPackage open(const std::string& path);

    const std::string& path() const { return path_; }
    const std::vector<Entry>& entries() const { return entries_; }
    // The entry named `name`, or nullptr.
    const Entry* find(std::string_view name) const;
    // The bytes of an entry; throws FileError naming the package and entry when the entry is
    // compressed or encrypted.
    std::string_view bytes(const Entry& entry) const;
    // The bytes of the entry named `name`; throws FileError naming the package and entry when
    // there is none or it cannot be read.
    std::string_view bytes(std::string_view name) const;

private:
    std::string path_;
    std::shared_ptr<const std::string_view> mapping_;  // the whole file; unmapped with the last copy
    std::string_view archive_;                         // this package's bytes within the mapping
    std::vector<Entry> entries_;
};

// A package-relative path split into its package file and the entry inside it.
struct PackagePath {
    std::string package;
    std::string entry;
};

// Splits "<package>[<entry>]" at the outermost package: "a.usdz[b.usdz[c.png]]" into the file
// "a.usdz" and the entry "b.usdz[c.png]"; nullopt for any other path.
std::optional<PackagePath> splitPackagePath(const std::string& path);

// Splits at the innermost package: "a.usdz[b.usdz[c.png]]" into the package "a.usdz[b.usdz]"
// and its entry "c.png"; nullopt for a path that is not package-relative.
std::optional<PackagePath> splitInnermostPackagePath(const std::string& path);

// "<package>[<entry>]"; a package-relative `package` nests: ("a.usdz[b.usdz]", "c.png") gives
// "a.usdz[b.usdz[c.png]]".
std::string packagePath(const std::string& package, const std::string& entry);

// Whether `path` names a USDZ package (by its extension, in any case): a file, or the innermost
// entry of a package-relative path ("a.usdz[b.usdz]").
bool isUsdzPath(const std::string& path);

// The root layer (first entry) of the package at `package` (a file or a package-relative path);
// "" when it cannot be read or is empty.
std::string packageRootLayer(const std::string& package);

// Whether the package-relative `path` names an entry of a readable package.
bool packagedEntryExists(const std::string& path);

// Why the entry the package-relative `path` names cannot be read ("cannot find '<path>'", or the
// FileError of a compressed or encrypted entry); "" when it can.
std::string packagedEntryProblem(const std::string& path);

}  // namespace fluence::usd
