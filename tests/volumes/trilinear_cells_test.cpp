// TrilinearCells and GridMedium's exact extinction: the cubic of each dual cell against the grid's
// own trilinear samples (VdbGrid::sample, OpenVDB's BoxSampler) along rays through a tilted, scaled
// grid, and its closed-form integral against the walk's (Simpson's rule); the exact transmittance
// against quadrature and against the mean of many ratio-tracking estimates; which grids may offer
// it (no colour grid, no negative value); the walk's skipping of empty cells; GridMedium's inlined
// sums against the pieces'.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/random.h"
#include "media/exact_tracking.h"
#include "media/ratio_tracking.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"
#include "tests/volumes/vdb_test_files.h"
#include "volumes/grid_medium.h"
#include "volumes/trilinear_cells.h"

namespace fluence::volumes {
namespace {

using test::makeGrid;

// The closed-form integral of a stretch's cubic over all of it, to compare with its Simpson integral
// (volumes/trilinear_cells.h, INTEGRAL): equal up to a few tens of roundings of terms below the
// largest corner (2 here, 1.5 in the two-block grid) times the stretch's length (at most sqrt(3)
// voxels, in index units; the test grids' world lengths are at most that too): far below 1e-12.
double cubicIntegral(const CellStretch& stretch) {
    double c[4];
    stretch.cubic(c);
    const double s = stretch.tMax - stretch.tMin;
    return (((c[3] * 0.25 * s + c[2] * (1.0 / 3.0)) * s + c[1] * 0.5) * s + c[0]) * s;
}

// Random voxel values in a 9 x 7 x 8 block with holes (zero voxels, and a tile-free sparse edge),
// voxel 0.3, translated, placed by the tilted prim transform; `negative` sets one voxel below 0.
class TrilinearCellsTest : public ::testing::Test {
protected:
    void write(bool negative) {
        path_ = dir_.file(negative ? "negative.vdb" : "cells.vdb");  // the file cache keeps what it read
        auto density = makeGrid<openvdb::FloatGrid>("density", 0.3, {0.4, -0.2, 0.7});
        auto colour = makeGrid<openvdb::Vec3SGrid>("Cd", 0.3, {0.4, -0.2, 0.7});
        auto d = density->getAccessor();
        SampleStream r(5, 0, 0);
        for (int i = 0; i < 9; ++i)
            for (int j = 0; j < 7; ++j)
                for (int k = 0; k < 8; ++k) {
                    const float v = r.next();
                    if (v > 0.15f) d.setValue({i - 3, j, k + 2}, 2.0f * v);
                }
        if (negative) d.setValue({0, 3, 5}, -0.5f);
        colour->getAccessor().setValue({0, 0, 2}, openvdb::Vec3s(0.5f));
        test::writeGrids(path_, {density, colour});
    }
    FloatVdbGrid density() const { return FloatVdbGrid(path_, "density", 0, test::tiltedObjectToWorld()); }
    // The written grid (without its colour grid) as a chromatic medium.
    GridMedium chromaticMedium(float densityScale, const RGB& albedo, const RGB& absorptionColor) const {
        GridMediumParams p;
        p.densityScale = densityScale;
        p.albedo = albedo;
        p.absorptionColor = absorptionColor;
        return GridMedium(density(), p);
    }

    // Rays through the grid's box, from outside it, in assorted directions.
    std::vector<media::MediumRay> rays() const {
        const WorldBounds b = density().worldBounds();
        const Vec3f centre = (b.lo + b.hi) * 0.5f;
        const float reach = length(b.hi - b.lo);
        std::vector<media::MediumRay> out;
        SampleStream r(6, 0, 0);
        for (int n = 0; n < 12; ++n) {
            const Vec3f d = normalize(Vec3f(r.next() - 0.5f, r.next() - 0.5f, r.next() - 0.5f));
            const Vec3f offset = (Vec3f(r.next(), r.next(), r.next()) - Vec3f(0.5f)) * (0.3f * reach);
            out.push_back({centre + offset - d * reach, d, 2.0f * reach});
        }
        return out;
    }

    test::TempDir dir_{"volumes_trilinear_cells"};
    std::string path_;
};

TEST_F(TrilinearCellsTest, EachCellsCubicIsTheTrilinearReconstruction) {
    write(false);
    const FloatVdbGrid grid = density();
    const TrilinearCells cells(grid);
    ASSERT_TRUE(cells.available());
    EXPECT_GE(cells.minValue(), 0.0f);
    int checked = 0;
    for (const media::MediumRay& ray : rays()) {
        double covered = 0.0, previousEnd = -1.0;
        cells.walk(ray.origin, ray.direction, 0.0, double(ray.tMax), [&](const CellStretch& stretch) {
            const double t0 = stretch.tMin, t1 = stretch.tMax;
            double c[4];
            stretch.cubic(c);
            EXPECT_LT(t0, t1);
            EXPECT_GE(t0, previousEnd);  // in order, no overlap
            EXPECT_NEAR(stretch.integral, cubicIntegral(stretch), 1e-12);
            previousEnd = t1;
            covered += t1 - t0;
            for (double f : {0.0, 0.25, 0.5, 0.9}) {
                const double s = f * (t1 - t0);
                const double cubic = ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
                const float sampled = grid.sample(ray.at(float(t0 + s)));
                EXPECT_NEAR(cubic, sampled, 2e-4) << "t " << t0 + s;
                ++checked;
            }
            return true;
        });
        // Between the cells the ray crosses the grid is 0: samples off the walked stretches are 0.
        EXPECT_GT(covered, 0.0);
    }
    EXPECT_GT(checked, 200);
}

// exp(-tau) of GridMedium's pieces against tau by the midpoint rule on the medium's own at() over
// 40000 steps (its error, O(h^2) on a piecewise-smooth integrand, is far below 1e-4 here).
TEST_F(TrilinearCellsTest, ExactTransmittanceIsExpOfTheQuadratureDepth) {
    write(false);
    GridMediumParams p;
    p.densityScale = 1.3f;
    p.albedo = RGB(0.9f, 0.6f, 0.3f);
    p.absorptionColor = RGB(0.0f, 0.5f, 0.8f);  // chromatic extinction
    const GridMedium medium(density(), p);
    ASSERT_TRUE(medium.hasExactExtinction());
    for (const media::MediumRay& ray : rays()) {
        Vec3d tau(0.0);
        constexpr int kSteps = 40000;
        for (int k = 0; k < kSteps; ++k) {
            const media::MediumProperties m = medium.at(ray.at(ray.tMax * (k + 0.5f) / kSteps));
            tau += Vec3d(m.sigmaA + m.sigmaS) * (double(ray.tMax) / kSteps);
        }
        const RGB exact = media::exactTransmittance(medium, ray).throughput;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(exact[c], std::exp(-tau[c]), 1e-4) << "depth " << tau[c];
    }
}

// The mean of 20000 ratio-tracking estimates (unbiased, over the majorant grid) lies within 4 of its
// standard errors of the exact transmittance, per channel (a 6e-5 chance each of failing by
// accident, 36 comparisons).
TEST_F(TrilinearCellsTest, ExactTransmittanceIsRatioTrackingsMean) {
    write(false);
    const GridMedium medium = chromaticMedium(2.0f, RGB(0.8f, 0.7f, 0.2f), RGB(0.1f, 0.4f, 0.9f));
    for (const media::MediumRay& ray : rays()) {
        const RGB exact = media::exactTransmittance(medium, ray).throughput;
        test::MeanEstimate estimate[3];
        for (int n = 0; n < 20000; ++n) {
            SampleStream stream(13, 0, std::uint64_t(n));
            const int hero = media::sampleHeroChannel(stream.next());
            const RGB t = media::ratioTrackingTransmittance(medium, ray, hero, stream).estimate();
            for (int c = 0; c < 3; ++c) estimate[c].add(t[c]);
        }
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(exact[c], estimate[c].mean(), 4.0 * estimate[c].standardError() + 1e-6) << "channel " << c;
    }
}

// Two blocks of voxels 4 apart along x: the dual cells between them have eight 0 corners, and the
// walk skips them (they would add 0 to every sum), leaving a gap of exactly those cells where the
// grid samples 0. Without the skip the walk covers the whole support and has no gap.
TEST_F(TrilinearCellsTest, TheWalkSkipsCellsWhoseCornersAreAllZero) {
    const std::string path = dir_.file("two_blocks.vdb");
    auto density = makeGrid<openvdb::FloatGrid>("density", 1.0, {0.0, 0.0, 0.0});
    auto d = density->getAccessor();
    SampleStream r(7, 0, 0);
    for (int i : {0, 1, 2, 3, 8, 9, 10, 11})
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) d.setValue({i, j, k}, 0.5f + r.next());
    test::writeGrids(path, {density});
    const FloatVdbGrid grid(path, "density", 0, Matrix4::identity());
    const TrilinearCells cells(grid);
    ASSERT_TRUE(cells.available());
    const media::MediumRay ray{Vec3f(-5.0f, 1.5f, 1.5f), Vec3f(1.0f, 0.0f, 0.0f), 30.0f};
    std::vector<std::pair<double, double>> gaps;
    double previousEnd = -1.0;
    cells.walk(ray.origin, ray.direction, 0.0, double(ray.tMax), [&](const CellStretch& stretch) {
        if (previousEnd >= 0.0 && stretch.tMin > previousEnd) gaps.emplace_back(previousEnd, stretch.tMin);
        previousEnd = stretch.tMax;
        // The integrals are the cubics' on both sides of the gap (the walk enters the cell after it
        // with density 0, INTEGRAL).
        EXPECT_NEAR(stretch.integral, cubicIntegral(stretch), 1e-12) << "t " << stretch.tMin;
        return true;
    });
    ASSERT_EQ(gaps.size(), 1u);
    EXPECT_DOUBLE_EQ(gaps[0].first, 9.0);  // x = 4: the cells of lower corner 4, 5, 6 are empty
    EXPECT_DOUBLE_EQ(gaps[0].second, 12.0);
    for (double f : {0.01, 0.3, 0.7, 0.99}) EXPECT_EQ(grid.sample(ray.at(float(9.0 + 3.0 * f))), 0.0f);
}

// GridMedium's own exactOpticalDepth / exactDepthCrossing (the visitors inlined into its walk, each
// cell's integral by Simpson's rule, volumes/trilinear_cells.h INTEGRAL) give what Medium's defaults
// give through extinctionPieces() (each cell's cubic integrated in closed form): the same pieces, the
// same crossings, and depths equal up to rounding. Both are exact in real arithmetic; in double each
// cell's integral is a few tens of roundings of terms no larger than (largest corner, 2, x scale,
// 1.7, x the piece's length), so over a ray of at most ~10 units and ~50 pieces the sums differ by
// far less than 1e-12 (a wrong rule, the trapezoid's, differs by ~0.2 here).
TEST_F(TrilinearCellsTest, InlinedSumsAreThoseOfThePieces) {
    write(false);
    const GridMedium medium = chromaticMedium(1.7f, RGB(0.9f, 0.6f, 0.3f), RGB(0.0f, 0.5f, 0.8f));
    const media::Medium& base = medium;
    const double rounding = 1e-12;
    int crossed = 0;
    for (const media::MediumRay& ray : rays()) {
        const media::OpticalDepth inlined = medium.exactOpticalDepth(ray.origin, ray.direction, 0.0f, ray.tMax);
        const media::OpticalDepth pieces = base.Medium::exactOpticalDepth(ray.origin, ray.direction, 0.0f, ray.tMax);
        EXPECT_EQ(inlined.pieces, pieces.pieces);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(inlined.tau[c], pieces.tau[c], rounding);
        for (int hero = 0; hero < 3; ++hero)
            for (double target : {0.05, 0.5, 2.0}) {
                const media::DepthCrossing a =
                    medium.exactDepthCrossing(ray.origin, ray.direction, 0.0f, ray.tMax, hero, target);
                const media::DepthCrossing b =
                    base.Medium::exactDepthCrossing(ray.origin, ray.direction, 0.0f, ray.tMax, hero, target);
                EXPECT_EQ(a.pieces, b.pieces);
                ASSERT_EQ(a.tStop >= 0.0, b.tStop >= 0.0);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.tau[c], b.tau[c], rounding);
                if (a.tStop >= 0.0) {
                    ++crossed;
                    // The same crossing: a depth difference d moves it by d / sigmaT_h.
                    EXPECT_NEAR(a.tStop, b.tStop, rounding / a.sigmaT[hero]);
                    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.sigmaT[c], b.sigmaT[c], 1e-9 * a.sigmaT[c]);
                    EXPECT_NEAR(a.tau[hero], target, 1e-9 * target);  // the crossing is where tau_h = target
                }
            }
    }
    EXPECT_GT(crossed, 20);
}

TEST_F(TrilinearCellsTest, OnlyGridsWhoseExtinctionIsTheReconstructionOfferIt) {
    write(true);
    EXPECT_LT(TrilinearCells(density()).minValue(), 0.0f);
    EXPECT_FALSE(GridMedium(density(), GridMediumParams{}).hasExactExtinction());  // max(d, 0) is not cubic
    write(false);
    EXPECT_TRUE(GridMedium(density(), GridMediumParams{}).hasExactExtinction());
    const Vec3VdbGrid colour(path_, "Cd", 0, test::tiltedObjectToWorld());
    EXPECT_FALSE(GridMedium(density(), GridMediumParams{}, std::nullopt, colour).hasExactExtinction());
}

}  // namespace
}  // namespace fluence::volumes
