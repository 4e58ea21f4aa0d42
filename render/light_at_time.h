// A light where it is at a time in the shutter (render::Ray::time): what the integrators sample,
// evaluate and ask densities of, through RenderScene::lightAt(light, time).
//
// A still light is itself (every call forwarded as it is). A moving UsdLux light
// (render/light_motion.h) is its frame's light under the rigid motion to that time: queries are
// mapped into the frame's light and the answers back. A triangle of a moving emissive mesh is the
// triangle where its mesh is at that time (deformation and transformation), made for the call.
// The conventions are Light's (render/light.h).
#pragma once

#include <optional>

#include "render/light.h"
#include "render/light_motion.h"
#include "render/lights/triangle_light.h"

namespace fluence::render {

class LightAtTime {
public:
    explicit LightAtTime(const Light& still) : light_(&still) {}
    LightAtTime(const Light& frame, const RigidMotion& motion) : light_(&frame), motion_(motion) {}
    explicit LightAtTime(TriangleLight&& triangle) : triangle_(std::move(triangle)) { light_ = &*triangle_; }
    // It may point into itself (a triangle made for the call): not copied or moved, only returned.
    LightAtTime(const LightAtTime&) = delete;
    LightAtTime& operator=(const LightAtTime&) = delete;

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const;
    RGB emitted(const LightHit& hit, const Vec3f& wo) const;
    RGB escaped(const Vec3f& direction) const;
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds& scene) const;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction, const SceneBounds& scene) const;

private:
    // The scene's bound as the frame's light sees it.
    SceneBounds sceneBack(const SceneBounds& scene) const { return {motion_->pointBack(scene.centre), scene.radius}; }
    LightHit hitBack(const LightHit& hit) const {
        return {motion_->pointBack(hit.point), motion_->vectorBack(hit.normal)};
    }

    const Light* light_ = nullptr;
    std::optional<RigidMotion> motion_;
    std::optional<TriangleLight> triangle_;
};

}  // namespace fluence::render
