// A float grid's trilinear reconstruction along a ray, exactly: the cubic polynomial of the density
// in each cell between voxel centres that the ray crosses (the pieces of media/medium.h's EXACT
// EXTINCTION, before a medium scales them).
//
// WHY CUBIC. OpenVDB's BoxSampler (volumes/vdb_grid.h, RECONSTRUCTION) interpolates the eight
// voxels around an index-space point q: in the dual cell [i, i + 1] x [j, j + 1] x [k, k + 1] (i, j,
// k integers: voxel centres), with local coordinates (x, y, z) = q - (i, j, k) in [0, 1]^3,
//   f = c000 + cx x + cy y + cz z + cxy x y + cxz x z + cyz y z + cxyz x y z,
// the monomial form of the eight corners' weights. The index transform is linear, so along a world
// ray x, y and z are linear in the distance t; the product of three linear functions is a cubic,
// and the density over the stretch of the ray in one cell is a cubic in s = t - (the stretch's
// start). Outside the support box [lo - 1, hi + 1] the grid is 0 (RECONSTRUCTION).
//
// STORAGE. The voxels the support reads, lo - 1 .. hi + 1 on each axis, are copied into a dense
// array once (stored voxels and tiles from VdbGrid::forEachValue, the background elsewhere), so a
// cell's eight corners are eight array reads. The copy is refused (available() false) above
// kMaxVoxels voxels (256 MiB of floats): such a grid is tracked, not walked.
//
// DDA. Amanatides & Woo's traversal in index space over the dual cells, as volumes/majorant_grid.h
// walks its cells: each crossing is computed from the ray in double precision, not accumulated, so
// consecutive pieces share their ends exactly.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "core/vec.h"
#include "volumes/vdb_grid.h"

namespace fluence::volumes {

class TrilinearCells {
public:
    static constexpr std::size_t kMaxVoxels = std::size_t(64) << 20;

    TrilinearCells() = default;  // unavailable
    explicit TrilinearCells(const FloatVdbGrid& grid);

    // Whether the dense copy was made (a non-empty grid within kMaxVoxels).
    bool available() const { return !values_.empty(); }
    // The smallest value the reconstruction reads (stored values and the background): the grid is
    // >= 0 wherever it is non-zero iff this is >= 0. +infinity for an unavailable grid.
    float minValue() const { return minValue_; }

    // For the world ray origin + t direction within [tMin, tMax): calls visit(t0, t1, c) for each
    // dual cell the ray crosses inside the support, in increasing t, where the density over [t0, t1)
    // is c[0] + c[1] s + c[2] s^2 + c[3] s^3 with s = t - t0, until visit returns false (then walk
    // returns false). Cells whose eight corners are all 0 (empty space inside the support) are
    // skipped: the density is 0 over them, and a piece that adds 0 to every sum changes none. A template, so the visitor is inlined into the DDA's loop.
    template <class Visit>
    bool walk(const Vec3f& origin, const Vec3f& direction, double tMin, double tMax, Visit&& visit) const;

private:
    std::size_t offset(const Vec3i& v) const {
        return (std::size_t(v.z - lo_.z) * std::size_t(size_.y) + std::size_t(v.y - lo_.y)) * std::size_t(size_.x) +
               std::size_t(v.x - lo_.x);
    }
    // The ray's stretch [t0, t1) inside the support box, or false.
    bool clip(const Vec3d& o, const Vec3d& d, double& t0, double& t1) const;
    // The cubic of cell `cell` along the index-space ray o + t d, about t (WHY CUBIC); false (and c
    // not written) where the cell's eight corners are all 0, so the density is 0 over all of it.
    bool cubic(const Vec3i& cell, const Vec3d& o, const Vec3d& d, double t, double c[4]) const;

    Vec3i lo_{0}, size_{0};  // the dense box's first voxel and extent (the support's lattice)
    std::vector<float> values_;
    float minValue_ = std::numeric_limits<float>::infinity();
    Matrix4 worldToIndex_ = Matrix4::identity();
};

template <class Visit>
bool TrilinearCells::walk(const Vec3f& origin, const Vec3f& direction, double tMin, double tMax, Visit&& visit) const {
    if (!available()) return true;
    const Vec3d o = worldToIndex_.transformPoint(Vec3d(origin)), d = worldToIndex_.transformVector(Vec3d(direction));
    double t = tMin, tEnd = tMax;
    if (!clip(o, d, t, tEnd)) return true;
    // Cells are indexed by their lower corner, lo - 1 .. hi: the box's lattice less its last plane.
    const Vec3i last = lo_ + size_ - Vec3i(2);
    Vec3i cell, step;
    Vec3d tNext, inverse;
    for (int axis = 0; axis < 3; ++axis) {
        cell[axis] = std::clamp(int(std::floor(o[axis] + t * d[axis])), lo_[axis], last[axis]);
        step[axis] = d[axis] > 0.0 ? 1 : (d[axis] < 0.0 ? -1 : 0);
        inverse[axis] = 1.0 / d[axis];
        tNext[axis] = step[axis] == 0 ? INFINITY : (cell[axis] + (step[axis] > 0 ? 1 : 0) - o[axis]) * inverse[axis];
    }
    while (t < tEnd) {
        const int axis = tNext.x <= tNext.y ? (tNext.x <= tNext.z ? 0 : 2) : (tNext.y <= tNext.z ? 1 : 2);
        const double t1 = std::min(tNext[axis], tEnd);
        if (t1 > t) {
            double c[4];
            if (cubic(cell, o, d, t, c) && !visit(t, t1, c)) return false;
        }
        t = t1;
        cell[axis] += step[axis];
        if (cell[axis] < lo_[axis] || cell[axis] > last[axis]) break;
        tNext[axis] = (cell[axis] + (step[axis] > 0 ? 1 : 0) - o[axis]) * inverse[axis];
    }
    return true;
}

}  // namespace fluence::volumes
