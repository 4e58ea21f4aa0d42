// A light that moves during the shutter, as the light tree and light selection see it: its
// frame's light (every call forwarded to it) with bounds() holding every place it takes while
// the shutter is open (render/light_motion.h), so that no shading point it can light at some
// time is culled. What it emits at a ray's time is asked of RenderScene::lightAt
// (render/light_at_time.h).
#pragma once

#include <memory>
#include <optional>

#include "render/light.h"

namespace fluence::render {

class SweptLight final : public Light {
public:
    SweptLight(std::unique_ptr<Light> frame, const LightBounds& swept)
        : Light(frame->name()), frame_(std::move(frame)), swept_(swept) {}

    const Light& frame() const { return *frame_; }

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override { return frame_->sample(p, u); }
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override { return frame_->pdf(p, wi, hit); }
    RGB emitted(const LightHit& hit, const Vec3f& wo) const override { return frame_->emitted(hit, wo); }
    bool atInfinity() const override { return frame_->atInfinity(); }
    RGB escaped(const Vec3f& direction) const override { return frame_->escaped(direction); }
    bool constantRadiance() const override { return frame_->constantRadiance(); }
    float power(const SceneBounds& bounds) const override { return frame_->power(bounds); }
    std::optional<LightBounds> bounds() const override {
        return frame_->atInfinity() ? std::nullopt : std::optional<LightBounds>(swept_);
    }
    LightSurface surface() const override { return frame_->surface(); }
    bool isSurfaceEmitter() const override { return frame_->isSurfaceEmitter(); }
    bool hasEmissionSampling() const override { return frame_->hasEmissionSampling(); }
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override {
        return frame_->sampleEmission(uPosition, uDirection, scene);
    }
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override {
        return frame_->emissionDensity(point, direction, scene);
    }

private:
    std::unique_ptr<Light> frame_;
    LightBounds swept_;
};

}  // namespace fluence::render
