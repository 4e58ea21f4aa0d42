// Native instances that cannot share a prototype because of UsdSkel.
//
// A native instance's prototype is read once and placed by each instance's transform, so every
// instance renders the same geometry. A skinned prim inside it is posed by its skeleton and
// animation; when everything its pose reads is inside the instance (skel_binding.h,
// skelInputsOutside), every instance poses it alike and the prototype holds it posed. When its
// pose reads a prim outside the instance (crowds bind each agent's SkelAnimation on a prim above
// an instanceable SkelRoot: arnold-usd test_1524), instances can differ in pose. Such an instance
// is de-instanced, as Hydra skins per instance: its prims become render prims of their own at
// their instance-proxy paths, each skinned on its own, and the delegate says so in one warning.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "scene/stage.h"

namespace fluence::delegate {

// Why an instance is posed per instance: its first skinned prim (in traversal order) whose pose
// reads a prim outside the instance, that prim, and how many such skinned prims it holds.
struct PerInstancePose {
    std::string skinnedPrim;
    std::string outsideInput;
    std::size_t skinnedPrims = 0;
};

// nullopt when the native instance `instance` can share its prototype.
std::optional<PerInstancePose> perInstancePose(const usd::Stage& stage, const usd::PrimSpec& instance);

// The warning the delegate gives when it de-instances `instance` for `why`.
std::string deinstancedWarning(const PerInstancePose& why);

}  // namespace fluence::delegate
