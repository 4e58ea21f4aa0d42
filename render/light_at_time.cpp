#include "render/light_at_time.h"

namespace fluence::render {

std::optional<LightSample> LightAtTime::sample(const Vec3f& p, Vec2f u) const {
    if (!motion_) return light_->sample(p, u);
    std::optional<LightSample> s = light_->sample(motion_->pointBack(p), u);
    if (s) s->wi = motion_->vector(s->wi);
    return s;
}

float LightAtTime::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    if (!motion_) return light_->pdf(p, wi, hit);
    return light_->pdf(motion_->pointBack(p), motion_->vectorBack(wi), hitBack(hit));
}

RGB LightAtTime::emitted(const LightHit& hit, const Vec3f& wo) const {
    if (!motion_) return light_->emitted(hit, wo);
    return light_->emitted(hitBack(hit), motion_->vectorBack(wo));
}

RGB LightAtTime::escaped(const Vec3f& direction) const {
    return light_->escaped(motion_ ? motion_->vectorBack(direction) : direction);
}

std::optional<EmissionSample> LightAtTime::sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                          const SceneBounds& scene) const {
    if (!motion_) return light_->sampleEmission(uPosition, uDirection, scene);
    std::optional<EmissionSample> e = light_->sampleEmission(uPosition, uDirection, sceneBack(scene));
    if (e) {
        e->point = motion_->point(e->point);
        e->direction = motion_->vector(e->direction);
        e->normal = motion_->vector(e->normal);
    }
    return e;
}

EmissionDensity LightAtTime::emissionDensity(const Vec3f& point, const Vec3f& direction,
                                             const SceneBounds& scene) const {
    if (!motion_) return light_->emissionDensity(point, direction, scene);
    return light_->emissionDensity(motion_->pointBack(point), motion_->vectorBack(direction), sceneBack(scene));
}

}  // namespace fluence::render
