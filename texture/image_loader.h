// Image files -> linear float pixels, through OpenImageIO.
//
// loadImage() reads the first subimage of any file OpenImageIO reads (EXR, HDR, PNG, JPEG, TIFF,
// ...) as 32-bit floats, top row first, and makes its colour channels linear as `colorSpace` says
// (the choices of UsdUVTexture's inputs:sourceColorSpace):
//   - Auto: as the file says (OpenImageIO's "oiio:ColorSpace"): "sRGB" is decoded with the sRGB
//     transfer function (IEC 61966-2-1), "GammaX.Y" / "GammaCorrected" with the power law of
//     oiio:Gamma, linear names are kept. A file that says nothing is sRGB when it stores integers
//     (8- and 16-bit PNG, JPEG, TIFF) and linear when it stores floats (EXR, HDR).
//   - Raw: the values as stored (data textures: normals, roughness, masks).
//   - SRGB: decoded as sRGB whatever the file says.
// Colour is read straight, as stored (not premultiplied by alpha; EXR files, premultiplied by
// definition, stay so), and the alpha channel is never decoded. Primaries are not converted: an
// image is taken to use the Rec.709 primaries of sRGB and of the rendering space.
//
// A file that cannot be read raises ImageLoadError naming it, with OpenImageIO's reason; callers
// (the delegate) turn that into a warning and a fallback. Nothing here is cached: the texture
// system that UsdUVTexture needs will sit beside this file and cache on top of it.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "texture/texture_types.h"

namespace fluence::texture {

struct Image {
    int width = 0, height = 0, channels = 0;
    int alphaChannel = -1;      // index of the alpha channel, or -1
    std::vector<float> pixels;  // width * height * channels, row-major, top row first, linear

    float at(int x, int y, int channel) const { return pixels[(std::size_t(y) * width + x) * channels + channel]; }
};

class ImageLoadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads the image at `path`: a file, or a package-relative asset path ("scene.usdz[tex/a.png]",
// scene/package_files.h), as dome and rect light textures name them.
Image loadImage(const std::string& path, SourceColorSpace colorSpace = SourceColorSpace::Auto);

// The sRGB electro-optical transfer function (IEC 61966-2-1): encoded value -> linear.
float srgbToLinear(float encoded);

}  // namespace fluence::texture
