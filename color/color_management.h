// Colour management for Fluence (OpenColorIO 2.1 behind a small interface).
//
// Fluence renders in one space, linear Rec.709 ("lin_rec709", see core/rgb.h). Colours authored in
// other spaces (sRGB textures, ACEScg values, ...) are converted into it once, when they enter the
// renderer; display transforms are applied only when writing previews. The config is, in order of
// precedence: an explicit path, $OCIO (when set and non-empty, as in every OCIO application), or the
// Fluence config config/ocio/fluence.ocio, which is embedded in the library at build time.
//
// OCIO headers stay out of this header. A ColorManagement is cheap to copy (copies share the
// config and the processor cache) and every const member function may be called from several
// threads at once.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/rgb.h"

namespace fluence::color {

// Thrown when a config cannot be loaded or a colour space, display or view is unknown.
class ColorError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A conversion into the rendering space, resolved once (ColorManagement::conversionToRenderingSpace):
// applying it takes no lock, for use per texture lookup. Default-constructed: the identity.
class ColorConversion {
public:
    ColorConversion() = default;
    bool isIdentity() const { return !processor_; }
    RGB apply(RGB c) const;

private:
    friend class ColorManagement;
    struct Processor;
    explicit ColorConversion(std::shared_ptr<const Processor> processor) : processor_(std::move(processor)) {}
    std::shared_ptr<const Processor> processor_;
};

class ColorManagement {
public:
    // The rendering (and scene_linear) space: every colour in the render core is in this space.
    static constexpr const char* kRenderingSpace = "lin_rec709";

    // Loads the config: `configPath` if non-empty, else $OCIO if set and non-empty, else the
    // embedded Fluence config. The config is validated. Throws ColorError (naming the file) when
    // the config cannot be read, does not validate, or has no colour space (or alias) named
    // kRenderingSpace.
    static ColorManagement load(const std::string& configPath = {});

    // "Fluence built-in config", or the path of the loaded file (with "(from $OCIO)" if so).
    std::string configDescription() const;

    // True if `space` names a colour space, alias or role of the config ("" means the rendering space).
    bool hasColorSpace(const std::string& space) const;

    // Converts `count` RGB triples (interleaved, 3*count floats) in place from `fromSpace` (a colour
    // space name, alias or role of the config; "" means the rendering space) to the rendering
    // space. Throws ColorError naming the space if it is unknown.
    void toRenderingSpace(const std::string& fromSpace, float* rgb, std::size_t count) const;
    RGB toRenderingSpace(const std::string& fromSpace, RGB c) const;
    // The same conversion, resolved once. Throws ColorError naming the space if it is unknown.
    ColorConversion conversionToRenderingSpace(const std::string& fromSpace) const;

    // Applies the display/view transform to `count` rendering-space RGB triples in place. The
    // result is display-encoded and clamped to [0, 1] (NaN becomes 0). "" means the config's
    // default display, and that display's default view. Throws ColorError for an unknown
    // display or view.
    void applyDisplayView(const std::string& display, const std::string& view, float* rgb, std::size_t count) const;

    std::string defaultDisplay() const;
    // Default view of `display` ("" means the default display). Throws ColorError if unknown.
    std::string defaultView(const std::string& display) const;

    // CIE xy chromaticities of the rendering space, {Rx, Ry, Gx, Gy, Bx, By, Wx, Wy}, for EXR
    // headers: Rec.709 primaries, D65 white (ITU-R BT.709-6, table 1, items 1.3 and 1.4).
    static std::array<float, 8> renderingChromaticities();

private:
    struct Impl;
    explicit ColorManagement(std::shared_ptr<const Impl> impl);
    std::shared_ptr<const Impl> impl_;
};

}  // namespace fluence::color
