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

// A light whose collections do not hold everything: its index in SceneDescription::lights.
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

}  // namespace

void resolveLightLinks(const usd::Stage& stage, double time, render::SceneDescription& scene, const Warn& warn) {
    std::vector<LinkedLight> lights;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const usd::PrimSpec* prim = stage.prim(scene.lights[i].name);
        if (!prim) continue;  // the default lights
        LinkedLight l{int(i), CollectionMembership::read(stage, *prim, "lightLink", true, time, warn),
                      CollectionMembership::read(stage, *prim, "shadowLink", true, time, warn)};
        if (!l.light.holdsEverything() || !l.shadow.holdsEverything()) lights.push_back(std::move(l));
    }
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
