// Emission of a light at infinity (the distant and dome lights' Light::sampleEmission): pbrt's
// infinite-light emission, a point uniformly on the disk of the scene's bounding radius, facing
// the direction light travels, a radius beyond the scene's centre.
#pragma once

#include "core/frame.h"
#include "core/sampling.h"
#include "render/light.h"

namespace fluence::render {

// The density of a point fromInfinity draws, per unit area of that disk.
inline float infinityPositionDensity(const SceneBounds& scene) { return 1.0f / (kPi * scene.radius * scene.radius); }

// Emission along `direction` (towards the scene) drawn with solid-angle density `directionPdf`,
// carrying radiance Le.
inline EmissionSample fromInfinity(const Vec3f& direction, float directionPdf, const RGB& Le, Vec2f uPosition,
                                   const SceneBounds& scene) {
    const float r = scene.radius;
    Vec2f d = sampleUniformDisk(uPosition);
    Frame frame = Frame::fromNormal(direction);
    Vec3f point = scene.centre - direction * r + (frame.s * d.x + frame.t * d.y) * r;
    return {point, direction, direction, Le, {infinityPositionDensity(scene), directionPdf, 1.0f}};
}

}  // namespace fluence::render
