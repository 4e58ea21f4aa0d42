// An IES profile as UsdLux's ShapingAPI applies it (inputs:shaping:ies:*): the file's candela
// table (texture/ies_file.h) unfolded over the whole sphere and looked up by direction.
//
// Directions are given as the light-space polar angles UsdLux's clarified documentation (OpenUSD
// PR 3182) and hdEmbree's reference implementation use: theta is the angle between the emission
// direction and the light's local -Z axis, so the profile's nadir (vertical angle 0) points along
// the light's -Z, the way every UsdLux light faces; phi is the angle about Z of the reversed
// emission direction, from the light's +X towards +Y (so horizontal angle 0 lights the light's -X
// side and 90 its -Y side, as hdEmbree evaluates it).
//
// - Symmetry: a single horizontal angle is symmetric about the vertical axis; 0-90 is mirrored
//   about the 90 and then the 180 degree planes; 0-180 and 90-270 about the 180 and 270 degree
//   planes. Vertical angles outside the file's range emit nothing.
// - Interpolation: bilinear in (vertical, horizontal) angle.
// - angleScale s (UsdLux's inputs:shaping:ies:angleScale, as RenderMan and hdEmbree apply it):
//   theta_ies = (theta - pi) / (1 + s) + pi, clamped to [0, pi]; s = 0 leaves the profile alone,
//   and the scaling keeps the zenith in place (a downlight's beam widens as s goes below 0).
//   s <= -1 is read as 0.
// - normalize (inputs:shaping:ies:normalize): the candela values are divided by the profile's
//   mean intensity, the integral of the unscaled candela over the sphere divided by 4 pi (by 2 pi
//   when the vertical angles span at most about 90 degrees, a hemisphere, as hdEmbree, Karma and
//   RenderMan divide), so the profile shapes the light and a uniform profile of any value
//   leaves it as it was.
#pragma once

#include <vector>

#include "texture/ies_file.h"

namespace fluence::render {

class IesProfile {
public:
    IesProfile(const texture::IesTable& table, float angleScale, bool normalize);

    // The candela value for light-space polar angles (radians) before angle scale and normalization.
    float candela(float theta, float phi) const;
    // What the light's radiance is multiplied by towards (theta, phi): angle-scaled, normalized.
    float factor(float theta, float phi) const;
    // The profile's mean intensity over the sphere (or hemisphere), as `normalize` divides by it.
    float meanIntensity() const { return mean_; }

private:
    std::vector<float> vertical_;    // radians, increasing
    std::vector<float> horizontal_;  // radians, increasing, spanning exactly 2 pi from the first
    std::vector<float> values_;      // horizontal-major, vertical_.size() per horizontal angle
    float profileScale_ = 1.0f;      // 1 + angleScale
    float mean_ = 0.0f;
    float scale_ = 1.0f;  // 1 / mean when normalized
};

}  // namespace fluence::render
