// Which side of a closed mesh is its inside, whatever way its triangles are wound.
//
// Glass, interior media and subsurface scattering need to know when a ray enters the solid a
// closed mesh bounds: integrators/medium_stack.h enters against the geometric normal, and the
// dielectric BSDF takes its relative index from the side of the shading normal the ray comes
// from. Both normals follow the triangles' winding, so a mesh wound inward (authored so, or
// mirrored by a transform with a negative determinant, which the delegate bakes into world-space
// positions) would be entered the wrong way round: a subsurface object rendered black. A closed
// mesh's winding is therefore checked against its signed volume once, when the render scene
// stores it, and an inward-wound one is turned outward (each triangle's second and third corners
// swapped, with their per-corner data), so it renders as its outward-wound twin. Shading normals
// that then point inward overall (authored with the inward winding) are turned outward too.
//
// A mesh is closed when every edge is shared by exactly two of its triangles, its corners welded
// by position (to a millionth of the mesh's extent), so a seam where the points are split joins;
// triangles with two corners at one point (a UV sphere's quads at its poles) are left out.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec.h"
#include "render/scene_description.h"

namespace fluence::render {

// A mesh's triangles and the data stored per triangle corner, which reversing the winding moves.
struct TriangleCorners {
    std::vector<std::uint32_t>& indices;  // 3 per triangle
    std::vector<Vec3f>& normals;          // empty, or 3 per triangle
    std::vector<RGB>& colors;             // empty, or 3 per triangle
    std::vector<CornerPrimvar>& primvars;
};

// Whether every edge of the triangles is shared by exactly two of them.
bool isClosed(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& indices);

// The volume the triangles enclose, positive when they are wound counter-clockwise seen from
// outside (their right-handed normals point out).
double signedVolume(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& indices);

// Whether a material fills the inside of a closed mesh with something a ray enters: glass,
// subsurface or an interior medium, and not thin-walled.
bool fillsItsInside(const MaterialDesc& material);

// Turns a closed mesh outward (see above). Returns false, changing nothing, when the mesh is not
// closed.
bool orientClosedMeshOutward(const std::vector<Vec3f>& positions, TriangleCorners corners);

}  // namespace fluence::render
