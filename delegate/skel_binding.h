// UsdSkel bindings on a Mesh (SkelBindingAPI): the skinned pose a mesh renders in; and on the
// implicit gprims (Sphere, Cube, ...), whose tessellation is posed the same way.
//
// Only prims below a SkelRoot are skinned. From the mesh up to that SkelRoot, the nearest prim
// authoring each of these gives it (they inherit down namespace): `skel:skeleton` (the Skeleton),
// `primvars:skel:jointIndices` and `primvars:skel:jointWeights` (constant or vertex
// interpolation, elementSize influences per point), `primvars:skel:geomBindTransform`
// (identity when unauthored), `primvars:skel:skinningMethod` ("classicLinear", or
// "dualQuaternion") and `skel:joints` (the joint names the indices count in; the skeleton's joints
// when unauthored). `skel:animationSource` is read from the Skeleton, else its nearest ancestor
// that binds one. `skel:blendShapes` and `skel:blendShapeTargets` are the mesh's own: weights
// from the animation's `blendShapes`/`blendShapeWeights`, by name (0 for a name it does not
// animate). SkelBindingAPI need not be applied (older files do not apply it).
//
// The pose: blend shapes move the rest points (and vertex normals, by their normalOffsets);
// skinning (delegate/skel_skinning.h) takes them through geomBindTransform into skeleton space,
// where the skeleton's own transform places them in the world: a skinned mesh's own transform
// has no effect, as UsdSkel defines. A mesh with blend shapes but no joint influences stays in
// its own space. Authored normals (vertex, varying or faceVarying, not indexed) are skinned like
// their points; others are dropped, and the render core shades the triangles' geometric normals.
//
// Inside native instances: a skinned prim whose pose reads nothing outside its instance
// (skelInputsOutside is empty) is posed once, in the shared prototype; an instance holding one
// that does (an animation bound above the instanceable prim, as crowds do) cannot share a
// prototype, and the delegate de-instances it (delegate/skinned_instances.h). Not skinned:
// meshes inside point-instancer prototypes (they render in their rest pose), and curves and
// points (they render as authored).
//
// A binding that cannot apply (no skeleton, a skeleton or influences that are malformed, sizes
// that do not match) leaves the mesh in its rest pose with one warning naming the prim, as Hydra
// does.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "delegate/material_adapter.h"
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

// A mesh's skinned points and normals at one time code, in the mesh's own space (the space its
// points are authored in: its world transform takes them where UsdSkel puts them).
struct SkinnedPose {
    std::vector<double> points;                  // 3 per point
    std::optional<std::vector<double>> normals;  // the authored normals skinned; nullopt: drop them
    std::string normalsName;                     // the attribute they were read from ("primvars:normals" or "normals")
    bool animated = false;                       // the pose changes with time (animation, skeleton or shapes sampled)
};

// The mesh's skinned pose at `time`, or nullopt when it is not skinned (or its binding is
// malformed: warned, naming the prim). The motion blur of a skinned mesh samples this at each time.
std::optional<SkinnedPose> skinnedPose(const usd::Stage& stage, const usd::PrimSpec& mesh, double time,
                                       const Warn& warn);

// Poses `surface`, the tessellation of an implicit gprim `prim` (Sphere, Cube, ...) in its own
// space, by the prim's binding: constant (rigid) joint influences, as a Mesh's. nullopt when it is
// not skinned (or its binding is malformed: warned); else whether the pose is animated.
std::optional<bool> skinSurface(const usd::Stage& stage, const usd::PrimSpec& prim, double time, const Warn& warn,
                                render::MeshDesc& surface);

// Whether UsdSkel deforms `prim`: it lies below a SkelRoot and has joint influences (its own or
// inherited) or blend shapes. Whether its binding can apply is for skinnedPose to find.
bool isSkelDeformed(const usd::Stage& stage, const usd::PrimSpec& prim);

// The prims outside `subtree` (a path) that the UsdSkel pose of `prim` reads: the nearest owners
// of its binding attributes and of `skel:skeleton`, the Skeleton, the prim binding its
// `skel:animationSource` and that SkelAnimation, and its BlendShapes; sorted, each once. Empty
// when the prim is not skinned or its binding cannot apply (it renders in its rest pose).
std::vector<std::string> skelInputsOutside(const usd::Stage& stage, const usd::PrimSpec& prim,
                                           const std::string& subtree);

// A copy of the mesh's prim spec (children included) holding `pose` as its points and normals,
// with UsdSkel's primvars removed: what the mesh adapters read for a skinned mesh.
std::unique_ptr<usd::PrimSpec> posedMeshSpec(const usd::PrimSpec& mesh, const SkinnedPose& pose);

}  // namespace fluence::delegate
