// One grid of an OpenVDB file, placed in the world and sampled by trilinear interpolation.
//
// SOURCE. A grid is read by name from an OpenVDB file, as a UsdVol OpenVDBAsset names it
// (filePath, fieldName, and fieldIndex to choose among grids of one name, in file order; a
// negative index, fieldIndex not authored, is the first). Float
// grids (density, temperature, flame) are read as FloatVdbGrid, vec3s grids (Cd, color, vel) as
// Vec3VdbGrid. Files are opened once per process and shared between grids and prims
// (volumes/vdb_file_cache.h); the grid's data is shared too, so several prims placing one grid
// cost one copy of its voxels (and each its own lookup table, volumes/vdb_grid.cpp).
//
// PLACEMENT. world = objectToWorld * gridTransform * index, where gridTransform is the grid's own
// index-to-object transform (voxel size, offset, rotation; only linear ones: frustum maps are
// refused) and objectToWorld the prim's transform (core/matrix.h conventions). OpenVDB puts a
// voxel's value at its centre: voxel (i, j, k) is the sample at the index-space point (i, j, k).
//
// RECONSTRUCTION. value(p) is the trilinear interpolation of the eight samples around p's
// index-space point, as OpenVDB's BoxSampler computes it (stored voxels and tiles, active or not,
// and the background where nothing is stored). The grid is confined to the support of its active
// voxels: with lo..hi the active voxels' index bounding box, the index box [lo - 1, hi + 1], the
// region trilinear interpolation reaches from those voxels. Outside it value(p) = 0, whatever the
// background: a medium made from a grid is finite. Empty grids are zero everywhere.
//
// ERRORS are std::runtime_error naming the file and the grid: those of the file cache (missing
// file, missing grid), a value type other than the one asked for, a non-linear transform.
//
// THREADS. Every const member may be called from any thread.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/function_ref.h"
#include "core/matrix.h"
#include "core/vec.h"

namespace fluence::volumes {

using Vec3i = Vec3<int>;

// A box of voxels lo..hi in index space, both ends included.
struct IndexBox {
    Vec3i lo, hi;
};

// An axis-aligned box in world space.
struct WorldBounds {
    Vec3f lo, hi;
};

// T is float or Vec3f (explicitly instantiated for those two in vdb_grid.cpp).
template <typename T>
class VdbGrid {
public:
    VdbGrid(const std::string& path, const std::string& name, int index = 0,
            const Matrix4& objectToWorld = Matrix4::identity());

    const std::string& path() const { return path_; }
    const std::string& name() const { return name_; }

    // The trilinearly interpolated value at world-space point p (see RECONSTRUCTION).
    T sample(const Vec3f& p) const;

    // The active voxels' index bounding box; nullopt for an empty grid.
    const std::optional<IndexBox>& activeVoxels() const { return activeVoxels_; }
    // The world-space bounding box of the support (see RECONSTRUCTION), rounded outward to float;
    // lo > hi for an empty grid.
    WorldBounds worldBounds() const;
    const Matrix4& indexToWorld() const { return indexToWorld_; }
    const Matrix4& worldToIndex() const { return worldToIndex_; }

    // The maximum over the stored values and the background (per component for Vec3f), which no
    // interpolated value exceeds; 0 for an empty grid.
    T maxValue() const;
    T background() const;
    // Calls visit(box, value) for every stored value: each voxel (lo == hi) and tile (a box of
    // voxels sharing one value), active or not. Values outside the support are visited too.
    void forEachValue(FunctionRef<void(const IndexBox&, const T&)> visit) const;

private:
    struct Data;  // the OpenVDB grid, shared with the file cache
    std::string path_, name_;
    std::shared_ptr<const Data> data_;
    Matrix4 indexToWorld_, worldToIndex_;
    std::optional<IndexBox> activeVoxels_;
};

using FloatVdbGrid = VdbGrid<float>;
using Vec3VdbGrid = VdbGrid<Vec3f>;

}  // namespace fluence::volumes
