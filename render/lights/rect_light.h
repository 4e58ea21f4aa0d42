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
// A rect without a texture is sampled uniformly by area; a textured rect by its texels' luminance
// (times the light's colour), with a piecewise-constant density over the texels
// (light_image_distribution.h), so that a small bright window in a dark frame gets the samples it
// deserves. A texture of one luminance everywhere (a black one included) is sampled uniformly.
// Emission sampling (light subpaths): a point as sample() draws it, a direction cosine-weighted
// about the emitting normal.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "render/light.h"
#include "render/light_image_distribution.h"
#include "render/light_shaping.h"
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
};

}  // namespace fluence::render
