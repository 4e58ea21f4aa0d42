#include "delegate/light_links.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "delegate/collection_membership.h"

namespace fluence::delegate {

namespace {

bool isAncestorOrSelf(const std::string& ancestor, const std::string& path) {
    if (ancestor == "/") return true;
    return path.starts_with(ancestor) && (path.size() == ancestor.size() || path[ancestor.size()] == '/');
}

// A light whose collections do not hold everything: its emitter number (render/light_links.h).
struct LinkedLight {
    int index;
    CollectionMembership light, shadow;
};

// Per linked light, whether it lights and is shadowed by a prim at `path`: the key of its group.
using Membership = std::vector<bool>;

Membership membershipOf(const std::vector<LinkedLight>& lights, const std::string& path) {
    Membership m;
    for (const LinkedLight& l : lights) {
        m.push_back(!l.light.contains(path));
        m.push_back(!l.shadow.contains(path));
    }
    return m;
}

// Link group numbers, one per distinct membership (0: every light lights and is shadowed).
class Groups {
public:
    Groups(const std::vector<LinkedLight>& lights, render::SceneDescription& scene) : lights_(lights), scene_(scene) {}

    int of(const Membership& m) {
        bool linkedToAll = true;
        for (bool excluded : m) linkedToAll = linkedToAll && !excluded;
        if (linkedToAll) return 0;
        auto [it, added] = numbers_.try_emplace(m, int(scene_.lightLinkGroups.size()) + 1);
        if (added) {
            render::LightLinkGroup& g = scene_.lightLinkGroups.emplace_back();
            for (std::size_t i = 0; i < lights_.size(); ++i) {
                if (m[2 * i]) g.unlit.push_back(lights_[i].index);
                if (m[2 * i + 1]) g.unshadowed.push_back(lights_[i].index);
            }
        }
        return it->second;
    }

private:
    const std::vector<LinkedLight>& lights_;
    render::SceneDescription& scene_;
    std::map<Membership, int> numbers_;
};

// The group of an instance: its meshes' memberships at their instance-proxy paths (a
// PointInstancer's instance: at their prototype paths), which must agree.
int instanceGroup(const std::vector<LinkedLight>& lights, const render::InstanceDesc& instance,
                  const render::PrototypeDesc& prototype, Groups& groups, const Warn& warn) {
    const bool pointInstance = instance.name.find('[') != std::string::npos;
    std::optional<Membership> shared;
    bool differ = false;
    for (const render::MeshDesc& mesh : prototype.meshes) {
        const bool inside = isAncestorOrSelf(prototype.name, mesh.name);
        const std::string path =
            pointInstance || !inside ? mesh.name : instance.name + mesh.name.substr(prototype.name.size());
        const Membership m = membershipOf(lights, path);
        differ = differ || (shared && *shared != m);
        if (!shared) shared = m;
    }
    if (differ || !shared) {
        if (differ)
            warn(instance.name,
                 "light or shadow links name prims inside this instance differently; the instance "
                 "takes the links of its own prim");
        const std::string own = pointInstance ? instance.name.substr(0, instance.name.find('[')) : instance.name;
        return groups.of(membershipOf(lights, own));
    }
    return groups.of(*shared);
}

// The light at `path` as emitter `emitter`, when its collections do not hold everything.
std::optional<LinkedLight> linkedLight(const usd::Stage& stage, const std::string& path, int emitter, double time,
                                       const Warn& warn) {
    const usd::PrimSpec* prim = stage.prim(path);
    if (!prim) return std::nullopt;  // the default lights
    LinkedLight l{emitter, CollectionMembership::read(stage, *prim, "lightLink", true, time, warn),
                  CollectionMembership::read(stage, *prim, "shadowLink", true, time, warn)};
    if (l.light.holdsEverything() && l.shadow.holdsEverything()) return std::nullopt;
    return l;
}

// Numbers the mesh lights whose collections do not hold everything (MeshLightDesc::linkId), each
// prim once however many parts and prototypes hold it, and adds them to `lights`.
void linkMeshLights(const usd::Stage& stage, double time, render::SceneDescription& scene,
                    std::vector<LinkedLight>& lights, const Warn& warn) {
    std::map<std::string, int> ids;  // MeshLightAPI prim -> its linkId, or -1
    int linked = 0;
    auto number = [&](std::vector<render::MeshDesc>& meshes) {
        for (render::MeshDesc& mesh : meshes) {
            if (!mesh.light) continue;
            auto [it, added] = ids.try_emplace(mesh.light->prim, -1);
            if (added)
                if (std::optional<LinkedLight> l =
                        linkedLight(stage, mesh.light->prim, int(scene.lights.size()) + linked, time, warn)) {
                    it->second = linked++;
                    lights.push_back(std::move(*l));
                }
            mesh.light->linkId = it->second;
        }
    };
    number(scene.meshes);
    for (render::PrototypeDesc& p : scene.prototypes) number(p.meshes);
}

}  // namespace

void resolveLightLinks(const usd::Stage& stage, double time, render::SceneDescription& scene, const Warn& warn) {
    std::vector<LinkedLight> lights;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (std::optional<LinkedLight> l = linkedLight(stage, scene.lights[i].name, int(i), time, warn))
            lights.push_back(std::move(*l));
    linkMeshLights(stage, time, scene, lights, warn);
    if (lights.empty()) return;
    Groups groups(lights, scene);
    for (render::MeshDesc& m : scene.meshes) m.linkGroup = groups.of(membershipOf(lights, m.name));
    for (render::CurvesDesc& c : scene.curves) c.linkGroup = groups.of(membershipOf(lights, c.name));
    for (render::PointsDesc& p : scene.points) p.linkGroup = groups.of(membershipOf(lights, p.name));
    for (render::InstanceDesc& instance : scene.instances)
        instance.linkGroup =
            instanceGroup(lights, instance, scene.prototypes[std::size_t(instance.prototype)], groups, warn);
}

}  // namespace fluence::delegate
