#include "delegate/default_lights.h"

#include <algorithm>

#include "render/textured_emission.h"

namespace fluence::delegate {

namespace {

bool volumeEmits(const render::VolumeDesc& v) {
    return (v.params.emissionScale > 0.0f && !isBlack(v.params.emissionColor)) ||
           (v.params.blackbodyIntensity > 0.0f && v.temperature.has_value());
}

}  // namespace

bool emitsLight(const render::SceneDescription& scene) {
    if (!scene.lights.empty() || std::any_of(scene.volumes.begin(), scene.volumes.end(), volumeEmits)) return true;
    auto meshEmits = [&](const render::MeshDesc& mesh) {
        return mesh.light || (mesh.material >= 0 && mesh.material < static_cast<int>(scene.materials.size()) &&
                              render::mayEmit(scene.materials[static_cast<std::size_t>(mesh.material)]));
    };
    if (std::any_of(scene.meshes.begin(), scene.meshes.end(), meshEmits)) return true;
    return std::any_of(scene.prototypes.begin(), scene.prototypes.end(), [&](const render::PrototypeDesc& p) {
        return std::any_of(p.meshes.begin(), p.meshes.end(), meshEmits);
    });
}

std::vector<render::LightDesc> defaultLights(const render::CameraDesc& camera) {
    render::LightDesc key;
    key.name = "(default key light)";
    key.type = render::LightType::Distant;
    key.transform = camera.transform;           // the camera and a distant light both look down local -Z
    key.radiance = RGB(kDefaultKeyIrradiance);  // a point-like (0 degree) distant light: the irradiance
    key.castsShadows = false;  // as usdview's camera light: a camera inside a closed shape still sees it lit
    render::LightDesc dome;
    dome.name = "(default dome)";
    dome.type = render::LightType::Dome;
    dome.radiance = RGB(kDefaultDomeRadiance);
    dome.visibleToCamera = false;
    return {key, dome};
}

}  // namespace fluence::delegate
