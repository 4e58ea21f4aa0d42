#include "delegate/light_groups.h"

#include <optional>
#include <string>

#include "delegate/prim_reader.h"
#include "render/textured_emission.h"

namespace fluence::delegate {

namespace {

constexpr const char* kLightGroup = "fluence:lightGroup";

// The light group `prim` authors, if any (of the wrong type: warned about, none).
std::optional<std::string> authoredGroup(const usd::PrimSpec& prim, double time, const Warn& warn) {
    PrimReader reader(prim, time);
    if (!reader.value(kLightGroup)) return std::nullopt;
    try {
        return reader.token({kLightGroup}, "");
    } catch (const SceneError& e) {
        warn(prim.path, std::string(e.what()) + "; the light group is left out");
        return std::nullopt;
    }
}

// The group of the prim at `path` or of its nearest ancestor that authors one.
std::optional<std::string> inheritedGroup(const usd::Stage& stage, std::string path, double time, const Warn& warn) {
    while (!path.empty() && path != "/") {
        if (const usd::PrimSpec* prim = stage.prim(path))
            if (auto group = authoredGroup(*prim, time, warn)) return group;
        path.resize(path.find_last_of('/'));
    }
    return std::nullopt;
}

}  // namespace

void resolveLightGroups(const usd::Stage& stage, double time, render::SceneDescription& scene, const Warn& warn) {
    for (const render::LightDesc& light : scene.lights)
        if (const usd::PrimSpec* prim = stage.prim(light.name))  // not the default lights
            if (auto group = authoredGroup(*prim, time, warn)) scene.lightGroups[light.name] = *group;
    for (const render::MeshDesc& mesh : scene.meshes) {
        const render::MaterialDesc* material =
            mesh.material >= 0 ? &scene.materials[std::size_t(mesh.material)] : nullptr;
        if (!material || !render::mayEmit(*material)) continue;
        std::optional<std::string> group = inheritedGroup(stage, mesh.name, time, warn);
        if (!group)
            if (const usd::PrimSpec* prim = stage.prim(material->name)) group = authoredGroup(*prim, time, warn);
        if (group) scene.lightGroups[mesh.name] = *group;
    }
}

}  // namespace fluence::delegate
