// UsdSkel Skeleton and SkelAnimation prims: the joint hierarchy, its bind and rest poses, and the
// skinning transforms of a pose, as UsdSkelSkeletonQuery computes them.
//
// Skeleton: `joints` (token paths; a joint's parent is the nearest ancestor path in the list,
// which must come before it), `bindTransforms` (matrix4d[], world space at bind time, one per
// joint) and `restTransforms` (matrix4d[], joint-local). SkelAnimation: `joints` (any subset of
// the skeleton's, in any order, matched by name), `translations` (float3[]), `rotations` (quatf[]),
// `scales` (half3[]), each one per animated joint, composed scale, then rotate, then translate;
// `blendShapes` (token[]) with `blendShapeWeights` (float[]). Joints the animation leaves out keep
// their rest transforms.
//
// A joint's skeleton-space transform is its parent's times its local one; its skinning transform
// is that times the inverse of its bind transform (column vectors: M = J_skel · B⁻¹).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

struct Skeleton {
    std::string path;
    std::vector<std::string> joints;
    std::vector<int> parents;          // per joint: the parent joint, -1 for a root
    std::vector<Matrix4> inverseBind;  // the inverses of bindTransforms, per joint
    std::vector<Matrix4> rest;         // joint-local rest transforms; empty when unauthored or of the wrong size
};

// Raises SceneError naming the skeleton when its joints, bind transforms or hierarchy are unusable;
// `warn` reports restTransforms of the wrong size (left out).
Skeleton readSkeleton(const PrimReader& prim, const std::function<void(const std::string&)>& warn);

// A skeleton posed by an animation at the readers' time.
struct SkeletonPose {
    std::vector<Matrix4> skinning;          // per skeleton joint
    std::vector<std::string> blendShapes;   // the animation's blend shape names
    std::vector<double> blendShapeWeights;  // one per name
};

// `animation`: the bound SkelAnimation, or nullptr (the rest pose). An animation whose arrays do
// not match its joints is ignored with a warning (the rest pose, as USD falls back to); raises
// SceneError naming the skeleton when there is no pose at all (joints neither animated nor given
// rest transforms).
SkeletonPose poseSkeleton(const Skeleton& skeleton, const PrimReader* animation,
                          const std::function<void(const std::string&)>& warn);

}  // namespace fluence::delegate
