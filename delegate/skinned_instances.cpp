#include "delegate/skinned_instances.h"

#include <vector>

#include "delegate/imageable.h"
#include "delegate/skel_binding.h"

namespace fluence::delegate {

std::optional<PerInstancePose> perInstancePose(const usd::Stage& stage, const usd::PrimSpec& instance) {
    PerInstancePose why;
    usd::Stage::traverse(instance, [&](const usd::PrimSpec& prim) {
        if (!isGeometryType(prim.typeName)) return true;
        const std::vector<std::string> outside = skelInputsOutside(stage, prim, instance.path);
        if (outside.empty()) return true;
        if (why.skinnedPrims++ == 0) {
            why.skinnedPrim = prim.path;
            why.outsideInput = outside.front();
        }
        return true;
    });
    if (why.skinnedPrims == 0) return std::nullopt;
    return why;
}

std::string deinstancedWarning(const PerInstancePose& why) {
    return "de-instanced: " + std::to_string(why.skinnedPrims) + " skinned prim" + (why.skinnedPrims == 1 ? "" : "s") +
           " in it (" + why.skinnedPrim + ") read UsdSkel data outside the " + "instance (" + why.outsideInput +
           "), so instances can differ in pose; its prims are skinned one by " +
           "one at their instance-proxy paths, as Hydra skins per instance";
}

}  // namespace fluence::delegate
