// RGB radiometric quantities in the rendering colour space (linear Rec.709, see docs/COLOR.md).
//
// Fluence renders in RGB. Every colour that enters the render core has already been converted into
// the rendering space by the delegate; the render core never sees another space.
#pragma once

#include <cmath>

#include "core/vec.h"

namespace fluence {

using RGB = Vec3f;

// Relative luminance of linear Rec.709 (ITU-R BT.709 Y coefficients).
constexpr float luminance(const RGB& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

inline bool isBlack(const RGB& c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; }
inline bool isFinite(const RGB& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

}  // namespace fluence
