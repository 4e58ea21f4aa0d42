// UsdLux DistantLight: light from a distant disk of angular diameter `angle` around the light's
// +Z axis (it emits along -Z). A light at infinity: only the rotation of its transform matters.
//
// | UsdLux input   | type  | default      | notes                                          |
// |----------------|-------|--------------|------------------------------------------------|
// | angle          | float | 0.53 degrees | angular diameter                               |
// | normalize      | bool  | false        | the value is the irradiance of the disk        |
// | shaping:*      |       |              | ignored (the delegate warns)                   |
// angle = 0 is a delta light whose value is the irradiance on a surface facing it. For angle > 0
// the authored radiance is the disk's radiance, unless `normalize` is on, in which case it is
// divided by UsdLux's sizeFactor, pi sin^2(theta_max) (theta_max half the angle): the value is then
// the irradiance the whole disk delivers to a surface facing it; past a hemisphere (angle > 180)
// sizeFactor is (2 - sin^2(theta_max)) pi, as OpenUSD PR 3182 defines it. The disk is sampled
// uniformly in its cone.
// Emission sampling: a direction by sample() (towards the light, reversed), and a point on the
// disk of the scene's bounding radius facing it (emission_at_infinity.h).
#pragma once

#include "render/lights/infinite_light.h"
#include "render/scene_description.h"

namespace fluence::render {

class DistantLight final : public InfiniteLight {
public:
    explicit DistantLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB escaped(const Vec3f& direction) const override;
    float power(const SceneBounds& bounds) const override;
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

    bool isDelta() const { return oneMinusCosMax_ == 0.0; }

private:
    Vec3f towardsLight_;
    double oneMinusCosMax_;  // 0 for a delta light
    RGB value_;              // radiance of the disk, or irradiance for a delta light
};

}  // namespace fluence::render
