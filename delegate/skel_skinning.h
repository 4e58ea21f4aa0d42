// UsdSkel's skinning kernels: joint influences applied to points and normals, as
// UsdSkelSkinPoints / UsdSkelSkinNormals define them (pxr/usd/usdSkel/utils.h).
//
// Plain math on plain data (no stage): the transforms are the skinning transforms of the joints
// the influences index (inverse bind × joint skeleton-space transform, column-vector matrices),
// and the geomBindTransform takes the mesh's points into bind space first. Results are in
// skeleton space.
//
// * Linear blend (classicLinear): p' = Σ w · M_j · (G · p).
// * Dual quaternion (dualQuaternion): each M_j is factored into a rotation R_j, a translation and
//   the rest, a scale/shear S_j; the rest is blended linearly (Σ w · S_j · G·p, or G·p when every
//   S_j is the identity), the rigid parts as unit dual quaternions flipped onto the hemisphere of
//   the point's most weighted joint, summed and normalised.
// * Normals: linear blend by each M_j's inverse transpose (and G's); with dual quaternions, the
//   blended rotation (after the inverse-transposed scales, when there are any). Not normalised.
//
// Weights are used as authored (UsdSkel does not normalise them on read).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/matrix.h"

namespace fluence::delegate {

enum class SkinningMethod { ClassicLinear, DualQuaternion };

// `perPoint` (the primvars' elementSize) influences per point, or one set for every point when
// `constant` (rigid deformation).
struct JointInfluences {
    int perPoint = 1;
    bool constant = false;
    std::vector<int> indices;
    std::vector<double> weights;

    // Why the influences cannot skin `pointCount` points with `jointCount` joints (sizes that do
    // not match, a joint index out of range), or nullopt when they can.
    std::optional<std::string> problem(std::size_t pointCount, std::size_t jointCount) const;
};

// Skins `points` in place (see the top of this file). The influences must have no problem().
void skinPoints(SkinningMethod method, const Matrix4& geomBind, const std::vector<Matrix4>& skinning,
                const JointInfluences& influences, std::vector<Vec3d>& points);

// Skins `normals` in place; normal i takes the influences of point pointOf[i].
void skinNormals(SkinningMethod method, const Matrix4& geomBind, const std::vector<Matrix4>& skinning,
                 const JointInfluences& influences, const std::vector<std::size_t>& pointOf,
                 std::vector<Vec3d>& normals);

}  // namespace fluence::delegate
