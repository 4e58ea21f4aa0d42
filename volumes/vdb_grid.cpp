#include "volumes/vdb_grid.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

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

// The lattice values of a box of index space, for trilinear lookups without walking the tree: one
// entry per leaf node's box (an 8^3 block of voxels) that holds the box's leaf's value array, or,
// where the box has no leaf, the one value filling it (a tile's or the background). A lookup reads
// the (at most eight) entries of the boxes its eight lattice points lie in, entries of neighbouring
// boxes sitting side by side in one array; an OpenVDB accessor instead walks the tree from the root
// (a std::map) whenever the lookup is not in the boxes of its previous one, which along the
// scattered points of volume tracking is most of the time. The table is built only when it is small
// beside the grid's leaves: at most kEntriesPerLeaf entries per leaf node (an entry is a pointer and a
// value, 16 bytes; a float leaf is 512 values, 2 KiB: at most an eighth of that), or kEntriesAlways
// (1 MiB) for any grid. Each VdbGrid builds its own (one per prim and field placing a grid).
template <typename Tree>
class LeafTable {
public:
    using Value = typename Tree::ValueType;
    using Leaf = typename Tree::LeafNodeType;

    LeafTable() = default;  // not built
    // Over the lattice points lo..hi (both included), if that is small enough (see above).
    LeafTable(const Tree& tree, const openvdb::Coord& lo, const openvdb::Coord& hi) {
        const std::int64_t most = kEntriesPerLeaf * std::int64_t(tree.leafCount()) + kEntriesAlways;
        std::int64_t entries = 1;  // at most `most`, so the product cannot overflow
        for (int axis = 0; axis < 3; ++axis) {
            first_[axis] = lo[axis] >> Leaf::LOG2DIM;
            count_[axis] = (hi[axis] >> Leaf::LOG2DIM) - first_[axis] + 1;
            if (count_[axis] > most / entries) return;
            entries *= count_[axis];
        }
        entries_.reserve(std::size_t(entries));
        openvdb::tree::ValueAccessor<const Tree, false> accessor(tree);
        for (int x = 0; x < count_[0]; ++x)
            for (int y = 0; y < count_[1]; ++y)
                for (int z = 0; z < count_[2]; ++z) {
                    const openvdb::Coord origin((first_[0] + x) << Leaf::LOG2DIM, (first_[1] + y) << Leaf::LOG2DIM,
                                                (first_[2] + z) << Leaf::LOG2DIM);
                    const Leaf* leaf = accessor.probeConstLeaf(origin);
                    entries_.push_back(leaf ? Entry{leaf->buffer().data(), Value{}}
                                            : Entry{nullptr, accessor.getValue(origin)});
                }
    }

    bool built() const { return !entries_.empty(); }

    // openvdb::tools::BoxSampler::sample(tree, q), to the bit (BoxSampler's own interpolation of the
    // same eight values), for q whose lattice points floor(q) and floor(q) + 1 lie in the table.
    Value sample(const openvdb::Vec3R& q) const {
        const openvdb::Coord ijk(openvdb::tools::local_util::floorVec3(q));
        const openvdb::Vec3R uvw = q - ijk.asVec3d();
        // Per axis, for the lattice points ijk and ijk + 1: the box's place in the table and the
        // point's in the box's array (x-major: the strides are DIM^2, DIM and 1).
        int box[3][2], offset[3][2];
        for (int axis = 0; axis < 3; ++axis)
            for (int d = 0; d < 2; ++d) {
                const int c = ijk[axis] + d;
                box[axis][d] = (c >> Leaf::LOG2DIM) - first_[axis];
                offset[axis][d] = c & int(Leaf::DIM - 1);
            }
        Value data[2][2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                for (int k = 0; k < 2; ++k) {
                    const Entry& e =
                        entries_[(std::size_t(box[0][i]) * std::size_t(count_[1]) + std::size_t(box[1][j])) *
                                     std::size_t(count_[2]) +
                                 std::size_t(box[2][k])];
                    data[i][j][k] = e.values ? e.values[(offset[0][i] << 2 * Leaf::LOG2DIM) +
                                                        (offset[1][j] << Leaf::LOG2DIM) + offset[2][k]]
                                             : e.fill;
                }
        return openvdb::tools::BoxSampler::trilinearInterpolation(data, uvw);
    }

private:
    static constexpr std::int64_t kEntriesPerLeaf = 16, kEntriesAlways = 1 << 16;
    struct Entry {
        const Value* values;  // the leaf's, or null
        Value fill;           // without a leaf
    };
    int first_[3] = {0, 0, 0}, count_[3] = {0, 0, 0};  // in boxes
    std::vector<Entry> entries_;
};

}  // namespace

template <typename T>
struct VdbGrid<T>::Data {
    typename GridTraits<T>::Grid::ConstPtr grid;
    T maxValue;
    // Over the lattice points that lookups in the support read (activeVoxels lo - 1 to hi + 2).
    LeafTable<typename GridTraits<T>::Grid::TreeType> table;
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
    LeafTable<typename Traits::Grid::TreeType> table;
    if (!active.empty()) {
        activeVoxels_ = IndexBox{{active.min().x(), active.min().y(), active.min().z()},
                                 {active.max().x(), active.max().y(), active.max().z()}};
        maxValue = Traits::convert(grid->background());
        for (auto it = grid->cbeginValueAll(); it; ++it) maxValue = Traits::max(maxValue, Traits::convert(*it));
        table = {grid->constTree(), active.min().offsetBy(-1), active.max().offsetBy(2)};
    }
    data_ = std::make_shared<const Data>(Data{grid, maxValue, std::move(table)});
}

template <typename T>
T VdbGrid<T>::sample(const Vec3f& p) const {
    if (!activeVoxels_) return T{};
    Vec3d q = worldToIndex_.transformPoint(Vec3d(p));
    for (int axis = 0; axis < 3; ++axis)
        if (!(q[axis] >= activeVoxels_->lo[axis] - 1 && q[axis] <= activeVoxels_->hi[axis] + 1)) return T{};
    const openvdb::Vec3R index(q.x, q.y, q.z);
    if (data_->table.built()) return GridTraits<T>::convert(data_->table.sample(index));
    auto accessor = data_->grid->getConstUnsafeAccessor();
    return GridTraits<T>::convert(openvdb::tools::BoxSampler::sample(accessor, index));
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
