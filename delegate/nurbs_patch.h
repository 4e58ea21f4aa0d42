// UsdGeomNurbsPatch tessellated: the rational B-spline surface its control points, weights,
// knots and orders define, evaluated on a grid over uRange x vRange (object space).
//
// | attribute                  | read as                                                              |
// |----------------------------|----------------------------------------------------------------------|
// | uVertexCount, vVertexCount | control points along u and v; `points` holds u-major rows (u fastest) |
// | uOrder, vOrder             | degree + 1 (2: linear, 4: cubic)                                      |
// | uKnots, vKnots             | vertexCount + order non-decreasing knots                              |
// | uRange, vRange             | the parameter range drawn (fallback: knots[order-1] .. knots[count])  |
// | pointWeights               | rational weights, one per point (fallback: all 1)                     |
// | orientation                | "leftHanded" flips the winding and the normals                       |
// | uForm, vForm               | not needed: closed and periodic patches repeat their points already   |
// | trimCurve:*                | not applied: the whole patch renders, with a warning                  |
// Each non-empty knot span is cut into 1 (order 2) or kNurbsSpanSegments steps; vertices lie on
// the exact surface, normals are the surface's (du x dv, by central differences in parameter
// space). Counts, orders, knots or weights that do not fit raise SceneError naming the prim.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

inline constexpr int kNurbsSpanSegments = 16;

struct TessellatedSurface {
    std::vector<Vec3d> points, normals;  // one normal per point
    std::vector<std::uint32_t> indices;  // 3 per triangle, counter-clockwise seen from the normals' side
};

TessellatedSurface tessellateNurbsPatch(const PrimReader& prim, const std::function<void(const std::string&)>& warn);

}  // namespace fluence::delegate
