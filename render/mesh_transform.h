// Moving a MeshDesc between spaces (object or prototype space -> world space).
#pragma once

#include "core/matrix.h"
#include "render/scene_description.h"

namespace fluence::render {

// The mesh with its positions and shading normals transformed by `transform`. Under a mirroring
// transform the triangles' winding is flipped back, so that they keep facing outwards.
MeshDesc transformMesh(const MeshDesc& mesh, const Matrix4& transform);

}  // namespace fluence::render
