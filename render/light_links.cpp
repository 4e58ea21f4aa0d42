#include "render/light_links.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "render/scene_description.h"

namespace fluence::render {

namespace {

void checkGroup(const std::string& name, int group, std::size_t groups) {
    if (group < 0 || std::size_t(group) > groups)
        throw std::invalid_argument(name + ": light link group " + std::to_string(group) + " out of range (" +
                                    std::to_string(groups) + " groups)");
}

}  // namespace

std::size_t linkEmitterCount(const SceneDescription& scene) {
    int meshLights = 0;
    auto count = [&](const std::vector<MeshDesc>& meshes) {
        for (const MeshDesc& m : meshes)
            if (m.light) meshLights = std::max(meshLights, m.light->linkId + 1);
    };
    count(scene.meshes);
    for (const PrototypeDesc& p : scene.prototypes) count(p.meshes);
    return scene.lights.size() + std::size_t(meshLights);
}

void checkLinkGroups(const SceneDescription& scene) {
    const std::size_t groups = scene.lightLinkGroups.size();
    for (const MeshDesc& m : scene.meshes) checkGroup(m.name, m.linkGroup, groups);
    for (const CurvesDesc& c : scene.curves) checkGroup(c.name, c.linkGroup, groups);
    for (const PointsDesc& p : scene.points) checkGroup(p.name, p.linkGroup, groups);
    for (const InstanceDesc& i : scene.instances) checkGroup(i.name, i.linkGroup, groups);
    for (const PrototypeDesc& p : scene.prototypes)
        for (const MeshDesc& m : p.meshes) checkGroup(m.name, m.linkGroup, groups);
    const std::size_t emitters = linkEmitterCount(scene);
    for (const LightLinkGroup& g : scene.lightLinkGroups)
        for (const std::vector<int>* lights : {&g.unlit, &g.unshadowed})
            for (int light : *lights)
                if (light < 0 || std::size_t(light) >= emitters)
                    throw std::invalid_argument("light link group names emitter " + std::to_string(light) + " of " +
                                                std::to_string(emitters));
}

LightLinkTable::LightLinkTable(const std::vector<LightLinkGroup>& groups,
                               const std::vector<std::vector<int>>& lightsOfEmitter, std::size_t lightCount) {
    if (groups.empty()) return;
    lightCount_ = lightCount;
    unlit_.assign(groups.size() * lightCount, false);
    unshadowed_.assign(groups.size() * lightCount, false);
    passes_.assign(lightCount, false);
    // Marks every light of `emitters` in group g's row of `table`, and in `anyGroup` when given.
    auto mark = [&](const std::vector<int>& emitters, std::size_t g, std::vector<bool>& table,
                    std::vector<bool>* anyGroup) {
        for (int emitter : emitters)
            for (int light : lightsOfEmitter[std::size_t(emitter)]) {
                table[g * lightCount + std::size_t(light)] = true;
                if (anyGroup) (*anyGroup)[std::size_t(light)] = true;
            }
    };
    for (std::size_t g = 0; g < groups.size(); ++g) {
        mark(groups[g].unlit, g, unlit_, nullptr);
        mark(groups[g].unshadowed, g, unshadowed_, &passes_);
    }
    excludes_ = std::find(unlit_.begin(), unlit_.end(), true) != unlit_.end();
}

}  // namespace fluence::render
