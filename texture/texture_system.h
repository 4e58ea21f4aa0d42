// Filtered, mip-mapped texture lookups for UsdUVTexture, through OpenImageIO's TextureSystem.
//
// open() names a file once per material input and returns a Texture: the OIIO handle, how many
// channels the file has, and the colour conversion its values need to reach the rendering space
// (resolved once through OpenColorIO, color/color_management.h):
//   - Raw: none (data textures: normals, roughness, masks).
//   - SRGB: from the config's "sRGB" texture space.
//   - Auto: the file's own colour space (OpenImageIO's "oiio:ColorSpace") when the config knows it;
//     otherwise sRGB for files storing integers (PNG, JPEG, 8/16-bit TIFF) and linear for floats
//     (EXR, HDR), as UsdUVTexture specifies.
// The conversion applies to RGB after filtering (OIIO filters the stored values; alpha is never
// converted). A grey file reads as (g, g, g, 1), grey-alpha as (g, g, g, a), RGB as (r, g, b, 1).
//
// Coordinates are USD's: st (0, 0) is the image's bottom-left corner, t grows upwards. UDIM sets
// (a file name holding <UDIM>) are resolved by OpenImageIO: tile 1001 + floor(s) + 10 * floor(t).
// Files without mip levels are mip-mapped on first use ("automip"), so a filter footprint of many
// texels costs what one texel does; within a level the filter is bilinear (exact at texel
// centres) unless the lookup asks for the nearest texel or bicubic. Lookups are thread-safe; the
// per-thread state is OIIO's.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "color/color_management.h"
#include "texture/texture_types.h"

namespace fluence::texture {

class TextureSystem {
public:
    struct Texture;  // an opened file, owned by the TextureSystem

    explicit TextureSystem(color::ColorManagement colors);
    ~TextureSystem();
    TextureSystem(const TextureSystem&) = delete;
    TextureSystem& operator=(const TextureSystem&) = delete;

    // Opens `path` (or a UDIM pattern). Returns nullptr and sets `error` (naming the file) when
    // it cannot be read; a UDIM set is readable when at least one tile is.
    // `namedSpace`, when not empty, is the colour space of the config the file's values are in (a
    // MaterialX colorspace such as "acescg"); it overrides `colorSpace`.
    const Texture* open(const std::string& path, SourceColorSpace colorSpace, std::string& error,
                        const std::string& namedSpace = "");

    // The filtered RGBA value at st; false where there is no data (an absent UDIM tile).
    // `filter` is the filter within a mip level (Closest: the nearest texel of the level).
    bool lookup(const Texture& texture, float s, float t, const Footprint& footprint, Wrap wrapS, Wrap wrapT,
                std::array<float, 4>& rgba, Filter filter = Filter::Linear) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fluence::texture
