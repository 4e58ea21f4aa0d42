// A coarse grid of per-cell maxima and minima of a density grid, and the 3D-DDA that walks a ray
// through it, yielding the majorant segments of media/medium.h (MAJORANTS, MINORANTS).
//
// MODEL. The support of the density grid (the index box [lo - 1, hi + 1] around its active voxels,
// volumes/vdb_grid.h), grown by a margin of 1e-3 voxel, is divided into nx x ny x nz equal cells;
// cell edges need not fall on voxel centres. A cell holds the largest value the trilinear
// reconstruction can take inside it: the maximum of the background (which fills wherever nothing
// is stored) and of every stored value whose reach meets the cell, clamped at 0. A voxel at v
// reaches the open box (v - 1, v + 1), where its trilinear weight is non-zero, and a tile the same
// around its voxels; the reach is grown by the margin too. Interpolation is a convex combination,
// so value(p) <= cell(p) for every p: the grid is conservative. The margins absorb rounding: a
// point computed in float at a segment's end may land a little off the cell boundary the DDA
// crossed in double, but never by 1e-3 voxel, so it still lies under a cell that counted every
// value reaching it, and a point just past the grid's box lies outside the support, where the
// density is exactly 0.
//
// MINORANTS. A cell also holds the smallest value the trilinear reconstruction can take inside it
// (grown by the margin): the minimum, clamped at 0, over every lattice point that interpolation
// reads for a point of the cell (floor(q) and floor(q) + 1 on each axis, q in index space), stored
// or the background where nothing is stored; 0 for a cell that reaches beyond the support, where
// the density is 0. Interpolation is a convex combination, so cell minimum <= value(p) (up to
// float rounding, far inside media/majorant_check.h's tolerance). They are the control extinction
// of residual ratio tracking (media/ratio_tracking.h): where a cell is dense throughout, tracking
// draws tentative collisions only at the rate of the difference, and in a cell of constant density
// none at all. Found with the maxima in one visit of the stored values: each counts towards the
// cells whose lattice reaches it, and a cell whose lattice points are not all stored also takes
// the background.
//
// RESOLUTION. Cells are `voxelsPerCell` voxels on a side (8 by default: an OpenVDB leaf node, so a
// cell spans about one leaf), at most `maxCellsPerAxis` per axis (64; larger grids get larger cells),
// at least one. pbrt-v4's GridMedium uses a fixed 16^3; maxCellsPerAxis = 1 gives the single global
// majorant (the grid's maximum over its whole support) that bench/majorant_grid_bench.cpp compares
// against.
//
// DDA. Amanatides & Woo, "A fast voxel traversal algorithm for ray tracing" (Eurographics 1987), run
// in cell coordinates: the ray is mapped by the affine world-to-cell transform, which keeps its
// parameter t, so segment ends are distances along the world ray. Each crossing is computed afresh
// from the ray (in double precision) rather than accumulated, so consecutive segments share their
// ends exactly and cover the ray's overlap with the support without gaps or overlaps. Cells whose
// majorant is 0 are stepped over and reported as gaps, as media/medium.h allows.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/matrix.h"
#include "core/rgb.h"
#include "media/medium.h"
#include "volumes/vdb_grid.h"

namespace fluence::volumes {

struct MajorantGridOptions {
    double voxelsPerCell = 8.0;
    int maxCellsPerAxis = 64;
};

class MajorantGrid {
public:
    MajorantGrid() = default;  // empty: no cells, every ray misses
    explicit MajorantGrid(const FloatVdbGrid& grid, const MajorantGridOptions& options = {});

    bool empty() const { return cells_.empty(); }
    const Vec3i& resolution() const { return resolution_; }
    float cell(const Vec3i& c) const { return cells_[index(c)]; }
    // The smallest value the reconstruction takes in cell c (see MINORANTS).
    float minorant(const Vec3i& c) const { return minorants_[index(c)]; }
    // World space to cell coordinates: cell (i, j, k) is the box [i, i + 1] x [j, j + 1] x [k, k + 1].
    const Matrix4& worldToCell() const { return worldToCell_; }

private:
    friend class MajorantDda;  // walks the cells by their index
    std::size_t index(const Vec3i& c) const {
        return (std::size_t(c.z) * std::size_t(resolution_.y) + std::size_t(c.y)) * std::size_t(resolution_.x) +
               std::size_t(c.x);
    }

    Vec3i resolution_{0};
    std::vector<float> cells_, minorants_;
    Matrix4 worldToCell_ = Matrix4::identity();
};

// A stretch of a ray over which MajorantDda::next() would give segments end to end.
struct MajorantRun {
    float tMin = 0.0f, tMax = 0.0f;
};

// The cells of a MajorantGrid that the ray origin + t direction crosses within [tMin, tMax), in
// order, as majorant segments with sigmaMaj = cell value * scale and sigmaMin = cell minorant *
// minorantScale (0 by default: no control). Cells of value 0 are skipped. The grid must outlive
// the walk.
class MajorantDda {
public:
    MajorantDda(const MajorantGrid& grid, const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                const RGB& scale, const RGB& minorantScale = RGB(0.0f));

    // The next segment with a non-zero majorant; nullopt once the ray has left the grid or tMax.
    std::optional<media::MajorantSegment> next();
    // The next run of the segments next() would give, each starting where the one before ends, as
    // one stretch with the same float ends, without computing their coefficients (a walk of its
    // own below the majorants, such as volumes/trilinear_cells.h's, needs only where they are).
    // nullopt once they are exhausted. One walk uses next() or nextRun(), not both.
    std::optional<MajorantRun> nextRun();
    // How many cells the walk has stepped through so far (empty ones included): its cost.
    int cellsVisited() const { return cellsVisited_; }

private:
    // Steps into the next cell: its [entry, exit) and index; false once the walk is over.
    bool step(double& entry, double& exit, std::size_t& index);
    // The next segment's ends, as next() gives them, and its cell's index; false once there is none.
    bool nextSpan(float& tMin, float& tMax, std::size_t& index);
    // Where the ray crosses the plane through which it leaves cell_ along `axis` (only that axis's
    // crossing changes when the walk steps along it).
    double crossing(int axis) const;

    const MajorantGrid* grid_;
    RGB scale_, minorantScale_;
    Vec3d origin_, invDirection_;  // in cell coordinates
    Vec3i cell_{0}, step_{0};
    Vec3d crossing_{0.0};             // crossing(axis), per axis that the ray moves along
    std::int64_t cellIndex_ = 0;      // cell_'s index in the grid's arrays
    std::int64_t indexStep_[3] = {};  // how the index changes on a step along each axis
    double t_ = 0.0, tEnd_ = 0.0;     // the walk is at t_ in cell_ and stops at tEnd_
    bool done_ = true;
    int cellsVisited_ = 0;
    std::optional<MajorantRun> pending_;  // the first segment of the run after the one nextRun() gave
};

}  // namespace fluence::volumes
