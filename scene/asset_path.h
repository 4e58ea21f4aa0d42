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
std::string anchorAssetPath(const std::string& layerIdentifier, const std::string& authored);

// The absolute, lexically normalized form of a file path.
std::string normalizedAbsolutePath(const std::string& path);

// Whether a resolved asset path names an existing file; a path holding <UDIM> exists when any of
// the tiles 1001 to 1100 does.
bool assetExists(const std::string& resolved);

}  // namespace fluence::usd
