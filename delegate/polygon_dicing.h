// Polygon meshes cut finer for the camera, so that displacement has vertices to move.
//
// A polygon Mesh (fan-triangulated by delegate/mesh_adapter.h) has only its authored points. When
// its material displaces (delegate/displacement.h), each of its triangles is cut into a regular
// grid of N x N triangles, N the largest segment count of its three edges, each edge's count
// chosen from the camera by the rule subdivision surfaces follow (delegate/dicing.h:
// --dicing-rate, the off-screen factor, --subdiv-level N for 2^N segments everywhere, and the
// per-mesh triangle budget, which scales the rates down with a warning).
//
// Watertight: an edge is shared by the triangles on both sides, which may pick different N, so a
// grid vertex on a triangle's side is moved to the nearest of that edge's own `segments + 1`
// evenly spaced points (grid triangles along the side may collapse to zero area; no ray hits
// those). Both sides compute the same points from the edge's lower-numbered point in the same
// arithmetic, and interpolate their corner data the same way, so the pieces meet bit for bit (by
// value: Embree's robust triangle test) before and after displacement, wherever what drives the
// displacement (st) is continuous across the edge. A seam in st stays a seam, and a displacement
// map that differs across it opens a crack there, as in other renderers.
//
// The direction of displacement is the base mesh's smooth normal: per point, the area-weighted
// normal of its triangles, interpolated over each triangle (authored normals shade the undisplaced
// mesh only: a displaced mesh's shading normals are its own).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/matrix.h"
#include "delegate/dicing.h"
#include "render/scene_description.h"

namespace fluence::delegate {

// A mesh's edges, each once, as (lower, higher) point indices, and the edge of each triangle side.
class TriangleEdges {
public:
    explicit TriangleEdges(const render::MeshDesc& mesh);
    const std::vector<std::pair<int, int>>& edges() const { return edges_; }
    // The edge of side s (from corner s to corner s + 1 mod 3) of triangle t.
    std::size_t sideEdge(std::size_t t, int s) const { return sideEdges_[3 * t + static_cast<std::size_t>(s)]; }

private:
    std::vector<std::pair<int, int>> edges_;
    std::vector<std::size_t> sideEdges_;
};

// The mesh cut with `segments[e]` segments on edges()[e], and the base surface's unit smooth
// normal at each of its vertices.
struct DicedTriangles {
    render::MeshDesc mesh;
    std::vector<Vec3f> normals;
};
DicedTriangles diceTriangles(const render::MeshDesc& mesh, const TriangleEdges& edges,
                             const std::vector<int>& segments);
// How many triangles diceTriangles makes.
std::size_t dicedTriangleCount(const TriangleEdges& edges, std::size_t triangles, const std::vector<int>& segments);

// An object-space polygon mesh part bound to `materialPath`, diced for the camera as `placements`
// (object to world) put it, within the per-mesh budget, and displaced; nullopt when the material
// displaces nothing (the part is then used as it is, bit for bit).
std::optional<render::MeshDesc> displacedPart(const render::MeshDesc& objectSpace, const std::string& materialPath,
                                              const std::vector<Matrix4>& placements, const DicingContext& context);

}  // namespace fluence::delegate
