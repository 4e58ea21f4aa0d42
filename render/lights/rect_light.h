// UsdLux RectLight: a flat rectangle emitting from its front (local -Z) side only. Its surface is
// also put in the ray-tracing scene (a quad), so camera and BSDF rays see it; shadow rays do not
// (lights cast no shadows on each other).
//
// | UsdLux input   | type   | default | notes                                                  |
// |----------------|--------|---------|--------------------------------------------------------|
// | width, height  | float  | 1, 1    | local X, Y extent                                      |
// | texture:file   | asset  | none    | multiplies the radiance; texel (0, 0) at local (+X, +Y),|
// |                |        |         | the last at (-X, -Y)                                    |
// | normalize      | bool   | false   | radiance / world-space area                             |
// | shaping:*      |        |         | light_shaping.h                                         |
// A rect without a texture (or with one of one luminance everywhere, a black one included) is
// sampled by solid angle near it (spherical_rectangle.h: every direction towards it equally likely,
// so no 1/cos or distance^2 spread near it or at grazing angles), and uniformly by area from
// points more than kAreaSamplingHeight half diagonals above its plane (where the two densities
// differ less and area sampling is cheaper), or where it is not a rectangle (a
// sheared transform makes a parallelogram) or the point lies in its plane. The choice
// is a function of the shading point alone, so sample() and pdf() make the same one. A textured
// rect is sampled by its texels' luminance (times the light's colour), with a piecewise-constant
// density over the texels (light_image_distribution.h), so that a small bright window in a dark
// frame gets the samples it deserves. pbrt-v4's warp of the square by the cosines at the shading
// point is left out: Light::sample is not given the shading normal.
// Emission sampling (light subpaths): a point as sample() draws it, a direction cosine-weighted
// about the emitting normal.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "render/light.h"
#include "render/light_image_distribution.h"
#include "render/light_shaping.h"
#include "render/lights/spherical_rectangle.h"
#include "render/scene_description.h"

namespace fluence::render {

class RectLight final : public Light {
public:
    explicit RectLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    LightSurface surface() const override;
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

    // Area sampling from points more than this many half diagonals R above the rect's plane. From
    // height z the distance to the rect's points varies by at most R and the cosine at the light,
    // z / distance, by as much, so the area density in solid angle (distance^2 / (area cos)) spreads
    // by a factor of about (1 + R / z)^3 / (1 - R / z)^3 at most. On the Cornell box (light 130 x
    // 105, R 84) the solid angle's gain in relMSE per sample is 6%, nearly all of it within 3 R
    // (bench/results/2026-12-06-spherical-rect-s18.md), while each solid angle sample costs several
    // times an area sample.
    static constexpr float kAreaSamplingHeight = 3.0f;

    // The four world-space corners, from local (-X, -Y) through (+X, -Y), (+X, +Y), (-X, +Y):
    // counter-clockwise seen from behind, so (c1 - c0) x (c3 - c0) points away from the emitting side.
    std::array<Vec3f, 4> corners() const;
    float area() const { return area_; }

private:
    // The power it emits without its shaping (UsdLux ShapingAPI), which power() scales and bounds() bounds.
    float unshapedPower() const;
    // Texture coordinates (u from the texture's left edge, v from its top, both in [0, 1]) of a
    // point on the rect, and the point at texture coordinates uv.
    Vec2f textureCoordinates(const Vec3f& point) const;
    Vec3f pointAt(Vec2f uv) const { return corner_ + edgeU_ * (1.0f - uv.x) + edgeV_ * (1.0f - uv.y); }
    // A point on the rectangle drawn from u: its texture coordinates and density per unit area
    // (by the texture's luminance, else uniform).
    struct PointSample {
        Vec2f uv;
        float areaPdf;
    };
    PointSample samplePoint(Vec2f u) const;
    // The rect as seen from p, where sample() draws by solid angle from p (see the top); nullopt
    // where it draws by area, or p is behind the rect.
    std::optional<SphericalRectangle> solidAngleView(const Vec3f& p) const;
    // Radiance leaving the rect at texture coordinates uv in direction `wo`, facing or not.
    RGB radianceAt(Vec2f uv, const Vec3f& wo) const;

    Vec3f corner_, edgeU_, edgeV_, normal_;  // corner_: local (-X, -Y); normal_: emitting direction
    float area_, inverseArea_;               // inverseArea_ = 1 / area_: the uniform density per unit area
    RGB radiance_;
    std::shared_ptr<const RgbImage> texture_;
    std::optional<ImageDistribution> distribution_;  // over texture coordinates, when the texture's luminance varies
    float meanLuminance_;                            // of the radiance over the rect's area, before shaping
    LightShaping shaping_;
    bool uniformRadiance_;  // no texture, no shaping: radianceAt is radiance_ everywhere (sample()'s fast path)
    bool rectangular_;      // edges orthogonal and the density over the area uniform: solid angle sampling applies
    Vec3d axisU_, axisV_;   // unit edge directions (axisV_ made exactly orthogonal to axisU_)
    double lengthU_, lengthV_;
    float boundingRadius2_;  // squared half diagonal: the rect lies in the ball of this radius about centre_
    Vec3f centre_;
};

}  // namespace fluence::render
