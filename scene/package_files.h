// Files on disk for assets inside USDZ packages, for readers that only open files by name
// (OpenImageIO's texture system).
//
// Conventions: a packaged asset "/abs/pkg.usdz[textures/a.png]" is extracted once to
// <temp directory>/fluence-usdz/<hash>/a.png, where the hash covers the package path, the entry
// name and the entry's bytes, so a changed package never reuses a stale copy. The copy is written
// under a unique name and renamed into place, so concurrent renders never see half a file.
// Why: OpenImageIO 2.4's TextureSystem cannot read from memory, and an uncompressed entry copies
// quickly; the copy keeps the extension OpenImageIO picks its reader by.
#pragma once

#include <string>

namespace fluence::usd {

// The path of a file holding the asset at the resolved path `asset`: `asset` itself unless it is
// package-relative; then the extracted copy of the entry. Returns `asset` unchanged when the
// package or entry cannot be read or the copy cannot be written (opening it then fails, naming it).
std::string fileForAsset(const std::string& asset);

}  // namespace fluence::usd
