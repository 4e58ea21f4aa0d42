// The small vocabulary of texture reads, shared by the scene description, the image loader and
// the texture system (no OpenImageIO here).
#pragma once

namespace fluence::texture {

// UsdUVTexture inputs:sourceColorSpace: how stored values become rendering-space values.
enum class SourceColorSpace { Auto, Raw, SRGB };

// UsdUVTexture inputs:wrapS / wrapT outside [0, 1].
enum class Wrap { Black, Clamp, Repeat, Mirror };

// How a lookup filters within a mip level (MaterialX filtertype): the nearest texel, bilinear
// (exact at texel centres) or bicubic.
enum class Filter { Closest, Linear, Cubic };

// The texture-space footprint of a lookup: how st changes across one pixel along the screen's
// x and y (zero: the finest level, bilinear).
struct Footprint {
    float dsdx = 0.0f, dtdx = 0.0f, dsdy = 0.0f, dtdy = 0.0f;
};

}  // namespace fluence::texture
