// Light linking and shadow linking (UsdLux's collection:lightLink and collection:shadowLink), as the
// render core takes them: no prim paths, only numbers. Each piece of geometry (MeshDesc, CurvesDesc,
// PointsDesc, InstanceDesc) carries a link group; group 0, the default, is lit by every light and
// casts every light's shadows. Group g > 0 is SceneDescription::lightLinkGroups[g - 1]: the lights
// that do not light its geometry, and those whose shadow rays pass through it. A group names a
// light by its emitter number: i < SceneDescription::lights.size() is lights[i], and
// lights.size() + k is the UsdLux mesh light whose MeshLightDesc::linkId is k (every triangle of
// every part and instance of it). The delegate (delegate/light_links.h) resolves the collections
// into groups.
//
// What "lit by" means, the same in every integrator: light leaving light L along a path's first
// segment counts only where that segment ends on geometry L lights (next-event estimation at the
// vertex, emission a BSDF-sampled ray from the vertex reaches, photons and light subpaths from L
// landing there). Camera rays see every light, as in Karma and Arnold, and light that L puts on
// other surfaces reaches unlinked geometry by reflection as usual.
#pragma once

#include <cstddef>
#include <vector>

namespace fluence::render {

struct SceneDescription;

struct LightLinkGroup {
    std::vector<int> unlit;       // emitters that do not light the group's geometry
    std::vector<int> unshadowed;  // emitters whose shadow rays the group's geometry does not block
};

// The number of emitters a group may name: the LightDescs, then the linked mesh lights (one more
// than the largest MeshLightDesc::linkId of the meshes and the prototypes' meshes).
std::size_t linkEmitterCount(const SceneDescription& scene);

// Throws std::invalid_argument naming the geometry whose link group is not one of `scene`'s, or the
// group that names an emitter `scene` does not have.
void checkLinkGroups(const SceneDescription& scene);

// The groups of a scene against its lights in the render core's numbering (RenderScene's light
// indices): built from the groups and, for each emitter, its light indices (a mesh light's: all
// its triangles).
class LightLinkTable {
public:
    LightLinkTable() = default;
    LightLinkTable(const std::vector<LightLinkGroup>& groups, const std::vector<std::vector<int>>& lightsOfEmitter,
                   std::size_t lightCount);

    bool empty() const { return lightCount_ == 0; }
    // Whether `light` lights geometry of `group`.
    bool lights(int light, int group) const { return group == 0 || empty() || !unlit_[at(light, group)]; }
    // Whether geometry of `group` blocks `light`'s shadow rays.
    bool shadows(int light, int group) const { return group == 0 || empty() || !unshadowed_[at(light, group)]; }
    // Whether some geometry does not block `light`'s shadow rays.
    bool passesSomething(int light) const { return !empty() && passes_[std::size_t(light)]; }
    // Whether some light does not light some geometry.
    bool excludesAnything() const { return excludes_; }

private:
    std::size_t at(int light, int group) const { return std::size_t(group - 1) * lightCount_ + std::size_t(light); }
    std::size_t lightCount_ = 0;
    std::vector<bool> unlit_, unshadowed_, passes_;
    bool excludes_ = false;
};

}  // namespace fluence::render
