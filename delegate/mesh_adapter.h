// UsdGeomMesh -> render::MeshDesc: polygons fan-triangulated, in world space.
//
// Reads points, faceVertexCounts, faceVertexIndices, holeIndices, orientation, normals (or
// primvars:normals, which wins, as in USD) and primvars:displayColor, each primvar honouring its
// interpolation (constant, uniform, vertex, varying, faceVarying) and an optional ":indices"
// array. Topology errors (counts that do not add up, indices out of range, primvars of the wrong
// length) raise SceneError naming the prim. Subdivision (issue 5) is not applied yet: a
// subdivision surface renders as its control cage.
#pragma once

#include <functional>
#include <string>

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

// `convertColor` maps an authored colour (with the attribute's colorSpace, "" if none) into the
// rendering space.
render::MeshDesc meshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                              const std::function<RGB(const RGB&, const std::string&)>& convertColor);

}  // namespace fluence::delegate
