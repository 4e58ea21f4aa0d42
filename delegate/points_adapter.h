// UsdGeomPoints -> render::PointsDesc (render/points_description.h).
//
// | attribute                      | read as                                                         |
// |--------------------------------|-----------------------------------------------------------------|
// | points                         | the centres (object space); none: an empty point set            |
// | widths / primvars:widths       | diameters (the primvar wins); constant (one value) or one per   |
// |                                | point; unauthored: 1, as Hydra's renderers draw them            |
// | normals / primvars:normals     | oriented discs' normals, one per point or constant              |
// | primvars:fluence:pointStyle    | token: "sphere" (default), "disc" (facing the ray), or          |
// |                                | "orientedDisc" (along `normals`; "disc" without normals)        |
// | primvars:displayColor          | diffuse colour, constant or one per point (indices honoured)    |
// | primvars:*                     | shading primvars a material reads (UsdPrimvarReader, a          |
// |                                | texture's st), constant or one per point (vertex, varying)      |
// | material:binding               | resolved as for meshes                                          |
// Widths or normals whose count is not the number of points, an unknown pointStyle, or a negative
// width raise SceneError naming the prim (it is skipped with a warning, or fails with --strict); a
// displayColor or shading primvar of the wrong count is ignored with a warning (`warn`), and what
// reads it falls back to its constant value.
#pragma once

#include <functional>
#include <string>

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/points_description.h"

namespace fluence::delegate {

// The points in object space (widths as radii; normals unnormalised).
render::PointsDesc pointsFromPrim(const PrimReader& prim,
                                  const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                  const std::function<void(const std::string&)>& warn);

// `points` moved into world space by `toWorld`: centres transformed, radii scaled by the cube
// root of the transform's volume scale (a sphere stays a sphere), normals as normals.
render::PointsDesc pointsToWorld(render::PointsDesc points, const Matrix4& toWorld);

}  // namespace fluence::delegate
