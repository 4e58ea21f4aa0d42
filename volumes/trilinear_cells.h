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
// kMaxVoxels voxels (256 MiB of floats): such a grid is tracked, not walked. Beside it, a bit per
// cell says whether any of its eight corners is non-zero (1/32 of the copy's size, so it stays in
// cache where the copy does not): the walk steps over an empty cell without reading its corners.
//
// DDA. Amanatides & Woo's traversal in index space over the dual cells, as volumes/majorant_grid.h
// walks its cells: each crossing is computed from the ray in double precision, not accumulated, so
// consecutive pieces share their ends exactly.
//
// INTEGRAL. A stretch's integral is what the sums of media/exact_depth.h take from every cell the
// ray passes; the cubic is needed only where a flight stops in it. Simpson's rule is exact for a
// cubic: the integral over [t0, t1) is (t1 - t0) / 6 (f(t0) + 4 f(tm) + f(t1)), tm the midpoint,
// each f a trilinear interpolation of the cell's corners. f(t1), on the face the ray leaves the
// cell by, is f(t0) of the next cell (the same point of the shared face; 0 exactly after an empty
// cell), so a cell costs two interpolations, and its cubic is computed only when asked
// (CellStretch::cubic). Equal to the cubic's integral in real arithmetic, not bit for bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/vec.h"
#include "volumes/vdb_grid.h"

namespace fluence::volumes {

// A world ray in a grid's index space, prepared once (TrilinearCells::prepare) for walks over
// several stretches of it: the transforms, the clip to the support box and the divisions are the
// same for every stretch.
struct CellRay {
    Vec3d origin{0.0}, direction{0.0}, inverse{0.0};  // in index space; inverse = 1 / direction
    Vec3i step{0};                                    // the sign of each direction component
    double tIn = 0.0, tOut = -1.0;                    // the ray's stretch inside the support box
};

// One dual cell's stretch [tMin, tMax) of a ray, as TrilinearCells::walk hands it to its visitor.
class CellStretch {
public:
    double tMin = 0.0, tMax = 0.0;
    double integral = 0.0;  // of the density over [tMin, tMax) (INTEGRAL)

    // The density over the stretch as c[0] + c[1] s + c[2] s^2 + c[3] s^3, s = t - tMin (WHY CUBIC).
    void cubic(double c[4]) const;

private:
    friend class TrilinearCells;
    // What the cubic is computed from, when asked: the cell's corners in the dense copy (its first
    // corner, and the strides along y and z), its lower corner in index space, and the ray.
    const float* first_ = nullptr;
    std::size_t dy_ = 0, dz_ = 0;
    Vec3d corner_{0.0};
    const CellRay* ray_ = nullptr;
};

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

    // For the world ray origin + t direction within [tMin, tMax): calls visit(stretch), a
    // CellStretch, for each dual cell the ray crosses inside the support, in increasing t, until
    // visit returns false (then walk returns false). Cells whose eight corners are all 0 (empty space
    // inside the support) are skipped: the density is 0 over them, and a piece that adds 0 to every
    // sum changes none. A template, so the visitor is inlined into the DDA's loop.
    template <class Visit>
    bool walk(const Vec3f& origin, const Vec3f& direction, double tMin, double tMax, Visit&& visit) const {
        return walk(prepare(origin, direction), tMin, tMax, visit);
    }
    // The same, for a ray prepared once and walked over several stretches.
    CellRay prepare(const Vec3f& origin, const Vec3f& direction) const;
    template <class Visit>
    bool walk(const CellRay& ray, double tMin, double tMax, Visit&& visit) const;

private:
    std::size_t offset(const Vec3i& v) const {
        return (std::size_t(v.z - lo_.z) * std::size_t(size_.y) + std::size_t(v.y - lo_.y)) * std::size_t(size_.x) +
               std::size_t(v.x - lo_.x);
    }
    // Whether any of the eight corners of the cell whose first corner is at `index` in the array is
    // non-zero (else the density is 0 over all of the cell).
    bool occupied(std::size_t index) const { return occupied_[index >> 6] >> (index & 63) & 1; }

    Vec3i lo_{0}, size_{0};  // the dense box's first voxel and extent (the support's lattice)
    std::vector<float> values_;
    std::vector<std::uint64_t> occupied_;  // bit i: a corner of the cell whose first corner is values_[i] is non-zero
    float minValue_ = std::numeric_limits<float>::infinity();
    Matrix4 worldToIndex_ = Matrix4::identity();
};

// The trilinear interpolation of corners v[zyx] at local coordinates q.
inline double interpolate(const double v[8], const Vec3d& q) {
    const double a0 = v[0] + q.x * (v[1] - v[0]), a1 = v[2] + q.x * (v[3] - v[2]);
    const double a2 = v[4] + q.x * (v[5] - v[4]), a3 = v[6] + q.x * (v[7] - v[6]);
    const double b0 = a0 + q.y * (a1 - a0), b1 = a2 + q.y * (a3 - a2);
    return b0 + q.z * (b1 - b0);
}

// Corners v[zyx] (bit 0: x + 1, bit 1: y + 1, bit 2: z + 1) of the cell whose first corner is p in
// an array of strides dy and dz along y and z.
inline void readCorners(const float* p, std::size_t dy, std::size_t dz, double v[8]) {
    v[0] = p[0], v[1] = p[1], v[2] = p[dy], v[3] = p[dy + 1];
    v[4] = p[dz], v[5] = p[dz + 1], v[6] = p[dz + dy], v[7] = p[dz + dy + 1];
}

template <class Visit>
bool TrilinearCells::walk(const CellRay& ray, double tMin, double tMax, Visit&& visit) const {
    if (!available()) return true;
    const Vec3d &o = ray.origin, &d = ray.direction, &inverse = ray.inverse;
    const Vec3i& step = ray.step;
    double t = std::max(tMin, ray.tIn);
    const double tEnd = std::min(tMax, ray.tOut);
    if (!(t < tEnd)) return true;
    // Cells are indexed by their lower corner, lo - 1 .. hi: the box's lattice less its last plane.
    const Vec3i last = lo_ + size_ - Vec3i(2);
    Vec3i cell;
    Vec3d corner, tNext;  // corner: the cell's lower corner, in doubles (exact integers)
    for (int axis = 0; axis < 3; ++axis) {
        cell[axis] = std::clamp(int(std::floor(o[axis] + t * d[axis])), lo_[axis], last[axis]);
        corner[axis] = cell[axis];
        tNext[axis] = step[axis] == 0 ? INFINITY : (cell[axis] + (step[axis] > 0 ? 1 : 0) - o[axis]) * inverse[axis];
    }
    // The cell's first corner in the array, and how it moves on a step along each axis.
    const std::size_t dy = std::size_t(size_.x), dz = dy * std::size_t(size_.y);
    auto first = std::ptrdiff_t(offset(cell));
    const std::ptrdiff_t move[3] = {step.x, step.y * std::ptrdiff_t(dy), step.z * std::ptrdiff_t(dz)};
    CellStretch stretch;
    stretch.dy_ = dy;
    stretch.dz_ = dz;
    stretch.ray_ = &ray;
    // The density where the ray enters the current cell, once known (INTEGRAL).
    double entryDensity = 0.0;
    bool entryKnown = false;
    while (t < tEnd) {
        const int axis = tNext.x <= tNext.y ? (tNext.x <= tNext.z ? 0 : 2) : (tNext.y <= tNext.z ? 1 : 2);
        const double t1 = std::min(tNext[axis], tEnd);
        if (t1 > t) {
            if (occupied(std::size_t(first))) {
                stretch.tMin = t;
                stretch.tMax = t1;
                stretch.first_ = values_.data() + first;
                stretch.corner_ = corner;
                double v[8];
                readCorners(stretch.first_, dy, dz, v);
                if (!entryKnown) entryDensity = interpolate(v, o + d * t - corner);
                const double exitDensity = interpolate(v, o + d * t1 - corner);
                const double middle = interpolate(v, o + d * (0.5 * (t + t1)) - corner);
                stretch.integral = (t1 - t) * (1.0 / 6.0) * (entryDensity + 4.0 * middle + exitDensity);
                entryDensity = exitDensity;
                if (!visit(stretch)) return false;
            } else {
                entryDensity = 0.0;
            }
            entryKnown = true;
        }
        t = t1;
        cell[axis] += step[axis];
        if (cell[axis] < lo_[axis] || cell[axis] > last[axis]) break;
        corner[axis] += step[axis];
        first += move[axis];
        tNext[axis] = (corner[axis] + (step[axis] > 0 ? 1.0 : 0.0) - o[axis]) * inverse[axis];
    }
    return true;
}

}  // namespace fluence::volumes
