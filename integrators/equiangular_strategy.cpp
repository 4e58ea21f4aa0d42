#include "integrators/equiangular_strategy.h"

namespace fluence::integrators {

std::optional<MediumSegment> mediumSegment(const media::Medium& medium, const Vec3f& origin, const Vec3f& direction,
                                           float tBoundary) {
    MediumSegment s{origin, direction, tBoundary, tBoundary};
    bool found = false;
    medium.majorants(origin, direction, 0.0f, tBoundary, [&](const media::MajorantSegment& m) {
        if (maxComponent(m.sigmaMaj) > 0.0f) {
            s.tMin = std::max(m.tMin, 0.0f);
            found = true;
        }
        return !found;
    });
    if (!found) return std::nullopt;
    if (!(s.tMin < s.tMax)) return std::nullopt;
    return s;
}

EquiangularLights::EquiangularLights(const render::RenderScene& scene) : centres_(scene.lightCount()) {
    for (std::size_t i = 0; i < centres_.size(); ++i)
        if (const std::optional<render::LightBounds> b = scene.light(i).bounds()) {
            centres_[i] = (b->lo + b->hi) * 0.5f;
            any_ = true;
        }
}

std::optional<EquiangularChoice> EquiangularLights::choose(const render::RenderScene& scene,
                                                           const MediumSegment& segment, float u) const {
    const render::LightChoice choice = scene.chooseLight(segment.origin, Vec3f(0.0f), u);
    if (choice.light < 0 || choice.probability <= 0.0f || !centres_[std::size_t(choice.light)]) return std::nullopt;
    return EquiangularChoice{choice.light, choice.probability,
                             media::EquiangularDistance(segment.origin, segment.direction, segment.tMin, segment.tMax,
                                                        *centres_[std::size_t(choice.light)])};
}

float EquiangularLights::pdf(const render::RenderScene& scene, const MediumSegment& segment, int light, float t) const {
    const std::optional<Vec3f>& centre = centres_[std::size_t(light)];
    if (!centre) return 0.0f;
    const media::EquiangularDistance distance(segment.origin, segment.direction, segment.tMin, segment.tMax, *centre);
    return scene.lightProbability(segment.origin, Vec3f(0.0f), light) * distance.pdf(t);
}

}  // namespace fluence::integrators
