#include "volumes/trilinear_cells.h"

#include <algorithm>
#include <cmath>

namespace fluence::volumes {

TrilinearCells::TrilinearCells(const FloatVdbGrid& grid) : worldToIndex_(grid.worldToIndex()) {
    minValue_ = std::numeric_limits<float>::infinity();
    const std::optional<IndexBox>& active = grid.activeVoxels();
    if (!active) return;
    lo_ = active->lo - Vec3i(1);
    const Vec3i hi = active->hi + Vec3i(1);
    size_ = hi - lo_ + Vec3i(1);
    const std::size_t count = std::size_t(size_.x) * std::size_t(size_.y) * std::size_t(size_.z);
    if (count > kMaxVoxels) return;
    values_.assign(count, grid.background());
    minValue_ = grid.background();
    grid.forEachValue([&](const IndexBox& box, const float& value) {
        const Vec3i a = vmax(box.lo, lo_), b = vmin(box.hi, hi);
        if (a.x > b.x || a.y > b.y || a.z > b.z) return;                // outside what the support reads
        if (std::isnan(value) || value < minValue_) minValue_ = value;  // a NaN stays: not >= 0, not walked
        for (int z = a.z; z <= b.z; ++z)
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x)
                    values_[(std::size_t(z - lo_.z) * std::size_t(size_.y) + std::size_t(y - lo_.y)) *
                                std::size_t(size_.x) +
                            std::size_t(x - lo_.x)] = value;
    });
    occupied_.assign((count + 63) / 64, 0);
    const std::size_t dy = std::size_t(size_.x), dz = dy * std::size_t(size_.y);
    for (int z = 0; z + 1 < size_.z; ++z)
        for (int y = 0; y + 1 < size_.y; ++y)
            for (int x = 0; x + 1 < size_.x; ++x) {
                const std::size_t i = std::size_t(z) * dz + std::size_t(y) * dy + std::size_t(x);
                const float* p = values_.data() + i;
                if (p[0] != 0.0f || p[1] != 0.0f || p[dy] != 0.0f || p[dy + 1] != 0.0f || p[dz] != 0.0f ||
                    p[dz + 1] != 0.0f || p[dz + dy] != 0.0f || p[dz + dy + 1] != 0.0f)
                    occupied_[i >> 6] |= std::uint64_t(1) << (i & 63);
            }
}

CellRay TrilinearCells::prepare(const Vec3f& origin, const Vec3f& direction) const {
    CellRay ray;
    if (!available()) return ray;
    const Vec3d o = worldToIndex_.transformPoint(Vec3d(origin)), d = worldToIndex_.transformVector(Vec3d(direction));
    ray.origin = o;
    ray.direction = d;
    double t0 = -INFINITY, t1 = INFINITY;  // the stretch inside the support box
    for (int axis = 0; axis < 3; ++axis) {
        ray.step[axis] = d[axis] > 0.0 ? 1 : (d[axis] < 0.0 ? -1 : 0);
        ray.inverse[axis] = 1.0 / d[axis];
        const double boxLo = lo_[axis], boxHi = lo_[axis] + size_[axis] - 1;
        if (d[axis] == 0.0) {
            if (!(o[axis] >= boxLo && o[axis] <= boxHi)) return ray;  // misses: tIn > tOut
            continue;
        }
        double ta = (boxLo - o[axis]) / d[axis], tb = (boxHi - o[axis]) / d[axis];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    ray.tIn = t0;
    ray.tOut = t1;
    return ray;
}

void CellStretch::cubic(double c[4]) const {
    // The monomial coefficients of the corners, then the product of the three linear coordinates.
    double v[8];
    readCorners(first_, dy_, dz_, v);
    const double v0 = v[0], v1 = v[1], v2 = v[2], v3 = v[3], v4 = v[4], v5 = v[5], v6 = v[6], v7 = v[7];
    const double cx = v1 - v0, cy = v2 - v0, cz = v4 - v0;
    const double cxy = v3 - v1 - v2 + v0, cxz = v5 - v1 - v4 + v0, cyz = v6 - v2 - v4 + v0;
    const double cxyz = v7 - v3 - v5 - v6 + v1 + v2 + v4 - v0;
    const Vec3d& d = ray_->direction;
    const Vec3d entry = ray_->origin + d * tMin - corner_;  // the walk's own expression for the point
    const double x = entry.x, y = entry.y, z = entry.z;
    c[0] = v0 + cx * x + cy * y + cz * z + cxy * x * y + cxz * x * z + cyz * y * z + cxyz * x * y * z;
    c[1] = cx * d.x + cy * d.y + cz * d.z + cxy * (x * d.y + d.x * y) + cxz * (x * d.z + d.x * z) +
           cyz * (y * d.z + d.y * z) + cxyz * (d.x * y * z + x * d.y * z + x * y * d.z);
    c[2] = cxy * d.x * d.y + cxz * d.x * d.z + cyz * d.y * d.z + cxyz * (d.x * d.y * z + d.x * y * d.z + x * d.y * d.z);
    c[3] = cxyz * d.x * d.y * d.z;
}

}  // namespace fluence::volumes
