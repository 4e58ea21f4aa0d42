// One triangle of an emissive mesh (a material whose emission is not black): emits `radiance`
// from both sides, as emissive UsdPreviewSurface materials do. RenderScene makes one per
// triangle of such a mesh (not from a LightDesc); the mesh itself is the surface rays hit, so the
// light has no surface of its own (isSurfaceEmitter).
// Sampled uniformly by area. Emission sampling draws a point by area, a side with probability 1/2
// and a cosine-weighted direction on that side: direction density |cos| / (2 pi).
// A triangle of a mesh whose emission a texture or primvar drives (render/textured_emission.h)
// emits that function's radiance at each point, and its power is that of its mean radiance, so
// light selection and the light tree choose it by its textured power; within it, points are still
// drawn uniformly by area.
// A triangle of a UsdLux mesh light (MeshDesc::light) emits from its front only, the side of
// cross(p1 - p0, p2 - p0), as a RectLight does: half the power, directions drawn with density
// cos / pi on that side, nothing behind it. Its UsdLux shaping (shape()) narrows that emission as
// a RectLight's: cone, focus and IES profile about the triangle's front normal, the profile's
// azimuth from the mesh light's local X and Y (render/light_shaping.h); the power, the light
// tree's bounds and the emitted radiance take it, the sampling densities do not change.
#pragma once

#include <optional>
#include <string>

#include "render/light.h"
#include "render/light_shaping.h"
#include "render/textured_emission.h"

namespace fluence::render {

// Which sides of a triangle emit.
enum class EmittingSides { Both, Front };

class TriangleLight final : public Light {
public:
    TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2, const RGB& radiance,
                  EmittingSides sides = EmittingSides::Both);
    // Triangle `triangle` of a mesh with textured emission (kept by reference).
    TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2,
                  const TexturedEmission& emission, unsigned triangle);

    // Shapes a front-only triangle's emission by `shaping` (built about the default ShapingFrame,
    // kept by reference), about its front normal, an IES profile oriented by `lightToWorld`'s X and Y.
    void shape(const LightShaping& shaping, const Matrix4& lightToWorld);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    bool isSurfaceEmitter() const override { return true; }
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

private:
    // The radiance at the point with barycentric weights b of p0 and p1 (sampleUniformTriangle's).
    RGB radianceAt(Vec2f b) const;
    // Whether light leaves towards `direction` (a unit vector away from the triangle).
    bool emitsTowards(const Vec3f& direction) const { return !frontOnly_ || dot(normal_, direction) > 0.0f; }
    float unshapedPower() const;
    // The shaping's factor on light leaving in unit `direction` (1 unshaped).
    RGB shapingFactor(const Vec3f& direction) const {
        return shaping_ ? shaping_->factor(shapingFrame_.toLocal(direction)) : RGB(1.0f);
    }

    Vec3f p0_, p1_, p2_, normal_;
    float area_;
    RGB radiance_;  // constant, or the textured emission's mean over the triangle
    const TexturedEmission* textured_ = nullptr;
    unsigned triangle_ = 0;
    bool frontOnly_ = false;
    const LightShaping* shaping_ = nullptr;
    ShapingFrame shapingFrame_;
};

}  // namespace fluence::render
