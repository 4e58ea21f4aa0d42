// Screen-space dicing: how finely each subdivision surface is tessellated for the camera.
//
// A subdivision mesh's limit surface is tessellated with a segment count per base-mesh edge. The
// count comes from the edge alone (its two world-space endpoints), so the two faces that share an
// edge always agree and the tessellation stays watertight:
//
//     segments = ceil(length * pixelsPerUnit / rate), clamped to [1, maxSegments]
//
// where pixelsPerUnit is the largest of the camera's pixels per scene unit at the edge's ends,
// quarters and middle (render::Camera::pixelsPerUnitAt, by distance from the eye, so nearer edges
// get more), and
// `rate` is the dicing rate in pixels per micro-edge (--dicing-rate, default 1; a prim's
// `primvars:fluence:dicingRate` overrides it), multiplied by `offscreenFactor` when no point of
// the edge (its ends, quarters and middle) is in view (the image grown by `margin` on every
// side). A face seen only through its interior, with every edge off-screen, is diced as if
// off-screen: the price of rates that depend on edges alone. With `uniformLevel` >= 0
// (--subdiv-level N) every edge gets 2^N segments and the camera is ignored, for comparisons.
//
// Budgets: a mesh whose tessellation would exceed `meshTriangleBudget` triangles, or a scene whose
// subdivision meshes together would exceed `sceneTriangleBudget`, is diced again with its rates
// scaled down to fit, and a warning says so.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/matrix.h"
#include "core/vec.h"
#include "render/camera.h"

namespace fluence::delegate {

struct DicingSettings {
    float rate = 1.0f;  // pixels per micro-edge
    int uniformLevel = -1;
    float offscreenFactor = 8.0f;
    float margin = 0.1f;
    int maxSegments = 256;
    std::size_t meshTriangleBudget = 4'000'000;
    std::size_t sceneTriangleBudget = 40'000'000;
};

class MaterialDisplacement;  // delegate/displacement.h

// Everything a dice needs besides the mesh.
struct DicingContext {
    const render::Camera& camera;
    const DicingSettings& settings;
    // The material's displacement, or nullptr when it displaces nothing.
    std::function<const MaterialDisplacement*(const std::string& materialPath)> displacement;
    std::function<void(const std::string& primPath, const std::string& message)> warn;
    float scale = 1.0f;  // < 1 when the scene's triangle budget shrinks every rate
};

// Segments for each world-space edge (endpoints a, b) seen by `camera` at dicing rate `rate`
// (the mesh's own, or the settings' rate). `scale` (<= 1) shrinks every count, for budgets.
std::vector<int> edgeSegments(const render::Camera& camera, const DicingSettings& settings, float rate,
                              const std::vector<std::pair<Vec3f, Vec3f>>& edges, float scale = 1.0f);

// Segments for edges between object-space `points` (index pairs) of a mesh that `placements`
// (object to world) put in the scene several times: per edge the largest count over the
// placements nearest the camera (at most 16; a prototype's other instances are farther).
std::vector<int> placedEdgeSegments(const render::Camera& camera, const DicingSettings& settings, float rate,
                                    const std::vector<Vec3f>& points, const std::vector<std::pair<int, int>>& edges,
                                    const std::vector<Matrix4>& placements, float scale);

}  // namespace fluence::delegate
