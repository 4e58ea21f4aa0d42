// Reading a layer file in whichever format it is in: USD's binary crate (chosen by its first bytes,
// "PXR-USDC", whatever the extension: .usdc, or .usd), a MaterialX document (.mtlx, presented as
// USD's MaterialX file format plugin does: scene/mtlx_reader.h), else USDA text. A USDZ package
// (.usdz, scene/usdz_package.h) reads as its first entry, its root layer (when that entry is a
// package itself, as that package's root layer), and a package-relative path
// "pkg.usdz[inner.usdc]" or "pkg.usdz[inner.usdz[layer.usda]]" as that entry; such layers are
// identified by their package-relative path, so asset paths authored in them resolve inside the
// package.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "scene/layer.h"

namespace fluence::usd {

// Whether `path` names a MaterialX document (by its extension).
bool isMaterialXPath(const std::string& path);

// The USD file format plugin a layer in `path`'s format needs, which Fluence does not have:
// "Alembic" (.abc, usdAbc) or "Draco" (.drc, usdDraco); "" for any other path.
std::string missingFormatPlugin(const std::string& path);

// A layer file in a format that needs a USD file format plugin Fluence does not have.
class UnsupportedFormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "'x.abc' needs the Alembic plugin (a USD file format plugin Fluence does not have)".
std::string unsupportedFormatMessage(const std::string& path);

// Reads the layer file at `path`. Throws FileError when it cannot be read (or a crate is damaged),
// UnsupportedFormatError when its format needs a plugin (missingFormatPlugin) and ParseError on
// bad text.
std::unique_ptr<Layer> readLayerFile(const std::string& path);

}  // namespace fluence::usd
