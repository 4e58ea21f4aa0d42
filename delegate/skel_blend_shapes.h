// UsdSkel BlendShape prims and how they deform a mesh's rest points (and normals) before
// skinning, as UsdSkelBlendShapeQuery does.
//
// A BlendShape holds `offsets` (vector3f[]), optional `normalOffsets`, and optional
// `pointIndices` (int[]: the points the offsets apply to; all points, in order, when unauthored),
// plus in-between shapes `inbetweens:NAME` (vector3f[], with `weight` metadata; their normal
// offsets in `inbetweens:NAME:normalOffsets`). The shapes at weights 0 (no offset) and 1
// (`offsets`) are implied; an in-between at 0 or 1, without a weight, or with a weight another one
// has, is ignored with a warning naming the prim, as USD does. Each shape's offsets apply on their
// own: unauthored ones add nothing; authored ones must match `pointIndices` (or not outnumber the
// points).
//
// A weight w applies the two shapes whose weights bracket it (the lowest two below the first
// shape, the highest two above the last one: unbounded extrapolation), linearly interpolated:
// P' = P + b_l·(1 − t) + b_u·t, t = (w − α_l)/(α_u − α_l).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

struct BlendShape {
    struct Shape {
        double weight = 1.0;
        std::vector<Vec3d> offsets;
        std::vector<Vec3d> normalOffsets;  // empty when not authored
    };
    std::string path;
    std::vector<int> pointIndices;  // empty: offset i moves point i
    std::vector<Shape> shapes;      // by increasing weight, the implied null shape (weight 0) first

    // Why the shape cannot deform `pointCount` points (an index out of range, offsets of the
    // wrong size), or nullopt.
    std::optional<std::string> problem(std::size_t pointCount) const;
    // Adds the shape at `weight` to `points`, and to `normals` when given (normals per point).
    void apply(double weight, std::vector<Vec3d>& points, std::vector<Vec3d>* normals) const;
};

// Reads a BlendShape prim; `warn` reports an in-between that is ignored.
BlendShape readBlendShape(const PrimReader& prim, const std::function<void(const std::string&)>& warn);

}  // namespace fluence::delegate
