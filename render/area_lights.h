// Lights with a surface in the scene: UsdLux RectLight and SphereLight, and the triangles of
// emissive meshes. Their surfaces are also put in the ray-tracing scene, so camera and BSDF rays
// see them; shadow rays do not (lights cast no shadows on each other).
#pragma once

#include <array>

#include "core/matrix.h"
#include "render/light.h"
#include "render/scene_description.h"

namespace fluence::render {

// UsdLux RectLight: a width x height rectangle in the local XY plane, emitting from its front
// (local -Z) side only. Sampled uniformly by area.
class RectLight final : public Light {
public:
    explicit RectLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::string name() const override { return name_; }

    // The four world-space corners, counter-clockwise seen from the emitting side.
    std::array<Vec3f, 4> corners() const;
    float area() const { return area_; }

private:
    std::string name_;
    Vec3f corner_, edgeU_, edgeV_, normal_;  // normal_: emitting direction
    float area_;
    RGB radiance_;
};

// UsdLux SphereLight: a sphere emitting outwards everywhere. Sampled uniformly within the cone
// it subtends (exact solid-angle sampling of the visible cap). Non-uniform scale is reduced to
// the cube root of the transform's determinant.
class SphereLight final : public Light {
public:
    explicit SphereLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override;
    float power(const SceneBounds& bounds) const override;
    std::string name() const override { return name_; }

    const Vec3f& centre() const { return centre_; }
    float radius() const { return radius_; }

private:
    std::string name_;
    Vec3f centre_;
    float radius_;
    RGB radiance_;
};

// One triangle of an emissive mesh: emits `radiance` from both sides, as emissive
// UsdPreviewSurface materials do. Sampled uniformly by area.
class TriangleLight final : public Light {
public:
    TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2, const RGB& radiance);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override { return radiance_; }
    float power(const SceneBounds& bounds) const override;
    std::string name() const override { return name_; }

private:
    std::string name_;
    Vec3f p0_, p1_, p2_, normal_;
    float area_;
    RGB radiance_;
};

}  // namespace fluence::render
