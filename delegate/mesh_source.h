// The prim spec the mesh adapters read for a Mesh or TetMesh prim at a time: a TetMesh's boundary
// surface as a Mesh (delegate/tet_mesh.h), posed by its UsdSkel binding when it is skinned
// (delegate/skel_binding.h); the prim itself when neither applies.
#pragma once

#include <memory>
#include <optional>

#include "delegate/skel_binding.h"

namespace fluence::delegate {

struct MeshSource {
    std::unique_ptr<usd::PrimSpec> copy;  // the surface, or the posed copy, when there is one
    std::optional<SkinnedPose> pose;      // set when the prim is skinned

    const usd::PrimSpec& prim(const usd::PrimSpec& authored) const { return copy ? *copy : authored; }
};

// `prim`'s source at `time`; an implicit gprim's is the prim itself (skinSurface poses its
// tessellation). Raises SceneError naming a TetMesh whose indices are malformed.
MeshSource meshSource(const usd::Stage& stage, const usd::PrimSpec& prim, double time, const Warn& warn);

}  // namespace fluence::delegate
