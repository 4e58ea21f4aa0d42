// Light linking and shadow linking: each UsdLux light's collection:lightLink and
// collection:shadowLink (UsdCollectionAPI) resolved into the link groups of the scene's geometry
// (render/light_links.h), so the render core never sees a collection or a prim path.
//
// Membership follows UsdCollectionAPI (delegate/collection_membership.h), with includeRoot's fallback
// true for both collections (UsdLux's, so an unauthored collection holds everything); collections
// named in `includes` are merged in.
// Geometry inside a native instance is judged at its instance-proxy path (the instance's path and
// the prim's path inside the prototype); an instance whose meshes would differ takes its own
// prim's membership, with a warning. A PointInstancer's instances are judged at their prototypes'
// paths.
#pragma once

#include "delegate/material_adapter.h"  // Warn
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

// Gives the geometry of `scene` (meshes, curves, points, instances) the link groups its lights'
// collections put it in, read at `time`, and fills scene.lightLinkGroups. Lights whose collections
// hold everything change nothing: a scene without links keeps every geometry in group 0.
void resolveLightLinks(const usd::Stage& stage, double time, render::SceneDescription& scene, const Warn& warn);

}  // namespace fluence::delegate
