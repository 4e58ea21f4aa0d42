#include "volumes/majorant_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fluence::volumes {

namespace {

// How far beyond its trilinear support a stored value is counted, and the grid's box beyond the
// grid's support, in voxels (see MODEL).
constexpr double kMargin = 1e-3;

// Along one axis, the lattice points interpolation reads for the points of each cell, grown by the
// margin (cell i reads first[i]..last[i], both non-decreasing in i), and whether the cell reaches
// beyond the support [activeLo - 1, activeHi + 1] (see MINORANTS).
struct AxisLattice {
    std::vector<int> first, last;
    std::vector<bool> beyondSupport;
};

AxisLattice axisLattice(int cells, double lo, double cellSize, int activeLo, int activeHi) {
    AxisLattice lattice;
    for (int i = 0; i < cells; ++i) {
        double from = lo + i * cellSize - kMargin, to = lo + (i + 1) * cellSize + kMargin;
        lattice.first.push_back(int(std::floor(from)));
        lattice.last.push_back(int(std::floor(to)) + 1);
        lattice.beyondSupport.push_back(from < activeLo - 1.0 || to > activeHi + 1.0);
    }
    return lattice;
}

}  // namespace

MajorantGrid::MajorantGrid(const FloatVdbGrid& grid, const MajorantGridOptions& options) {
    if (!grid.activeVoxels()) return;
    const IndexBox& active = *grid.activeVoxels();
    Vec3d lo, cellSize;  // of the support grown by the margin (see MODEL)
    AxisLattice lattice[3];
    for (int axis = 0; axis < 3; ++axis) {
        double extent = active.hi[axis] - active.lo[axis] + 2.0;
        resolution_[axis] =
            std::clamp(int(std::ceil(extent / options.voxelsPerCell)), 1, std::max(options.maxCellsPerAxis, 1));
        lo[axis] = active.lo[axis] - 1.0 - kMargin;
        cellSize[axis] = (extent + 2.0 * kMargin) / resolution_[axis];
        lattice[axis] = axisLattice(resolution_[axis], lo[axis], cellSize[axis], active.lo[axis], active.hi[axis]);
    }
    worldToCell_ = Matrix4::scale(Vec3d(1.0) / cellSize) * Matrix4::translate(-lo) * grid.worldToIndex();

    const std::size_t cellCount = std::size_t(resolution_.x) * std::size_t(resolution_.y) * std::size_t(resolution_.z);
    const float base = std::max(grid.background(), 0.0f);
    cells_.assign(cellCount, base);
    std::vector<float> lowest(cellCount, std::numeric_limits<float>::infinity());  // over the stored lattice points
    std::vector<std::int64_t> stored(cellCount, 0);  // how many of a cell's lattice points hold a stored value
    auto raiseMaxima = [&](const IndexBox& box, float value) {
        if (!(value > base)) return;
        Vec3i first, last;  // the cells the value reaches
        for (int axis = 0; axis < 3; ++axis) {
            double from = (box.lo[axis] - 1.0 - kMargin - lo[axis]) / cellSize[axis];
            double to = (box.hi[axis] + 1.0 + kMargin - lo[axis]) / cellSize[axis];
            if (to < 0.0 || from > resolution_[axis]) return;  // entirely outside the support
            first[axis] = int(std::clamp(std::floor(from), 0.0, resolution_[axis] - 1.0));
            last[axis] = int(std::clamp(std::floor(to), 0.0, resolution_[axis] - 1.0));
        }
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    float& c = cells_[index({x, y, z})];
                    c = std::max(c, value);
                }
    };
    auto lowerMinima = [&](const IndexBox& box, float value) {
        Vec3i first, last;  // the cells whose lattice holds some of the box's points
        for (int axis = 0; axis < 3; ++axis) {
            const AxisLattice& l = lattice[axis];
            first[axis] = int(std::lower_bound(l.last.begin(), l.last.end(), box.lo[axis]) - l.last.begin());
            last[axis] = int(std::upper_bound(l.first.begin(), l.first.end(), box.hi[axis]) - l.first.begin()) - 1;
            if (first[axis] > last[axis]) return;
        }
        auto overlap = [&](int axis, int i) {
            const AxisLattice& l = lattice[axis];
            return std::int64_t(std::min(box.hi[axis], l.last[i]) - std::max(box.lo[axis], l.first[i]) + 1);
        };
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    const std::size_t i = index({x, y, z});
                    stored[i] += overlap(0, x) * overlap(1, y) * overlap(2, z);
                    lowest[i] = std::min(lowest[i], value);
                }
    };
    grid.forEachValue([&](const IndexBox& box, const float& value) {
        raiseMaxima(box, value);
        lowerMinima(box, value);
    });

    minorants_.assign(cellCount, 0.0f);
    for (int z = 0; z < resolution_.z; ++z)
        for (int y = 0; y < resolution_.y; ++y)
            for (int x = 0; x < resolution_.x; ++x) {
                const int cell[3] = {x, y, z};
                std::int64_t points = 1;
                bool beyond = false;
                for (int axis = 0; axis < 3; ++axis) {
                    const AxisLattice& l = lattice[axis];
                    points *= l.last[cell[axis]] - l.first[cell[axis]] + 1;
                    beyond = beyond || l.beyondSupport[cell[axis]];
                }
                if (beyond) continue;
                const std::size_t i = index({x, y, z});
                const float least = stored[i] < points ? std::min(lowest[i], grid.background()) : lowest[i];
                minorants_[i] = std::max(least, 0.0f);
            }
}

MajorantDda::MajorantDda(const MajorantGrid& grid, const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                         const RGB& scale, const RGB& minorantScale)
    : grid_(&grid), scale_(scale), minorantScale_(minorantScale) {
    if (grid.empty() || !(tMax > tMin)) return;
    origin_ = grid.worldToCell().transformPoint(Vec3d(origin));
    Vec3d d = grid.worldToCell().transformVector(Vec3d(direction));
    const Vec3i& n = grid.resolution();
    double t0 = tMin, t1 = tMax;  // the overlap of [tMin, tMax] with the grid's box [0, n]
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (origin_[axis] < 0.0 || origin_[axis] > n[axis]) return;
            continue;
        }
        step_[axis] = d[axis] > 0.0 ? 1 : -1;
        invDirection_[axis] = 1.0 / d[axis];
        double ta = -origin_[axis] * invDirection_[axis], tb = (n[axis] - origin_[axis]) * invDirection_[axis];
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    if (!(t0 < t1)) return;
    t_ = t0;
    tEnd_ = t1;
    for (int axis = 0; axis < 3; ++axis)
        cell_[axis] = int(std::clamp(std::floor(origin_[axis] + d[axis] * t0), 0.0, n[axis] - 1.0));
    cellIndex_ = std::int64_t(grid.index(cell_));
    const std::int64_t stride[3] = {1, n.x, std::int64_t(n.x) * n.y};
    for (int axis = 0; axis < 3; ++axis) {
        indexStep_[axis] = step_[axis] * stride[axis];
        if (step_[axis] != 0) crossing_[axis] = crossing(axis);
    }
    done_ = false;
}

double MajorantDda::crossing(int axis) const {
    const double plane = cell_[axis] + (step_[axis] > 0 ? 1.0 : 0.0);
    return (plane - origin_[axis]) * invDirection_[axis];
}

bool MajorantDda::step(double& entry, double& exit, std::size_t& index) {
    if (done_) return false;
    const Vec3i& n = grid_->resolution();
    ++cellsVisited_;
    exit = tEnd_;
    int exitAxis = -1;
    for (int axis = 0; axis < 3; ++axis)
        if (step_[axis] != 0 && crossing_[axis] < exit) {
            exit = crossing_[axis];
            exitAxis = axis;
        }
    exit = std::max(exit, t_);
    index = std::size_t(cellIndex_);
    entry = t_;
    t_ = exit;
    if (exitAxis < 0) {
        done_ = true;
    } else {
        cell_[exitAxis] += step_[exitAxis];
        done_ = cell_[exitAxis] < 0 || cell_[exitAxis] >= n[exitAxis];
        crossing_[exitAxis] = crossing(exitAxis);
        cellIndex_ += indexStep_[exitAxis];
    }
    return true;
}

std::optional<media::MajorantSegment> MajorantDda::next() {
    float tMin, tMax;
    std::size_t index;
    if (!nextSpan(tMin, tMax, index)) return std::nullopt;
    return media::MajorantSegment{tMin, tMax, scale_ * grid_->cells_[index], minorantScale_ * grid_->minorants_[index]};
}

bool MajorantDda::nextSpan(float& tMin, float& tMax, std::size_t& index) {
    double entry, exit;
    while (step(entry, exit, index)) {
        const float value = grid_->cells_[index];
        if (!(value > 0.0f)) continue;
        tMin = float(entry);
        tMax = float(exit);
        if (tMax > tMin && !isBlack(scale_ * value)) return true;
    }
    return false;
}

std::optional<MajorantRun> MajorantDda::nextRun() {
    MajorantRun run;
    std::size_t index;  // unused: a run needs only where its segments are
    if (pending_) {
        run = *pending_;
        pending_.reset();
    } else if (!nextSpan(run.tMin, run.tMax, index)) {
        return std::nullopt;
    }
    MajorantRun span;
    while (nextSpan(span.tMin, span.tMax, index)) {
        if (span.tMin != run.tMax) {
            pending_ = span;
            break;
        }
        run.tMax = span.tMax;
    }
    return run;
}

}  // namespace fluence::volumes
