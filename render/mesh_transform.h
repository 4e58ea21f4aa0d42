// Moving a MeshDesc between spaces (object or prototype space -> world space), and its area.
#pragma once

#include <vector>

#include "core/matrix.h"
#include "render/scene_description.h"

namespace fluence::render {

// The mesh with its positions and shading normals transformed by `transform`. Under a mirroring
// transform the triangles' winding is flipped back, so that they keep facing outwards.
MeshDesc transformMesh(const MeshDesc& mesh, const Matrix4& transform);

// The summed area of the mesh's triangles, in its own space.
float surfaceArea(const MeshDesc& mesh);

// Curves' or points' control points, radii and normals (render/curves_description.h,
// render/points_description.h) moved by `transform`: the points transformed, the radii scaled by
// the cube root of its volume scale, the normals by its inverse transpose, kept unit length.
void transformPrimitives(std::vector<Vec3f>& points, std::vector<float>& radii, std::vector<Vec3f>& normals,
                         const Matrix4& transform);

}  // namespace fluence::render
