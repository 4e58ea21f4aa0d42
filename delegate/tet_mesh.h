// UsdGeomTetMesh: a volume of tetrahedra, rendered as its boundary surface.
//
// The surface is `surfaceFaceVertexIndices` (int3[], one triangle per element) when authored, else
// the triangles that belong to one tetrahedron only, as UsdGeomTetMesh::ComputeSurfaceFaces finds
// them: tetrahedron (a, b, c, d) has the faces (b, c, d), (a, d, c), (a, b, d), (a, c, b), which
// wind outward for a right-handed tetrahedron; a face two tetrahedra share is interior. The
// surface renders as the polygon Mesh of those triangles (never subdivided), with the TetMesh's
// `orientation`, transform, `points` (time-sampled, with velocities), constant and vertex
// primvars, normals and material binding, as a Mesh reads them.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "delegate/prim_reader.h"
#include "scene/layer.h"

namespace fluence::delegate {

// The faces of `tets` that belong to one tetrahedron only, each with the winding its tetrahedron
// gives it, sorted (as OpenUSD sorts them).
std::vector<std::array<int, 3>> tetSurfaceFaces(const std::vector<std::array<int, 4>>& tets);

// A copy of the TetMesh `prim` (read at the reader's time) as the polygon Mesh of its surface:
// type "Mesh", `faceVertexCounts` all 3, `faceVertexIndices` the surface's triangles,
// `subdivisionScheme` "none". Raises SceneError naming the prim when its indices are malformed
// (not triples or quadruples, or a point index out of range).
std::unique_ptr<usd::PrimSpec> tetMeshSurface(const PrimReader& prim);

}  // namespace fluence::delegate
