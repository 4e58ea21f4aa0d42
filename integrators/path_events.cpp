#include "integrators/path_events.h"

#include "core/name_table.h"

namespace fluence::integrators {

LightEvents::LightEvents(const render::RenderScene& scene) {
    for (std::size_t i = 0; i < scene.lightCount(); ++i) {
        const std::string* group = scene.lightGroup(scene.light(i).name());
        labels_.push_back(group ? *group : primName(scene.light(i).name()));
    }
    for (std::size_t i = 0; i < scene.lightCount(); ++i) {
        const bool surface = scene.light(i).isSurfaceEmitter();
        events_.push_back(PathEvent{surface ? EventType::Object : EventType::Light, Scattering::None, labels_[i]});
    }
}

PathEvent volumeEvent(bool subsurface) {
    return PathEvent{EventType::Volume, Scattering::Diffuse, subsurface ? "subsurface" : ""};
}

VertexEvents joinedEvents(const render::Bsdf& bsdf, const Vec3f& woLocal, const Vec3f& wiLocal) {
    return VertexEvents(woLocal.z * wiLocal.z < 0.0f, bsdf.fByKind(woLocal, wiLocal));
}

VertexEvents surfaceEvents(const render::Bsdf& bsdf, const Vec3f& toCameraLocal, const Vec3f& toLightLocal,
                           bool delta) {
    if (!delta) return joinedEvents(bsdf, toCameraLocal, toLightLocal);
    const bool transmitted = toCameraLocal.z * toLightLocal.z < 0.0f;
    return VertexEvents(PathEvent{transmitted ? EventType::Transmission : EventType::Reflection, Scattering::Singular});
}

VertexEvents sampledEvents(const render::Bsdf& bsdf, const Vec3f& woLocal, const render::BsdfSample& bs) {
    return surfaceEvents(bsdf, woLocal, bs.wi, bs.specular);
}

}  // namespace fluence::integrators
