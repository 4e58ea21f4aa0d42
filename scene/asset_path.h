// Asset path resolution, as USD's default resolver does it for files: an asset path is anchored at
// the directory of the layer that authored it.
#pragma once

#include <string>

namespace fluence::usd {

// The absolute, lexically normalized path of `authored` anchored at the directory of the layer
// `layerIdentifier` (a file path; a relative identifier counts from the current directory).
// Absolute paths are only normalized; empty paths and URIs ("scheme:...") are returned unchanged.
// Backslashes read as separators. Tokens such as <UDIM> are kept as written. In a layer inside a
// USDZ package ("/a/pkg.usdz[dir/layer.usdc]") relative paths resolve inside the package:
// "./tex.png" -> "/a/pkg.usdz[dir/tex.png]", in a nested package inside the innermost one:
// "/a/pkg.usdz[inner.usdz[dir/layer.usdc]]" -> "/a/pkg.usdz[inner.usdz[dir/tex.png]]".
// A search-relative path there ("tex/a.png", no leading "./" or "../") that names no entry beside
// the layer resolves, as OpenUSD's SdfComputeAssetPathRelativeToLayer does, beside the package's
// root layer (its first entry), then beside the (outermost) package file; when none exists, it is
// the path beside the layer.
std::string anchorAssetPath(const std::string& layerIdentifier, const std::string& authored);

// The absolute, lexically normalized form of a file path.
std::string normalizedAbsolutePath(const std::string& path);

// Whether a resolved asset path names an existing file; a path holding <UDIM> exists when any of
// the tiles 1001 to 1100 does. An entry of a USDZ package exists only when it can be read (not
// compressed or encrypted: usdz_package.h).
bool assetExists(const std::string& resolved);

}  // namespace fluence::usd
