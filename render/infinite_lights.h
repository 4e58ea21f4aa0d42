// Lights at infinity: UsdLux DistantLight and DomeLight (constant colour in this slice).
#pragma once

#include "render/light.h"
#include "render/scene_description.h"

namespace fluence::render {

// UsdLux DistantLight: light from a distant disk of angular diameter `angle` around the light's
// +Z axis (it emits along -Z). angle = 0 is a delta light whose value is the irradiance on a
// surface facing it. For angle > 0 the authored radiance is the disk's radiance, unless
// `normalize` is on, in which case it is the irradiance the whole disk delivers.
class DistantLight final : public Light {
public:
    explicit DistantLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    bool atInfinity() const override { return true; }
    RGB escaped(const Vec3f& direction) const override;
    float power(const SceneBounds& bounds) const override;
    std::string name() const override { return name_; }

    bool isDelta() const { return oneMinusCosMax_ == 0.0; }

private:
    std::string name_;
    Vec3f towardsLight_;
    double oneMinusCosMax_;  // 0 for a delta light
    RGB value_;              // radiance of the disk, or irradiance for a delta light
};

// UsdLux DomeLight with a constant colour: radiance L from every direction. Sampled uniformly
// over the sphere.
class DomeLight final : public Light {
public:
    explicit DomeLight(const LightDesc& desc) : name_(desc.name), radiance_(desc.radiance) {}

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    bool atInfinity() const override { return true; }
    RGB escaped(const Vec3f&) const override { return radiance_; }
    float power(const SceneBounds& bounds) const override;
    std::string name() const override { return name_; }

private:
    std::string name_;
    RGB radiance_;
};

}  // namespace fluence::render
