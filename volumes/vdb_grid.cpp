#include "volumes/vdb_grid.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "volumes/vdb_file_cache.h"

namespace fluence::volumes {

namespace {

template <typename T>
struct GridTraits;
template <>
struct GridTraits<float> {
    using Grid = openvdb::FloatGrid;
    static constexpr const char* kTypeName = "float";
    static float convert(float v) { return v; }
    static float max(float a, float b) { return std::max(a, b); }
};
template <>
struct GridTraits<Vec3f> {
    using Grid = openvdb::Vec3SGrid;
    static constexpr const char* kTypeName = "vec3s";
    static Vec3f convert(const openvdb::Vec3s& v) { return {v.x(), v.y(), v.z()}; }
    static Vec3f max(const Vec3f& a, const Vec3f& b) { return vmax(a, b); }
};

std::string describe(const std::string& path, const std::string& name) {
    return "OpenVDB file '" + path + "', grid '" + name + "'";
}

Vec3d toVec3d(const openvdb::Vec3d& v) { return {v.x(), v.y(), v.z()}; }

// The grid's own index-to-object transform as a Matrix4, read off the images of the origin and the
// unit vectors (exact for the linear maps accepted).
Matrix4 gridIndexToObject(const openvdb::math::Transform& transform) {
    Vec3d origin = toVec3d(transform.indexToWorld(openvdb::Vec3d(0.0, 0.0, 0.0)));
    Matrix4 m = Matrix4::identity();
    for (int axis = 0; axis < 3; ++axis) {
        openvdb::Vec3d unit(0.0);
        unit[axis] = 1.0;
        Vec3d column = toVec3d(transform.indexToWorld(unit)) - origin;
        for (int row = 0; row < 3; ++row) m.m[row][axis] = column[row];
    }
    for (int row = 0; row < 3; ++row) m.m[row][3] = origin[row];
    return m;
}

}  // namespace

template <typename T>
struct VdbGrid<T>::Data {
    typename GridTraits<T>::Grid::ConstPtr grid;
    T maxValue;
};

template <typename T>
VdbGrid<T>::VdbGrid(const std::string& path, const std::string& name, int index, const Matrix4& objectToWorld)
    : path_(path), name_(name) {
    using Traits = GridTraits<T>;
    openvdb::GridBase::ConstPtr base = readVdbGrid(path, name, index);
    auto grid = openvdb::GridBase::constGrid<typename Traits::Grid>(base);
    if (!grid)
        throw std::runtime_error(describe(path, name) + ": holds " + base->valueType() + " values, expected " +
                                 Traits::kTypeName);
    if (!grid->transform().isLinear())
        throw std::runtime_error(describe(path, name) + ": has a non-linear (" + grid->transform().mapType() +
                                 ") transform; only linear transforms are supported");
    indexToWorld_ = objectToWorld * gridIndexToObject(grid->transform());
    std::optional<Matrix4> inverse = indexToWorld_.inverse();
    if (!inverse) throw std::runtime_error(describe(path, name) + ": its index-to-world transform is singular");
    worldToIndex_ = *inverse;

    openvdb::CoordBBox active = grid->evalActiveVoxelBoundingBox();
    T maxValue{};
    if (!active.empty()) {
        activeVoxels_ = IndexBox{{active.min().x(), active.min().y(), active.min().z()},
                                 {active.max().x(), active.max().y(), active.max().z()}};
        maxValue = Traits::convert(grid->background());
        for (auto it = grid->cbeginValueAll(); it; ++it) maxValue = Traits::max(maxValue, Traits::convert(*it));
    }
    data_ = std::make_shared<const Data>(Data{grid, maxValue});
}

template <typename T>
T VdbGrid<T>::sample(const Vec3f& p) const {
    if (!activeVoxels_) return T{};
    Vec3d q = worldToIndex_.transformPoint(Vec3d(p));
    for (int axis = 0; axis < 3; ++axis)
        if (!(q[axis] >= activeVoxels_->lo[axis] - 1 && q[axis] <= activeVoxels_->hi[axis] + 1)) return T{};
    auto accessor = data_->grid->getConstUnsafeAccessor();
    return GridTraits<T>::convert(openvdb::tools::BoxSampler::sample(accessor, openvdb::Vec3R(q.x, q.y, q.z)));
}

template <typename T>
WorldBounds VdbGrid<T>::worldBounds() const {
    if (!activeVoxels_) return {Vec3f(1.0f), Vec3f(-1.0f)};
    Vec3d lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        Vec3d q;
        for (int axis = 0; axis < 3; ++axis)
            q[axis] = (corner >> axis & 1) ? activeVoxels_->hi[axis] + 1.0 : activeVoxels_->lo[axis] - 1.0;
        Vec3d p = indexToWorld_.transformPoint(q);
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    WorldBounds bounds;  // rounded outward to float
    for (int axis = 0; axis < 3; ++axis) {
        bounds.lo[axis] = std::nextafter(float(lo[axis]), -INFINITY);
        bounds.hi[axis] = std::nextafter(float(hi[axis]), INFINITY);
    }
    return bounds;
}

template <typename T>
T VdbGrid<T>::maxValue() const {
    return data_->maxValue;
}

template <typename T>
T VdbGrid<T>::background() const {
    return GridTraits<T>::convert(data_->grid->background());
}

template <typename T>
void VdbGrid<T>::forEachValue(FunctionRef<void(const IndexBox&, const T&)> visit) const {
    for (auto it = data_->grid->cbeginValueAll(); it; ++it) {
        openvdb::CoordBBox box;
        it.getBoundingBox(box);
        visit(IndexBox{{box.min().x(), box.min().y(), box.min().z()}, {box.max().x(), box.max().y(), box.max().z()}},
              GridTraits<T>::convert(*it));
    }
}

template class VdbGrid<float>;
template class VdbGrid<Vec3f>;

}  // namespace fluence::volumes
