// One triangle of an emissive mesh (a material whose emission is not black): emits `radiance`
// from both sides, as emissive UsdPreviewSurface materials do. RenderScene makes one per
// triangle of such a mesh (not from a LightDesc); the mesh itself is the surface rays hit, so the
// light has no surface of its own (isSurfaceEmitter).
// Sampled uniformly by area. Emission sampling draws a point by area, a side with probability 1/2
// and a cosine-weighted direction on that side: direction density |cos| / (2 pi).
#pragma once

#include <optional>
#include <string>

#include "render/light.h"

namespace fluence::render {

class TriangleLight final : public Light {
public:
    TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2, const RGB& radiance);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override { return radiance_; }
    float power(const SceneBounds& bounds) const override;
    std::optional<LightBounds> bounds() const override;
    bool isSurfaceEmitter() const override { return true; }
    bool hasEmissionSampling() const override { return true; }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

private:
    Vec3f p0_, p1_, p2_, normal_;
    float area_;
    RGB radiance_;
};

}  // namespace fluence::render
