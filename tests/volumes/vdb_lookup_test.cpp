// VdbGrid::sample against OpenVDB's own trilinear lookup (tools::BoxSampler), bit for bit: the grid
// reads its lattice values through a table of leaf nodes (volumes/vdb_grid.cpp), and a render must
// not change by a bit for it. The grids mix what a lookup can meet: leaves across the origin (negative
// coordinates), a tile, stored inactive values, a background that is not 0, and points in the last
// voxel slab of a leaf, whose lattice points lie in two to eight leaves' boxes. A grid too sparse for
// the table checks the lookup without one. Index space is world space here (voxel size 1, identity
// placement), so the world point of a lookup is its index-space point exactly.
#include <gtest/gtest.h>
#include <openvdb/tools/Interpolation.h>

#include <cstring>
#include <string>

#include "core/random.h"
#include "tests/support/temp_dir.h"
#include "tests/volumes/vdb_test_files.h"
#include "volumes/vdb_file_cache.h"
#include "volumes/vdb_grid.h"

namespace fluence::volumes {
namespace {

using test::makeGrid;
using test::writeGrids;

// The voxels set, on each axis (across leaf boxes and the origin). kLo is a leaf box's first voxel and
// kHi its seventh, so the table's outer lattice points, kLo - 1 and kHi + 2, lie in other boxes than
// kLo and kHi + 1: a table one box short at either end would read outside itself.
constexpr int kLo = -24, kHi = 22;

float valueAt(SampleStream& random) { return 4.0f * random.next() - 1.0f; }
openvdb::Vec3s valueAt3(SampleStream& random) { return {valueAt(random), valueAt(random), valueAt(random)}; }

// A third of the voxels of [kLo, kHi]^3 set (some inactive), an active tile of one leaf's box inside, and
// background `background`.
template <typename GridT, typename MakeValue>
typename GridT::Ptr mixedGrid(const std::string& name, typename GridT::ValueType background, MakeValue make) {
    auto grid = makeGrid<GridT>(name, 1.0, {0.0, 0.0, 0.0}, background);
    SampleStream random(7, 0, 0);
    auto accessor = grid->getAccessor();
    for (int i = kLo; i <= kHi; ++i)
        for (int j = kLo; j <= kHi; ++j)
            for (int k = kLo; k <= kHi; ++k) {
                const float u = random.next();
                if (u < 0.25f) accessor.setValue({i, j, k}, make(random));
                if (u >= 0.25f && u < 0.33f) accessor.setValueOff({i, j, k}, make(random));
            }
    grid->tree().addTile(1, openvdb::Coord(0, 8, -16), make(random), true);  // replaces a leaf, inside
    return grid;
}

// Lookups at points of the support, their lattice points often in a leaf's last slab, compared with
// BoxSampler on the grid as read from the file.
template <typename T, typename GridT>
void expectSameAsBoxSampler(const VdbGrid<T>& grid, const GridT& reference, int lookups) {
    ASSERT_TRUE(grid.activeVoxels());
    const IndexBox& box = *grid.activeVoxels();
    const auto expectSame = [&](const Vec3f& p) {
        const auto expected = openvdb::tools::BoxSampler::sample(reference.tree(), openvdb::Vec3R(p.x, p.y, p.z));
        const T got = grid.sample(p);
        if constexpr (std::is_same_v<T, float>) {
            ASSERT_EQ(std::memcmp(&got, &expected, sizeof got), 0) << to_string(p) << ": " << got << " vs " << expected;
        } else {
            const float want[3] = {expected.x(), expected.y(), expected.z()};
            ASSERT_EQ(std::memcmp(&got, want, sizeof want), 0) << to_string(p) << ": " << to_string(got);
        }
    };
    // The support's faces, edges and corners exactly (lo - 1 and hi + 1 on an axis; hi + 1 reads the
    // lattice points hi + 2), each other axis at its ends or at a point inside.
    for (int corner = 0; corner < 27; ++corner) {
        Vec3f p;
        for (int axis = 0, code = corner; axis < 3; ++axis, code /= 3) {
            const int choice = code % 3;
            p[axis] = choice == 0   ? float(box.lo[axis] - 1)
                      : choice == 1 ? float(box.hi[axis] + 1)
                                    : 0.5f * float(box.lo[axis] + box.hi[axis]) + 0.25f;
        }
        expectSame(p);
        if (::testing::Test::HasFatalFailure()) return;
    }
    SampleStream random(11, 0, 0);
    for (int n = 0; n < lookups; ++n) {
        Vec3f p;
        for (int axis = 0; axis < 3; ++axis) {
            // An integer of the support, then a fraction: often in a leaf's last slab (index & 7 == 7).
            const int lo = box.lo[axis] - 1, hi = box.hi[axis] + 1;
            int i = lo + int(random.next() * float(hi - lo));
            if (random.next() < 0.5f) i = std::min((i | 7), hi - 1);
            p[axis] = float(i) + random.next();
        }
        expectSame(p);
        if (::testing::Test::HasFatalFailure()) return;
    }
}

TEST(VdbLookup, FloatGridMatchesOpenVdbsBoxSamplerToTheBit) {
    test::TempDir dir("volumes_vdb_lookup");
    writeGrids(dir.file("mixed.vdb"), {mixedGrid<openvdb::FloatGrid>("density", 0.25f, valueAt)});
    FloatVdbGrid grid(dir.file("mixed.vdb"), "density");
    auto reference = openvdb::GridBase::constGrid<openvdb::FloatGrid>(readVdbGrid(dir.file("mixed.vdb"), "density"));
    expectSameAsBoxSampler(grid, *reference, 50000);
}

TEST(VdbLookup, Vec3GridMatchesOpenVdbsBoxSamplerToTheBit) {
    test::TempDir dir("volumes_vdb_lookup");
    writeGrids(dir.file("mixed3.vdb"),
               {mixedGrid<openvdb::Vec3SGrid>("Cd", openvdb::Vec3s(0.5f, -0.25f, 2.0f), valueAt3)});
    Vec3VdbGrid grid(dir.file("mixed3.vdb"), "Cd");
    auto reference = openvdb::GridBase::constGrid<openvdb::Vec3SGrid>(readVdbGrid(dir.file("mixed3.vdb"), "Cd"));
    expectSameAsBoxSampler(grid, *reference, 50000);
}

// Two voxels far apart on every axis: a table over the box between them would hold 500^3 entries
// (4000 voxels apart) or (2^22)^3 = 2^66 (2^25 - 18 apart), a count that wraps to 0 in an int64,
// for two leaves, so the grid looks up without one. Between 2^24 and 2^25 the floats are the even
// numbers: the points near the far voxel are.
TEST(VdbLookup, SparseGridsLookUpWithoutATableWhoseSizeWouldOverflow) {
    for (const int far : {4000, (1 << 25) - 18}) {
        test::TempDir dir("volumes_vdb_lookup");
        auto sparse = makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0}, 0.125f);
        sparse->tree().setValue(openvdb::Coord(-3, 5, 0), 1.5f);
        sparse->tree().setValue(openvdb::Coord(far, far, far), 0.75f);
        writeGrids(dir.file("sparse.vdb"), {sparse});
        FloatVdbGrid grid(dir.file("sparse.vdb"), "density");
        auto reference =
            openvdb::GridBase::constGrid<openvdb::FloatGrid>(readVdbGrid(dir.file("sparse.vdb"), "density"));
        const float f = float(far);
        for (const Vec3f& p : {Vec3f(-3.5f, 4.25f, 0.75f), Vec3f(-2.125f, 5.5f, -0.5f), Vec3f(f, f, f),
                               Vec3f(f - 2.0f, f, f - 2.0f), Vec3f(f / 2.0f, f / 2.0f, f / 2.0f)}) {
            const float expected = openvdb::tools::BoxSampler::sample(reference->tree(), openvdb::Vec3R(p.x, p.y, p.z));
            const float got = grid.sample(p);
            EXPECT_EQ(std::memcmp(&got, &expected, sizeof got), 0)
                << far << ", " << to_string(p) << ": " << got << " vs " << expected;
        }
    }
}

}  // namespace
}  // namespace fluence::volumes
