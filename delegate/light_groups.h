// Light groups: the name a light, or the light of an emissive surface, goes by in light path
// expressions (integrators/light_path_expression.h), so that one LPE AOV can gather the light of
// several lights ("all the key lights") or of several emissive objects, as Arnold's light `aov`,
// Karma's lpetag and Cycles' light groups do.
//
// A UsdLux light's group is its `fluence:lightGroup` (string or token). An emissive mesh's is the
// `fluence:lightGroup` of the mesh or of its nearest ancestor that authors one, else the one its
// bound Material prim authors. Without a group, a light's label is its prim's name
// (integrators/path_events.h, LightEvents). A group replaces the name: `<L'key'>` then
// matches the light whose group is "key", not a light named key in another group.
#pragma once

#include "delegate/material_adapter.h"  // Warn
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

// Fills scene.lightGroups for the lights and emissive meshes of `scene` that have a group, read at
// `time`. An attribute of another type is warned about and left out.
void resolveLightGroups(const usd::Stage& stage, double time, render::SceneDescription& scene, const Warn& warn);

}  // namespace fluence::delegate
