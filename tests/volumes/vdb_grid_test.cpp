// The OpenVDB grid loader: values at known world points through the grid's own transform and the
// prim's, trilinear reconstruction and its support, bounds, maxima, vec3 grids, fieldIndex, the
// errors (each naming the file and the grid), the file cache (one open per file, also under
// concurrent loads), and the Cycles peer's smoke.vdb.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/random.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"
#include "tests/volumes/vdb_test_files.h"
#include "volumes/vdb_file_cache.h"
#include "volumes/vdb_grid.h"

namespace fluence::volumes {
namespace {

using test::makeGrid;
using test::tiltedObjectToWorld;
using test::writeGrids;

// The density the test file holds on its block of voxels: linear, so that trilinear interpolation
// reproduces it exactly between voxel centres.
constexpr int kLo[3] = {-3, 2, 0}, kHi[3] = {4, 9, 5};
float linear(double i, double j, double k) { return float(1.0 + 0.1 * i + 0.2 * j - 0.05 * k); }

// World point of index-space point q: the grid's transform (voxel 0.5, offset (1, 2, 3)) then the prim's.
Vec3f worldOf(const Vec3d& q) { return Vec3f(tiltedObjectToWorld().transformPoint(q * 0.5 + Vec3d(1.0, 2.0, 3.0))); }

class VdbGridTest : public ::testing::Test {
protected:
    void SetUp() override {
        auto density = makeGrid<openvdb::FloatGrid>("density", 0.5, {1.0, 2.0, 3.0});
        auto color = makeGrid<openvdb::Vec3SGrid>("Cd", 0.5, {1.0, 2.0, 3.0});
        auto a = density->getAccessor();
        auto c = color->getAccessor();
        for (int i = kLo[0]; i <= kHi[0]; ++i)
            for (int j = kLo[1]; j <= kHi[1]; ++j)
                for (int k = kLo[2]; k <= kHi[2]; ++k) {
                    a.setValue({i, j, k}, linear(i, j, k));
                    c.setValue({i, j, k}, openvdb::Vec3s(0.1f * i, 0.2f * j, 1.0f - 0.1f * k));
                }
        writeGrids(path_, {density, color});
    }

    test::TempDir dir_{"volumes_vdb_grid"};
    std::string path_ = dir_.file("block.vdb");
};

TEST_F(VdbGridTest, SamplesVoxelValuesAtTheirWorldCentres) {
    FloatVdbGrid grid(path_, "density", 0, tiltedObjectToWorld());
    for (int i = kLo[0]; i <= kHi[0]; ++i)
        for (int j = kLo[1]; j <= kHi[1]; ++j)
            for (int k = kLo[2]; k <= kHi[2]; ++k)
                EXPECT_NEAR(grid.sample(worldOf({double(i), double(j), double(k)})), linear(i, j, k), 2e-5)
                    << i << " " << j << " " << k;
}

TEST_F(VdbGridTest, InterpolatesTrilinearlyBetweenVoxels) {
    FloatVdbGrid grid(path_, "density", 0, tiltedObjectToWorld());
    SampleStream random(1, 0, 0);
    for (int n = 0; n < 1000; ++n) {
        Vec3d q;
        for (int axis = 0; axis < 3; ++axis) q[axis] = kLo[axis] + (kHi[axis] - kLo[axis]) * double(random.next());
        EXPECT_NEAR(grid.sample(worldOf(q)), linear(q.x, q.y, q.z), 2e-5) << to_string(q);
    }
    // Beyond the last voxel centre the value ramps down to the background over one voxel.
    EXPECT_NEAR(grid.sample(worldOf({kHi[0] + 0.25, 5.0, 2.0})), 0.75f * linear(kHi[0], 5, 2), 2e-5);
}

TEST_F(VdbGridTest, IsZeroOutsideTheSupportOfItsActiveVoxels) {
    FloatVdbGrid grid(path_, "density", 0, tiltedObjectToWorld());
    EXPECT_EQ(grid.sample(worldOf({kHi[0] + 1.01, 5.0, 2.0})), 0.0f);
    EXPECT_EQ(grid.sample(worldOf({0.0, kLo[1] - 1.01, 2.0})), 0.0f);
    EXPECT_EQ(grid.sample(worldOf({0.0, 5.0, kHi[2] + 3.0})), 0.0f);
    EXPECT_EQ(grid.sample(Vec3f(1e6f)), 0.0f);
}

TEST_F(VdbGridTest, ReportsItsIndexBoxWorldBoundsAndMaximum) {
    FloatVdbGrid grid(path_, "density", 0, tiltedObjectToWorld());
    ASSERT_TRUE(grid.activeVoxels());
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_EQ(grid.activeVoxels()->lo[axis], kLo[axis]);
        EXPECT_EQ(grid.activeVoxels()->hi[axis], kHi[axis]);
    }
    // The support's corners, placed through OpenVDB's own transform and then the prim's.
    openvdb::FloatGrid::ConstPtr vdb = openvdb::gridConstPtrCast<openvdb::FloatGrid>(readVdbGrid(path_, "density"));
    Vec3d lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        openvdb::Vec3d q;
        for (int axis = 0; axis < 3; ++axis) q[axis] = (corner >> axis & 1) ? kHi[axis] + 1 : kLo[axis] - 1;
        openvdb::Vec3d object = vdb->transform().indexToWorld(q);
        Vec3d p = tiltedObjectToWorld().transformPoint({object.x(), object.y(), object.z()});
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    WorldBounds bounds = grid.worldBounds();
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(bounds.lo[axis], lo[axis], 1e-5);
        EXPECT_NEAR(bounds.hi[axis], hi[axis], 1e-5);
    }
    EXPECT_FLOAT_EQ(grid.maxValue(), linear(kHi[0], kHi[1], kLo[2]));
    EXPECT_EQ(grid.background(), 0.0f);
}

TEST_F(VdbGridTest, ReadsVec3Grids) {
    Vec3VdbGrid grid(path_, "Cd", 0, tiltedObjectToWorld());
    Vec3f c = grid.sample(worldOf({1.5, 4.25, 2.5}));
    EXPECT_NEAR(c.x, 0.15f, 1e-5f);
    EXPECT_NEAR(c.y, 0.85f, 1e-5f);
    EXPECT_NEAR(c.z, 0.75f, 1e-5f);
    Vec3f m = grid.maxValue();
    EXPECT_FLOAT_EQ(m.x, 0.4f);
    EXPECT_FLOAT_EQ(m.y, 1.8f);
    EXPECT_FLOAT_EQ(m.z, 1.0f);
}

// Expects `load` to throw a std::runtime_error whose message contains every one of `parts`.
template <typename F>
void expectError(F load, const std::vector<std::string>& parts) {
    try {
        load();
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        for (const std::string& part : parts)
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST_F(VdbGridTest, ErrorsNameTheFileAndTheGrid) {
    std::string missing = dir_.file("missing.vdb");
    expectError([&] { FloatVdbGrid(missing, "density"); }, {missing, "'density'", "no such file"});
    expectError([&] { FloatVdbGrid(path_, "smoke"); }, {path_, "'smoke'", "no such grid", "density", "Cd"});
    expectError([&] { FloatVdbGrid(path_, "density", 1); }, {path_, "'density'", "index 1"});
    expectError([&] { FloatVdbGrid(path_, "Cd"); }, {path_, "'Cd'", "vec3s", "expected float"});
    expectError([&] { Vec3VdbGrid(path_, "density"); }, {path_, "'density'", "float", "expected vec3s"});
    std::string text = dir_.file("text.vdb");
    std::ofstream(text) << "not a volume\n";
    expectError([&] { FloatVdbGrid(text, "density"); }, {text, "'density'", "not a readable OpenVDB file"});
}

TEST(VdbGrid, FieldIndexPicksAmongGridsOfOneName) {
    test::TempDir dir("volumes_field_index");
    openvdb::GridPtrVec grids;
    for (float value : {1.0f, 2.0f, 3.0f}) {
        auto grid = makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0});
        grid->getAccessor().setValue({0, 0, 0}, value);
        grids.push_back(grid);
    }
    writeGrids(dir.file("three.vdb"), grids);
    EXPECT_EQ(FloatVdbGrid(dir.file("three.vdb"), "density", -1).maxValue(), 1.0f);  // not authored
    EXPECT_EQ(FloatVdbGrid(dir.file("three.vdb"), "density", 0).maxValue(), 1.0f);
    EXPECT_EQ(FloatVdbGrid(dir.file("three.vdb"), "density", 1).maxValue(), 2.0f);
    EXPECT_EQ(FloatVdbGrid(dir.file("three.vdb"), "density", 2).maxValue(), 3.0f);
}

TEST(VdbGrid, RefusesNonLinearTransforms) {
    test::TempDir dir("volumes_frustum");
    auto grid = makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0});
    grid->setTransform(openvdb::math::Transform::createFrustumTransform(
        openvdb::BBoxd({0.0, 0.0, 0.0}, {10.0, 10.0, 10.0}), 0.5, 2.0, 1.0));
    grid->getAccessor().setValue({1, 1, 1}, 1.0f);
    writeGrids(dir.file("frustum.vdb"), {grid});
    expectError([&] { FloatVdbGrid(dir.file("frustum.vdb"), "density"); }, {"frustum.vdb", "'density'", "non-linear"});
}

TEST(VdbGrid, OpensEachFileOnceForEveryGridAndPrim) {
    test::TempDir dir("volumes_cache");
    auto density = makeGrid<openvdb::FloatGrid>("density", 0.25, {0.0, 0.0, 0.0});
    auto temperature = makeGrid<openvdb::FloatGrid>("temperature", 0.25, {0.0, 0.0, 0.0});
    density->getAccessor().setValue({0, 0, 0}, 1.0f);
    temperature->getAccessor().setValue({0, 0, 0}, 700.0f);
    writeGrids(dir.file("fire.vdb"), {density, temperature});
    std::string samePath = (dir.path() / "." / "fire.vdb").string();

    std::size_t before = vdbFilesOpened();
    FloatVdbGrid a(dir.file("fire.vdb"), "density");
    FloatVdbGrid b(samePath, "density", 0, Matrix4::translate({5.0, 0.0, 0.0}));  // a second prim
    FloatVdbGrid c(dir.file("fire.vdb"), "temperature");
    EXPECT_EQ(vdbFilesOpened() - before, 1u);
    EXPECT_EQ(a.sample({0.0f, 0.0f, 0.0f}), 1.0f);
    EXPECT_EQ(b.sample({5.0f, 0.0f, 0.0f}), 1.0f);
    EXPECT_EQ(c.sample({0.0f, 0.0f, 0.0f}), 700.0f);
}

TEST(VdbGrid, ConcurrentLoadsShareOneOpen) {
    test::TempDir dir("volumes_cache_threads");
    auto density = makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0});
    density->getAccessor().setValue({2, 3, 4}, 0.5f);
    writeGrids(dir.file("shared.vdb"), {density});
    std::size_t before = vdbFilesOpened();
    std::vector<float> values(8, -1.0f);
    std::vector<std::thread> threads;
    for (std::size_t n = 0; n < values.size(); ++n)
        threads.emplace_back([&, n] {
            values[n] = FloatVdbGrid(dir.file("shared.vdb"), "density").sample({2.0f, 3.0f, 4.0f});
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(vdbFilesOpened() - before, 1u);
    for (float v : values) EXPECT_EQ(v, 0.5f);
}

// The plume the Cycles peer renders (shared/peers/cycles/README.md): one float grid "density",
// voxel size 0.02 with no offset, active index box (-33,-37,1)-(42,30,126), values in [0, 1].
TEST(VdbGrid, ReadsTheCyclesPeersSmoke) {
    const std::filesystem::path path = test::sharedPath("peers/cycles/smoke.vdb");
    FLUENCE_REQUIRE_SHARED(path);
    FloatVdbGrid grid(path.string(), "density");
    ASSERT_TRUE(grid.activeVoxels());
    const IndexBox& box = *grid.activeVoxels();
    EXPECT_EQ(box.lo, Vec3i(-33, -37, 1));
    EXPECT_EQ(box.hi, Vec3i(42, 30, 126));
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 4; ++column)
            EXPECT_NEAR(grid.indexToWorld().m[row][column], row == column ? 0.02 : 0.0, 1e-12);
    EXPECT_GT(grid.maxValue(), 0.9f);
    EXPECT_LE(grid.maxValue(), 1.0f);
    WorldBounds b = grid.worldBounds();
    EXPECT_NEAR(b.lo.x, -0.68f, 1e-5f);
    EXPECT_NEAR(b.hi.z, 2.54f, 1e-5f);
    std::cout << "smoke.vdb: grid 'density', max " << grid.maxValue() << ", world bounds " << to_string(b.lo) << " - "
              << to_string(b.hi) << "\n";
}

}  // namespace
}  // namespace fluence::volumes
