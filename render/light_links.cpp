#include "render/light_links.h"

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

void checkLinkGroups(const SceneDescription& scene) {
    const std::size_t groups = scene.lightLinkGroups.size();
    for (const MeshDesc& m : scene.meshes) checkGroup(m.name, m.linkGroup, groups);
    for (const CurvesDesc& c : scene.curves) checkGroup(c.name, c.linkGroup, groups);
    for (const PointsDesc& p : scene.points) checkGroup(p.name, p.linkGroup, groups);
    for (const InstanceDesc& i : scene.instances) checkGroup(i.name, i.linkGroup, groups);
    for (const PrototypeDesc& p : scene.prototypes)
        for (const MeshDesc& m : p.meshes) checkGroup(m.name, m.linkGroup, groups);
    for (const LightLinkGroup& g : scene.lightLinkGroups)
        for (const std::vector<int>* lights : {&g.unlit, &g.unshadowed})
            for (int light : *lights)
                if (light < 0 || std::size_t(light) >= scene.lights.size())
                    throw std::invalid_argument("light link group names light " + std::to_string(light) + " of " +
                                                std::to_string(scene.lights.size()));
}

LightLinkTable::LightLinkTable(const std::vector<LightLinkGroup>& groups, const std::vector<int>& lightOfDesc,
                               std::size_t lightCount) {
    if (groups.empty()) return;
    lightCount_ = lightCount;
    unlit_.assign(groups.size() * lightCount, false);
    unshadowed_.assign(groups.size() * lightCount, false);
    passes_.assign(lightCount, false);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        for (int desc : groups[g].unlit) {
            unlit_[g * lightCount + std::size_t(lightOfDesc[std::size_t(desc)])] = true;
            excludes_ = true;
        }
        for (int desc : groups[g].unshadowed) {
            const std::size_t light = std::size_t(lightOfDesc[std::size_t(desc)]);
            unshadowed_[g * lightCount + light] = true;
            passes_[light] = true;
        }
    }
}

}  // namespace fluence::render
