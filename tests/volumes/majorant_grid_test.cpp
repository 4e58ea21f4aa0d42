// The majorant grid and its DDA: conservative for trilinear interpolation along many random rays
// through a sparse grid of voxels, tiles and inactive values (every point of every segment, densely
// sampled, lies between its segment's minorant and majorant, and every point outside the segments
// has density 0); minorants tight inside a block of constant density and 0 at its border;
// segments ordered and non-overlapping; on a grid with no empty cell, contiguous and covering
// exactly the ray's overlap with the support; runs of segments end to end (nextRun); resolution by
// voxelsPerCell and maxCellsPerAxis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/random.h"
#include "media/majorant_check.h"
#include "tests/support/temp_dir.h"
#include "tests/volumes/vdb_test_files.h"
#include "volumes/majorant_grid.h"
#include "volumes/vdb_file_cache.h"

namespace fluence::volumes {
namespace {

using test::makeGrid;
using test::tiltedObjectToWorld;

struct Ray {
    Vec3f origin, direction;
    float tMin, tMax;
};

// Rays from points around the bounds towards points inside them (so most of them cross the grid),
// some starting inside, some stopping inside.
std::vector<Ray> randomRays(const WorldBounds& b, int count, std::uint64_t seed) {
    std::vector<Ray> rays;
    Vec3f centre = (b.lo + b.hi) * 0.5f, size = b.hi - b.lo;
    for (int n = 0; n < count; ++n) {
        SampleStream r(seed, 0, std::uint64_t(n));
        Vec3f from = centre + Vec3f(r.next() - 0.5f, r.next() - 0.5f, r.next() - 0.5f) * size * 2.0f;
        Vec3f to = b.lo + Vec3f(r.next(), r.next(), r.next()) * size;
        Vec3f d = normalize(to - from);
        float length = 4.0f * maxComponent(size);
        float tMin = n % 4 == 1 ? r.next() * length * 0.5f : 0.0f;
        float tMax = n % 4 == 2 ? tMin + r.next() * length * 0.5f : INFINITY;
        rays.push_back({from, d, tMin, tMax});
    }
    return rays;
}

std::vector<media::MajorantSegment> segmentsOf(const MajorantGrid& grid, const Ray& ray) {
    std::vector<media::MajorantSegment> segments;
    MajorantDda dda(grid, ray.origin, ray.direction, ray.tMin, ray.tMax, RGB(1.0f), RGB(1.0f));
    while (auto s = dda.next()) segments.push_back(*s);
    return segments;
}

// d >= minorant up to the float rounding of the interpolation (media/majorant_check.h's tolerance).
bool aboveMinorant(float d, float minorant) { return d >= minorant * (1.0f - media::kMajorantTolerance); }

// Checks the DDA's contract along `ray` against the grid's density (see the file comment), and that
// each segment is one cell's.
void checkRay(const FloatVdbGrid& grid, const MajorantGrid& majorants, const Ray& ray, float span, int& points) {
    std::vector<media::MajorantSegment> segments = segmentsOf(majorants, ray);
    float previous = ray.tMin;
    for (const media::MajorantSegment& s : segments) {
        ASSERT_LT(s.tMin, s.tMax);
        ASSERT_GE(s.tMin, previous);
        ASSERT_EQ(s.sigmaMaj.x, s.sigmaMaj.y);
        previous = s.tMax;
    }
    ASSERT_LE(previous, ray.tMax);
    // Each segment lies in one cell and carries its value.
    auto cellAt = [&](float t) {
        Vec3d c = majorants.worldToCell().transformPoint(Vec3d(ray.origin + ray.direction * t));
        return Vec3i(int(std::floor(c.x)), int(std::floor(c.y)), int(std::floor(c.z)));
    };
    for (const media::MajorantSegment& s : segments) {
        Vec3i middle = cellAt(0.5f * (s.tMin + s.tMax));
        EXPECT_EQ(majorants.cell(middle), s.sigmaMaj.x);
        EXPECT_EQ(majorants.minorant(middle), s.sigmaMin.x);
        if (s.tMax - s.tMin > 1e-3f * std::max(1.0f, s.tMax)) {
            EXPECT_EQ(cellAt(s.tMin + 1e-3f * (s.tMax - s.tMin)), middle);
            EXPECT_EQ(cellAt(s.tMax - 1e-3f * (s.tMax - s.tMin)), middle);
        }
    }
    auto check = [&](float t) {
        float d = grid.sample(ray.origin + ray.direction * t);
        float bound = -1.0f, lower = 0.0f;  // no segment
        for (const media::MajorantSegment& s : segments)
            if (t >= s.tMin && t < s.tMax) {  // [tMin, tMax)
                bound = std::max(bound, s.sigmaMaj.x);
                lower = std::max(lower, s.sigmaMin.x);
            }
        ++points;
        if (bound < 0.0f)
            EXPECT_EQ(d, 0.0f) << "outside every segment, t = " << t;
        else
            EXPECT_LE(d, bound) << "t = " << t;
        EXPECT_TRUE(aboveMinorant(d, lower)) << "t = " << t << ": density " << d << " below the minorant " << lower;
    };
    for (const media::MajorantSegment& s : segments)  // densely inside each segment, most densely at its ends
        for (int k = 0; k <= 16; ++k) {
            float f = std::pow(float(k) / 16.0f, 3.0f) * 0.5f;
            check(s.tMin + (s.tMax - s.tMin) * f);
            check(s.tMax - (s.tMax - s.tMin) * f);
        }
    float end = std::min(ray.tMax, ray.tMin + span);  // and evenly along the whole ray
    for (int k = 0; k <= 400; ++k) check(ray.tMin + (end - ray.tMin) * float(k) / 400.0f);
}

// A sparse grid: clusters of random voxels (values up to 5), a tile, and inactive voxels holding
// values (which trilinear interpolation reads too), placed by a tilted transform.
std::string writeSparseGrid(const test::TempDir& dir) {
    auto grid = makeGrid<openvdb::FloatGrid>("density", 0.5, {1.0, -2.0, 0.5});
    auto a = grid->getAccessor();
    for (int cluster = 0; cluster < 12; ++cluster) {
        SampleStream r(7, std::uint64_t(cluster), 0);
        openvdb::Coord centre(int(r.next() * 60) - 10, int(r.next() * 40), int(r.next() * 30) - 20);
        for (int n = 0; n < 150; ++n) {
            openvdb::Coord offset(int(r.next() * 9) - 4, int(r.next() * 9) - 4, int(r.next() * 9) - 4);
            a.setValue(centre + offset, 5.0f * r.next() * r.next());
        }
    }
    grid->tree().addTile(1, openvdb::Coord(64, 8, 0), 3.5f, true);  // an 8^3 tile
    a.setValueOff({-20, 30, 5}, 9.0f);                              // inactive but stored: read by interpolation
    a.setValueOff({20, 20, 0}, 9.0f);
    test::writeGrids(dir.file("sparse.vdb"), {grid});
    return dir.file("sparse.vdb");
}

TEST(MajorantGrid, BoundsTheDensityAlongRandomRays) {
    test::TempDir dir("volumes_majorant");
    FloatVdbGrid grid(writeSparseGrid(dir), "density", 0, tiltedObjectToWorld());
    for (MajorantGridOptions options :
         {MajorantGridOptions{}, MajorantGridOptions{3.0, 64}, MajorantGridOptions{8.0, 5}}) {
        MajorantGrid majorants(grid, options);
        WorldBounds b = grid.worldBounds();
        float span = 3.0f * length(b.hi - b.lo);
        int points = 0, nonEmpty = 0;
        for (const Ray& ray : randomRays(b, 300, 11)) {
            checkRay(grid, majorants, ray, span, points);
            nonEmpty += !segmentsOf(majorants, ray).empty();
        }
        EXPECT_GT(nonEmpty, 75);  // the test is not vacuous: many rays meet the clusters
        if (HasFailure()) return;
    }
}

// Around every positive stored value (read from the file by OpenVDB itself), on a lattice over the
// box its trilinear weight reaches, the cell holding each point bounds the density there: this
// finds a reach too short, or values missed, wherever they are, which random rays may not.
TEST(MajorantGrid, EveryCellBoundsTheDensityAroundEveryStoredValue) {
    test::TempDir dir("volumes_majorant_cells");
    std::string path = writeSparseGrid(dir);
    FloatVdbGrid grid(path, "density", 0, tiltedObjectToWorld());
    MajorantGrid majorants(grid, {5.0, 64});
    auto vdb = openvdb::gridConstPtrCast<openvdb::FloatGrid>(readVdbGrid(path, "density"));
    int points = 0;
    for (auto it = vdb->cbeginValueAll(); it; ++it) {
        if (*it <= 0.0f) continue;
        openvdb::CoordBBox box;
        it.getBoundingBox(box);
        for (int x = 0; x <= 6; ++x)
            for (int y = 0; y <= 6; ++y)
                for (int z = 0; z <= 6; ++z) {
                    Vec3d q;  // from just inside lo - 1 to just inside hi + 1
                    const int step[3] = {x, y, z};
                    for (int axis = 0; axis < 3; ++axis)
                        q[axis] =
                            box.min()[axis] - 0.999 + (box.max()[axis] - box.min()[axis] + 1.998) * step[axis] / 6.0;
                    Vec3f p(grid.indexToWorld().transformPoint(q));
                    float d = grid.sample(p);
                    if (d == 0.0f) continue;
                    Vec3d c = majorants.worldToCell().transformPoint(Vec3d(p));
                    Vec3i cell;
                    for (int axis = 0; axis < 3; ++axis)
                        cell[axis] = std::clamp(int(std::floor(c[axis])), 0, majorants.resolution()[axis] - 1);
                    ASSERT_LE(d, majorants.cell(cell)) << "index point " << to_string(q);
                    ++points;
                }
    }
    EXPECT_GT(points, 100000);
}

// On a lattice of 7^3 points over every cell with a positive minorant (its faces included), on a
// dense block placed by a tilted transform and on the sparse grid's tile, the density is never
// below the cell's minorant. The block's values fall along every axis (plus a little noise), so a
// cell's least values lie on its lattice's upper rows: leaving out the row a face's points read
// raises the minorant above the density there.
TEST(MajorantGrid, EveryCellsMinorantLiesBelowTheDensityThroughoutIt) {
    test::TempDir dir("volumes_minorant_cells");
    auto block = makeGrid<openvdb::FloatGrid>("density", 0.5, {1.0, -2.0, 0.5});
    auto a = block->getAccessor();
    SampleStream r(13, 0, 0);
    for (int x = 0; x < 40; ++x)
        for (int y = 0; y < 30; ++y)
            for (int z = 0; z < 20; ++z) a.setValue({x, y, z}, 2.5f - 0.02f * float(x + y + z) + 0.01f * r.next());
    test::writeGrids(dir.file("block.vdb"), {block});
    const FloatVdbGrid blockGrid(dir.file("block.vdb"), "density", 0, tiltedObjectToWorld());
    const FloatVdbGrid sparseGrid(writeSparseGrid(dir), "density", 0, tiltedObjectToWorld());
    int positive = 0;
    for (const FloatVdbGrid* grid : {&blockGrid, &sparseGrid})
        for (MajorantGridOptions options : {MajorantGridOptions{}, MajorantGridOptions{3.0, 64}}) {
            MajorantGrid majorants(*grid, options);
            const Matrix4 cellToWorld = *majorants.worldToCell().inverse();
            const Vec3i& n = majorants.resolution();
            for (int z = 0; z < n.z; ++z)
                for (int y = 0; y < n.y; ++y)
                    for (int x = 0; x < n.x; ++x) {
                        const float minorant = majorants.minorant({x, y, z});
                        ASSERT_LE(minorant, majorants.cell({x, y, z}));
                        if (minorant == 0.0f) continue;
                        ++positive;
                        for (int k = 0; k < 343; ++k) {
                            Vec3d c(x + (k % 7) / 6.0, y + (k / 7 % 7) / 6.0, z + (k / 49) / 6.0);
                            float d = grid->sample(Vec3f(cellToWorld.transformPoint(c)));
                            ASSERT_TRUE(aboveMinorant(d, minorant))
                                << "cell " << x << " " << y << " " << z << " at " << to_string(c) << ": density " << d
                                << " below " << minorant;
                        }
                    }
        }
    EXPECT_GT(positive, 100);
}

// Minorants are tight where the density is constant: a block of density 1 gives its inner cells a
// minorant of exactly 1 (residual ratio tracking draws no collision there) and the cells at the
// support's border, which reach beyond the block's ramp, 0.
TEST(MajorantGrid, ABlockOfConstantDensityIsItsOwnMinorantInside) {
    test::TempDir dir("volumes_minorant_constant");
    auto dense = makeGrid<openvdb::FloatGrid>("density", 0.5, {1.0, -2.0, 0.5});
    dense->fill(openvdb::CoordBBox({0, 0, 0}, {37, 29, 29}), 1.0f, true);
    test::writeGrids(dir.file("constant.vdb"), {dense});
    MajorantGrid majorants(FloatVdbGrid(dir.file("constant.vdb"), "density"));
    const Vec3i& n = majorants.resolution();
    EXPECT_EQ(n, Vec3i(5, 4, 4));  // a support of 39 x 31 x 31 voxels, 8 per cell
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) {
                const bool border = x == 0 || y == 0 || z == 0 || x == n.x - 1 || y == n.y - 1 || z == n.z - 1;
                EXPECT_EQ(majorants.minorant({x, y, z}), border ? 0.0f : 1.0f) << x << " " << y << " " << z;
            }
}

TEST(MajorantGrid, SkipsEmptyCellsAndStaysFarBelowTheGlobalMaximumThere) {
    test::TempDir dir("volumes_majorant_sparse");
    FloatVdbGrid grid(writeSparseGrid(dir), "density");
    MajorantGrid majorants(grid);
    int empty = 0, total = 0;
    const Vec3i& n = majorants.resolution();
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y)
            for (int x = 0; x < n.x; ++x) {
                empty += majorants.cell({x, y, z}) == 0.0f;
                ++total;
                EXPECT_LE(majorants.cell({x, y, z}), grid.maxValue());
            }
    EXPECT_GT(empty, total / 3);  // clusters leave most of the support empty
}

// A grid whose every cell holds density: the segments must tile the ray's overlap with the support.
TEST(MajorantGrid, SegmentsCoverTheOverlapWithTheSupportExactly) {
    test::TempDir dir("volumes_majorant_dense");
    auto dense = makeGrid<openvdb::FloatGrid>("density", 0.5, {1.0, -2.0, 0.5});
    dense->fill(openvdb::CoordBBox({0, 0, 0}, {37, 21, 14}), 1.0f, true);
    test::writeGrids(dir.file("dense.vdb"), {dense});
    FloatVdbGrid grid(dir.file("dense.vdb"), "density", 0, tiltedObjectToWorld());
    MajorantGrid majorants(grid);
    EXPECT_EQ(majorants.resolution(), Vec3i(5, 3, 2));  // a support of 39 x 23 x 16 voxels, 8 per cell

    // The support box [-1, 38] x [-1, 22] x [-1, 15] in index space, grown by the grid's margin of
    // 1e-3 voxel, against each ray by a slab test in index space (through OpenVDB's transform and
    // the inverse of the prim's).
    Matrix4 worldToObject = *tiltedObjectToWorld().inverse();
    int crossing = 0;
    for (const Ray& ray : randomRays(grid.worldBounds(), 400, 5)) {
        auto toIndex = [&](const Vec3d& world) {
            Vec3d o = worldToObject.transformPoint(world);
            openvdb::Vec3d q = dense->transform().worldToIndex(openvdb::Vec3d(o.x, o.y, o.z));
            return Vec3d(q.x(), q.y(), q.z());
        };
        Vec3d o = toIndex(Vec3d(ray.origin)), d = toIndex(Vec3d(ray.origin + ray.direction)) - o;
        double t0 = ray.tMin, t1 = ray.tMax;
        const double lo[3] = {-1.001, -1.001, -1.001}, hi[3] = {38.001, 22.001, 15.001};
        for (int axis = 0; axis < 3; ++axis) {
            double ta = (lo[axis] - o[axis]) / d[axis], tb = (hi[axis] - o[axis]) / d[axis];
            t0 = std::max(t0, std::min(ta, tb));
            t1 = std::min(t1, std::max(ta, tb));
        }
        std::vector<media::MajorantSegment> segments = segmentsOf(majorants, ray);
        if (t1 - t0 < 1e-4) {
            EXPECT_TRUE(segments.empty() || segments.back().tMax - segments.front().tMin < 1e-3);
            continue;
        }
        ++crossing;
        ASSERT_FALSE(segments.empty());
        EXPECT_NEAR(segments.front().tMin, t0, 1e-4 * std::max(1.0, std::abs(t0)));
        EXPECT_NEAR(segments.back().tMax, t1, 1e-4 * std::max(1.0, std::abs(t1)));
        for (std::size_t i = 1; i < segments.size(); ++i) EXPECT_EQ(segments[i].tMin, segments[i - 1].tMax);
        for (const media::MajorantSegment& s : segments) EXPECT_EQ(s.sigmaMaj, RGB(1.0f));
    }
    EXPECT_GT(crossing, 200);
}

// nextRun() gives next()'s segments merged wherever one starts where the one before ends, with the
// same float ends, on rays through a sparse grid (whose empty cells split the runs).
TEST(MajorantGrid, RunsAreTheSegmentsMergedEndToEnd) {
    test::TempDir dir("volumes_majorant_runs");
    FloatVdbGrid grid(writeSparseGrid(dir), "density", 0, tiltedObjectToWorld());
    MajorantGrid majorants(grid, {3.0, 64});
    int split = 0;
    for (const Ray& ray : randomRays(grid.worldBounds(), 200, 17)) {
        std::vector<MajorantRun> expected;
        for (const media::MajorantSegment& s : segmentsOf(majorants, ray)) {
            if (!expected.empty() && expected.back().tMax == s.tMin)
                expected.back().tMax = s.tMax;
            else
                expected.push_back({s.tMin, s.tMax});
        }
        MajorantDda dda(majorants, ray.origin, ray.direction, ray.tMin, ray.tMax, RGB(1.0f), RGB(1.0f));
        std::vector<MajorantRun> runs;
        while (std::optional<MajorantRun> run = dda.nextRun()) runs.push_back(*run);
        ASSERT_EQ(runs.size(), expected.size());
        for (std::size_t i = 0; i < runs.size(); ++i) {
            EXPECT_EQ(runs[i].tMin, expected[i].tMin);
            EXPECT_EQ(runs[i].tMax, expected[i].tMax);
        }
        if (runs.size() > 1) ++split;
    }
    EXPECT_GT(split, 0);  // some ray has several runs: the segment that ends one run starts the next
}

TEST(MajorantGrid, ResolutionFollowsTheOptions) {
    test::TempDir dir("volumes_majorant_resolution");
    FloatVdbGrid grid(writeSparseGrid(dir), "density");
    Vec3i extent = grid.activeVoxels()->hi - grid.activeVoxels()->lo + Vec3i(2);  // the support's, in voxels
    MajorantGrid leafSized(grid);
    for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(leafSized.resolution()[axis], (extent[axis] + 7) / 8);
    EXPECT_EQ(MajorantGrid(grid, {8.0, 4}).resolution(), Vec3i(4, 4, 4));
    MajorantGrid global(grid, {8.0, 1});
    EXPECT_EQ(global.resolution(), Vec3i(1, 1, 1));
    EXPECT_EQ(global.cell({0, 0, 0}), grid.maxValue());
}

TEST(MajorantGrid, AnAxisAlignedRayVisitsOneCellPerStep) {
    test::TempDir dir("volumes_majorant_axis");
    auto dense = makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0});
    dense->fill(openvdb::CoordBBox({0, 0, 0}, {37, 5, 5}), 2.0f, true);
    test::writeGrids(dir.file("bar.vdb"), {dense});
    FloatVdbGrid grid(dir.file("bar.vdb"), "density");
    MajorantGrid majorants(grid);  // support x in [-1, 38] and its margin: 5 cells of 7.8 voxels
    MajorantDda dda(majorants, {-10.0f, 2.5f, 2.5f}, {1.0f, 0.0f, 0.0f}, 0.0f, INFINITY, RGB(0.5f, 1.0f, 2.0f));
    std::vector<media::MajorantSegment> segments;
    while (auto s = dda.next()) segments.push_back(*s);
    ASSERT_EQ(segments.size(), 5u);
    EXPECT_EQ(dda.cellsVisited(), 5);
    EXPECT_FLOAT_EQ(segments.front().tMin, 8.999f);
    EXPECT_FLOAT_EQ(segments.back().tMax, 48.001f);
    EXPECT_FLOAT_EQ(segments[1].tMin, 8.999f + 39.002f / 5.0f);
    EXPECT_EQ(segments[2].sigmaMaj, RGB(1.0f, 2.0f, 4.0f));
}

TEST(MajorantGrid, AnEmptyGridHasNoSegments) {
    test::TempDir dir("volumes_majorant_empty");
    test::writeGrids(dir.file("empty.vdb"), {makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0})});
    FloatVdbGrid grid(dir.file("empty.vdb"), "density");
    MajorantGrid majorants(grid);
    EXPECT_TRUE(majorants.empty());
    EXPECT_FALSE(MajorantDda(majorants, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, INFINITY, RGB(1.0f)).next());
}

}  // namespace
}  // namespace fluence::volumes
