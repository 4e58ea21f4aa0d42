// UsdLuxShapingAPI: narrowing the emission of rect, disk, sphere and cylinder lights (and of the
// point and line lights they become) around the light's primary axis, its local -Z, and of a
// UsdLux mesh light's triangles, each around its own front normal (render/lights/triangle_light.h).
//
// With θ the angle between the axis and the direction ω light leaves in (UsdLux's
// θ_offAxis = acos(lightAxis · emissionDir)), the emitted radiance is multiplied by
//   cone    0 beyond θ_cutoff = coneAngle ("guaranteed to be zero"); inside, with softness s,
//           1 - smoothstep(θ_start, θ_cutoff, θ) with θ_start = (1 - s) θ_cutoff, so s = 0 is a
//           hard edge and s = 1 fades from the axis to the edge (s is clamped to [0, 1]);
//   focus   lerp(f, focusTint, 1) with f = |cos θ|^focus: "an off-axis cosine power exponent"
//           that pulls light towards the axis, tinting what it takes away (black by default).
//           focus = 0 leaves the emission alone.
//   IES     the profile's factor towards ω in the light's frame (render/ies_profile.h: angle
//           scale and normalization applied), when inputs:shaping:ies:file names one.
// | attribute                     | type    | default | notes                                   |
// |-------------------------------|---------|---------|-----------------------------------------|
// | inputs:shaping:cone:angle     | float   | 90      | degrees, clamped to [0, 180]             |
// | inputs:shaping:cone:softness  | float   | 0       |                                          |
// | inputs:shaping:focus          | float   | 0       | negative values act as 0                 |
// | inputs:shaping:focusTint      | color3f | (0,0,0) |                                          |
// | inputs:shaping:ies:file       | asset   | none    | texture/ies_file.h reads it              |
// | inputs:shaping:ies:angleScale | float   | 0       | render/ies_profile.h                     |
// | inputs:shaping:ies:normalize  | bool    | false   | render/ies_profile.h                     |
// Softness and focus follow the clarified UsdLux documentation (OpenUSD PR 3182, as hdEmbree
// implements it): softness outside [0, 1] is clamped, and focus takes the absolute value of the
// cosine, so a sphere light whose cone passes 90 degrees is focused along both ends of its axis.
//
// A light with a profile samples the directions it emits in (sampleDirection, for light tracing,
// bdpt light subpaths and sppm photons) from a piecewise-constant density over a grid of
// (θ, φ) cells in the light's frame, each cell weighted by the largest luminance of the whole
// shaping factor at nine points in it, times sin θ: proportional to the emission where the
// profile is smooth within a cell, and positive wherever the profile emits.
#pragma once

#include <memory>
#include <optional>

#include "core/matrix.h"
#include "core/rgb.h"
#include "render/ies_profile.h"
#include "render/light.h"
#include "render/light_image_distribution.h"
#include "render/scene_description.h"

namespace fluence::render {

// The frame a shaping is evaluated in: its axis, and the X and Y axes that orient an IES profile
// about it (the light's local X and Y, made perpendicular to the axis).
struct ShapingFrame {
    Vec3f x{1.0f, 0.0f, 0.0f}, y{0.0f, 1.0f, 0.0f}, axis{0.0f, 0.0f, 1.0f};
    ShapingFrame() = default;
    ShapingFrame(const Vec3f& axis, const Matrix4& lightToWorld);
    // `d` in this frame's coordinates: what a shaping built about the default frame takes (one
    // shaping shared by emitters that each have their own frame, as a mesh light's triangles do).
    Vec3f toLocal(const Vec3f& d) const { return {dot(d, x), dot(d, y), dot(d, axis)}; }
};

class LightShaping {
public:
    LightShaping() = default;  // unshaped: factor 1 everywhere
    // `axis`: the light's primary axis in world space (unit); `lightToWorld` orients an IES
    // profile about it (its local X and Y axes).
    LightShaping(const LightShapingDesc& desc, const Vec3f& axis, const Matrix4& lightToWorld);

    bool active() const { return active_; }
    // The factor on radiance leaving in unit direction `emission`.
    RGB factor(const Vec3f& emission) const;
    // Bounds the share of the power a cosine emitter facing along the axis (oneSided) or an
    // emitter spreading light evenly over directions keeps (an upper bound for light selection),
    // times an IES profile's mean factor over the sphere.
    float powerFraction(bool oneSided) const;
    // Tightens the emission bounds of a light whose unshaped bounds are `bounds`: a one-sided
    // light emits no further than the cone from its normal; any other light emits within the cone
    // around the axis. The power is scaled by the factor's peak (1 for a cone, which only takes
    // light away), not by powerFraction: the cone itself already keeps the light tree's importance
    // at 0 outside it, and inside it the light delivers its unshaped irradiance, which the
    // importance must still bound (scaling by the cone's share as well made a narrow spot light
    // beside a dome hundreds of times less likely to be chosen than its light warrants).
    LightBounds narrow(LightBounds bounds, bool oneSided) const;

    // Whether emission directions are drawn by sampleDirection (a light with an IES profile).
    bool samplesDirections() const { return ies_ != nullptr; }
    struct DirectionSample {
        Vec3f direction;
        float pdf = 0.0f;  // per unit solid angle
    };
    std::optional<DirectionSample> sampleDirection(Vec2f u) const;
    float directionPdf(const Vec3f& emission) const;

private:
    float iesFactor(const Vec3f& emission) const;
    Vec3f direction(float theta, float phi) const;
    void buildDirections();

    bool active_ = false;
    Vec3f axis_, xAxis_, yAxis_;
    float cosCutoff_ = -1.0f, cutoff_ = 0.0f, softStart_ = 0.0f;
    float focus_ = 0.0f;
    RGB focusTint_;
    std::shared_ptr<const IesProfile> ies_;
    float iesMean_ = 1.0f;  // the profile's mean factor over the sphere
    float peak_ = 1.0f;     // the largest luminance of factor() over the directions
    ImageDistribution directions_;
};

}  // namespace fluence::render
