// Path-event recording for light path expressions (integrators/light_path_tracker.h), the part
// every integrator that writes LPE AOVs shares: the events of the scene's lights, of a scattering
// in a medium, and of a surface vertex, whether the next direction was sampled from its BSDF or
// joined to a light (or to another subpath).
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"
#include "integrators/light_path_tracker.h"
#include "render/bsdf.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// Per light of a scene, its event: <L . 'label'> for a UsdLux light, <O . 'label'> for an emissive
// triangle, labelled with the light group of the light or mesh (delegate/light_groups.h) or else
// its prim's name. Built once per render (it belongs in a per-render state, integrators/
// integrator.h). Its events' labels point into its own strings: a move keeps them where they are
// (a vector's move hands over its buffer), a copy would not, so there is none.
class LightEvents {
public:
    LightEvents() = default;  // no lights: for a render without LPE AOVs
    explicit LightEvents(const render::RenderScene& scene);
    LightEvents(const LightEvents&) = delete;
    LightEvents& operator=(const LightEvents&) = delete;
    LightEvents(LightEvents&&) = default;
    LightEvents& operator=(LightEvents&&) = default;

    const PathEvent& operator[](int light) const { return events_[std::size_t(light)]; }

private:
    std::vector<std::string> labels_;  // per light: its light group or prim's name
    std::vector<PathEvent> events_;
};

// The event of a scattering in a medium; `subsurface`: inside a subsurface material's interior.
PathEvent volumeEvent(bool subsurface);

// A non-delta surface vertex left along wiLocal (a light sample, a join), by the kinds of its BSDF's
// lobes for that direction.
VertexEvents joinedEvents(const render::Bsdf& bsdf, const Vec3f& woLocal, const Vec3f& wiLocal);

// A surface vertex between toCamera and toLight (local, in the radiance view): a delta lobe's
// single singular event (`delta`; R or T by the sides), or joinedEvents.
VertexEvents surfaceEvents(const render::Bsdf& bsdf, const Vec3f& toCameraLocal, const Vec3f& toLightLocal, bool delta);

// A surface vertex left along the BSDF sample bs: a delta lobe's single event, or joinedEvents.
VertexEvents sampledEvents(const render::Bsdf& bsdf, const Vec3f& woLocal, const render::BsdfSample& bs);

}  // namespace fluence::integrators
