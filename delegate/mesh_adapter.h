// UsdGeomMesh with subdivisionScheme "none" -> render::MeshDesc: polygons fan-triangulated.
//
// Reads points, faceVertexCounts, faceVertexIndices, holeIndices, orientation, normals (or
// primvars:normals, which wins, as in USD) and primvars:displayColor, each primvar honouring its
// interpolation (constant, uniform, vertex, varying, faceVarying) and an optional ":indices"
// array. Topology errors (counts that do not add up, indices out of range, primvars of the wrong
// length) raise SceneError naming the prim. Subdivision surfaces (every other scheme) go through
// delegate/subdivision_mesh.h instead. Per-face materials (materialBind GeomSubsets) split the
// result in geom_subset.h.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

// `convertColor` maps an authored colour (with the attribute's colorSpace, "" if none) into the
// rendering space.
render::MeshDesc meshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                              const std::function<RGB(const RGB&, const std::string&)>& convertColor);

// The same mesh with its face bookkeeping, for per-face data such as GeomSubsets: the authored
// face (index into faceVertexCounts) each triangle came from, and the number of authored faces
// (holes and faces of fewer than 3 vertices included, as GeomSubset indices count them).
struct TriangulatedMesh {
    render::MeshDesc mesh;
    std::vector<std::size_t> triangleFaces;  // one per triangle
    std::size_t faceCount = 0;
};

TriangulatedMesh triangulatedMeshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                                          const std::function<RGB(const RGB&, const std::string&)>& convertColor);

}  // namespace fluence::delegate
