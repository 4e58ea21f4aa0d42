// Cryptomatte output, to Psyop's Cryptomatte specification (v1.2): ID mattes a compositor can
// pick objects and materials from, written into the beauty's EXR.
//
// Ids: a name (a prim path, UTF-8) is hashed with MurmurHash3_x86_32, seed 0. The 32 bits are then
// stored as a 32-bit float; so that float is never denormal, infinite or NaN, a hash whose exponent
// bits are all 0 or all 1 has its lowest exponent bit flipped (bit 23) — every reader applies the
// same rule (cryptomatteId).
// Channels, per layer of type name T (e.g. CryptoObject) and depth D (ranks): ceil(D / 2) RGBA
// layers T00, T01, ..., rank 2k in T0k.R (id) and T0k.G (coverage), rank 2k+1 in T0k.B and T0k.A,
// ranks by decreasing coverage (core/cryptomatte_film.h); empty ranks are id 0, coverage 0. Written
// as 32-bit float, listed as data channels (no colour transform applies), losslessly: a lossy
// compression of the header (dwaa, dwab, b44, b44a, pxr24) is replaced by zip.
// Header, per layer, under the key K = the first 7 hex digits of T's id:
//     cryptomatte/K/name        T
//     cryptomatte/K/hash        MurmurHash3_32
//     cryptomatte/K/conversion  uint32_to_float32
//     cryptomatte/K/manifest    {"name":"8 hex digits of its id",...}, the names the layer's channels hold
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/cryptomatte_film.h"
#include "core/image.h"
#include "core/name_table.h"
#include "output/exr_writer.h"

namespace fluence::output {

// MurmurHash3_x86_32 (Austin Appleby's public-domain hash) of `data`.
std::uint32_t murmurHash3_x86_32(std::string_view data, std::uint32_t seed = 0);
// The id bits `name` is stored as: its hash, exponent fixed as above.
std::uint32_t cryptomatteId(std::string_view name);
// Those bits read as the float stored in the id channels.
float cryptomatteIdFloat(std::uint32_t id);
// The 8 lower-case hex digits of an id, as the manifest writes it.
std::string cryptomatteHex(std::uint32_t id);
// The metadata key of a layer: the first 7 hex digits of its type name's id.
std::string cryptomatteKey(std::string_view typeName);

struct CryptomatteLayer {
    std::string typeName;    // e.g. "CryptoObject"
    const NameTable* names;  // what the film's name indices of this layer mean
};

// The union of two manifests (tiles of one image each name what they saw): `a`'s entries, then those
// of `b` whose names `a` lacks. Throws std::invalid_argument when either is not a JSON object of strings.
std::string mergeCryptomatteManifests(const std::string& a, const std::string& b);

// Appends the channels of every layer of `film` (layers[i] describes the film's layer i) to
// `image`, `depth` ranks each, and their metadata and data channels to `header`.
void appendCryptomatte(Image& image, ExrHeader& header, const CryptomatteFilm& film,
                       const std::vector<CryptomatteLayer>& layers, int depth);

}  // namespace fluence::output
