// The finite-element mesh of the radiosity integrator (integrators/radiosity.h): the scene's surface
// triangles (render::RenderScene::surfaceTriangles, world space) cut into patches, and the lookup
// that finds the patch under a surface point.
//
// Meshing: a triangle whose longest edge is L is cut into n^2 congruent triangles (each edge into
// n = ceil(L / maxEdge) equal parts, joined by lines parallel to the sides), so no patch edge is
// longer than maxEdge. Each patch keeps its triangle's albedo and emission (constant elements).
// The patch normal is (p1 - p0) x (p2 - p0), normalised: the winding's side, "side 0".
//
// Smoothing: cornerAverages() gives each element's corners the area-weighted mean of a per-element
// value over the elements that meet at that point and face the same way (side normals within
// kSmoothingCosine; across a crease such as a wall meeting the floor, each side keeps its own),
// for Gouraud interpolation over the patch.
//
// Lookup: a uniform grid of cells about the patches' mean size (gridCellSize; finely tessellated
// meshes have patches far smaller than maxEdge, and a cell should hold a few); each patch is listed in every cell its
// bounding box overlaps. locate(p, n) takes the patches in p's cell that lie in a plane through p
// (within a tolerance relative to the cell size) facing along +-n, and returns the one p lies in (or
// nearest to, for points on shared edges). Ray hits from render::RenderScene::intersect carry no
// triangle index, so this is how a hit is matched to its patch.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/rgb.h"
#include "core/vec.h"
#include "render/light.h"
#include "render/render_scene.h"

namespace fluence::integrators {

struct Patch {
    Vec3f p0, p1, p2;
    Vec3f normal;  // unit, side 0
    float area = 0.0f;
    RGB albedo, emission;
};

// The default maximum patch edge: the scene's bounding-sphere diameter over kDefaultPatchesPerDiameter
// (a Cornell box's wall is then cut into about 10 x 10 patches per edge).
inline constexpr float kDefaultPatchesPerDiameter = 16.0f;
float defaultPatchEdge(const render::SceneBounds& bounds);

// Every triangle cut into patches with no edge longer than maxEdge (> 0); degenerate triangles
// (zero area) are dropped.
std::vector<Patch> meshPatches(const std::vector<render::RenderScene::SurfaceTriangle>& triangles, float maxEdge);

// Elements: two per patch, element 2 * patch + side, side 0 facing along the patch normal.
inline constexpr int kSides = 2;
inline int elementOf(int patch, int side) { return kSides * patch + side; }
inline Vec3f sideNormal(const Patch& patch, int side) { return side == 0 ? patch.normal : -patch.normal; }

// Corners whose elements' normals are within this cosine share their values (about 25 degrees).
inline constexpr float kSmoothingCosine = 0.9f;
// Per element corner (3 * element + corner, the corners p0, p1, p2), the smoothed `values` (one
// per element).
std::vector<RGB> cornerAverages(const std::vector<Patch>& patches, const std::vector<RGB>& values);

// The scale of the lookup grid and of welding: the patches' mean longest edge, but no less than
// kMaxCellsPerPatch-th of the longest, so that no patch spans more than kMaxCellsPerPatch + 1
// cells along an axis.
inline constexpr float kMaxCellsPerPatch = 8.0f;
float gridCellSize(const std::vector<Patch>& patches);

// Where a point lies on the mesh: its patch and barycentrics (b1 along p1, b2 along p2).
struct PatchPoint {
    int patch;
    float b1, b2;
};

class PatchLocator {
public:
    PatchLocator() = default;
    explicit PatchLocator(const std::vector<Patch>& patches);

    // The patch that point p, on a surface with normal n (either side), lies on; nullopt if none.
    std::optional<PatchPoint> locate(const std::vector<Patch>& patches, const Vec3f& p, const Vec3f& n) const;

private:
    std::int64_t cellOf(float coordinate) const;  // a grid coordinate along one axis

    float cellSize_ = 1.0f;
    std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace fluence::integrators
