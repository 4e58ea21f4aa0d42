// UsdLuxShapingAPI: narrowing the emission of rect, disk, sphere and cylinder lights (and of the
// point and line lights they become) around the light's primary axis, its local -Z.
//
// With θ the angle between the axis and the direction ω light leaves in (UsdLux's
// θ_offAxis = acos(lightAxis · emissionDir)), the emitted radiance is multiplied by
//   cone    0 beyond θ_cutoff = coneAngle ("guaranteed to be zero"); inside, with softness s,
//           1 - smoothstep(θ_start, θ_cutoff, θ) with θ_start = (1 - s) θ_cutoff, so s = 0 is a
//           hard edge and s = 1 fades from the axis to the edge (s > 1 widens the fade further);
//   focus   lerp(f, focusTint, 1) with f = cos(θ)^focus (0 behind the light): "an off-axis cosine
//           power exponent" that pulls light towards the axis, tinting what it takes away
//           (black by default). focus = 0 leaves the emission alone.
// | attribute                     | type    | default | notes                                   |
// |-------------------------------|---------|---------|-----------------------------------------|
// | inputs:shaping:cone:angle     | float   | 90      | degrees, clamped to [0, 180]             |
// | inputs:shaping:cone:softness  | float   | 0       |                                          |
// | inputs:shaping:focus          | float   | 0       | negative values act as 0                 |
// | inputs:shaping:focusTint      | color3f | (0,0,0) |                                          |
// | inputs:shaping:ies:*          |         |         | not supported: the delegate warns        |
// The semantics of softness and focus follow the UsdLux documentation's formulas; the 24.x schema
// itself still says "TODO: clarify semantics" for both.
#pragma once

#include "core/rgb.h"
#include "render/light.h"
#include "render/scene_description.h"

namespace fluence::render {

class LightShaping {
public:
    LightShaping() = default;  // unshaped: factor 1 everywhere
    // `axis`: the light's primary axis in world space (unit).
    LightShaping(const LightShapingDesc& desc, const Vec3f& axis);

    bool active() const { return active_; }
    // The factor on radiance leaving in unit direction `emission`.
    RGB factor(const Vec3f& emission) const;
    // Bounds the share of the power a cosine emitter facing along the axis (oneSided) or an
    // emitter spreading light evenly over directions keeps: an upper bound for light selection.
    float powerFraction(bool oneSided) const;
    // Tightens the emission bounds of a light whose unshaped bounds are `bounds`: a one-sided
    // light emits no further than the cone from its normal; any other light emits within the cone
    // around the axis.
    LightBounds narrow(LightBounds bounds, bool oneSided) const;

private:
    bool active_ = false;
    Vec3f axis_;
    float cosCutoff_ = -1.0f, cutoff_ = 0.0f, softStart_ = 0.0f;
    float focus_ = 0.0f;
    RGB focusTint_;
};

}  // namespace fluence::render
