// The USD crate reader: binary layers (.usdc, and .usd files whose first bytes are "PXR-USDC")
// into the same Layer the USDA text reader builds for the equivalent text, so composition cannot
// tell which format a layer came from. crate_file.h reads the file's structure, crate_values.h its
// values; this file maps the specs.
//
// Specs map as the text reader fills them:
//   - the pseudo-root's fields are the layer metadata; subLayers and subLayerOffsets join into one
//     "subLayers" list of Reference values, primOrder becomes a "rootPrims" reorder entry;
//   - prim specs, in their parent's primChildren order, with specifier, typeName and metadata;
//     properties in `properties` order: attributes (typeName, custom, uniform variability,
//     default, timeSamples, connections, metadata) and relationships (targets, metadata);
//     variant sets and variants from variantSetChildren / variantChildren;
//   - fields whose name differs from the text keyword are renamed: documentation -> doc,
//     variantSetNames -> variantSets, variantSelection -> variants, layerRelocates -> relocates;
//     primOrder -> nameChildren and propertyOrder -> properties as reorder entries.
// Metadata values are untyped as in text (no type name, tokens as strings); a list op becomes one
// metadata entry per edit (explicit, add, prepend, append, delete, reorder); references,
// payloads, inherits and specializes are always lists (text may write a single item); a crate
// 0.7 single payload with neither asset nor prim is `payload = None`. Attribute values take the
// attribute's declared type name. A target or connection list op sets the spec's own op and paths
// (explicit, else prepend, else append, else add); its other edits are kept as "targetPaths" /
// "connectionPaths" metadata entries, as the text reader keeps `delete` and `reorder`. Specs
// carry the file as their location with line 0: a crate has no text positions.
//
// A damaged or unsupported file throws FileError whose message names the file and what is wrong.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scene/layer.h"
#include "scene/mapped_file.h"

namespace fluence::usd {

// Whether a file's first bytes are a crate file's magic, "PXR-USDC".
bool isCrateHeader(std::string_view firstBytes);

// Reads a crate layer from shared bytes (scene/mapped_file.h); `identifier` names it in errors and
// becomes Layer::identifier. Large numeric arrays are decoded on first use (crate_values.h) and
// keep `bytes` alive until then; a damaged one throws FileError then, naming `identifier`.
std::unique_ptr<Layer> readCrateBytes(SharedBytes bytes, const std::string& identifier);
// The same, from bytes in memory.
std::unique_ptr<Layer> readCrateBytes(std::vector<char> bytes, const std::string& identifier);

// Reads a crate layer file, memory-mapped (mapFile: read-only, kept mapped while a value still
// to be decoded refers to it).
std::unique_ptr<Layer> readCrateFile(const std::string& path);

}  // namespace fluence::usd
