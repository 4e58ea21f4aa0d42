// GridMedium: coefficients from the grids and the parameters (density * scale * albedo, the
// absorption colour, the colour grid, constant and blackbody emission), nothing outside the
// support, majorants bounding sigmaT in every channel (by our own dense check and by media's
// majorant checker), visiting stopping on request, parameter checks, and the transmittance that
// media's ratio tracking estimates over its majorants agreeing with exp(-optical depth) within the
// estimate's standard error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/blackbody.h"
#include "core/random.h"
#include "media/majorant_check.h"
#include "media/transmittance.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"
#include "tests/volumes/vdb_test_files.h"
#include "volumes/blackbody_radiance.h"
#include "volumes/grid_medium.h"

namespace fluence::volumes {
namespace {

using test::makeGrid;
using test::tiltedObjectToWorld;

// Density: a smooth bump over a 24 x 16 x 20 block (voxel 0.5); temperature: a different voxel
// size and offset; colour: values above 1 in places (red), so the extinction factor exceeds 1.
class GridMediumTest : public ::testing::Test {
protected:
    void SetUp() override {
        auto density = makeGrid<openvdb::FloatGrid>("density", 0.5, {1.0, 2.0, 3.0});
        auto temperature = makeGrid<openvdb::FloatGrid>("temperature", 0.75, {0.5, 1.5, 2.5});
        auto color = makeGrid<openvdb::Vec3SGrid>("Cd", 0.5, {1.0, 2.0, 3.0});
        auto d = density->getAccessor();
        auto c = color->getAccessor();
        for (int i = 0; i < 24; ++i)
            for (int j = 0; j < 16; ++j)
                for (int k = 0; k < 20; ++k) {
                    double r2 =
                        std::pow((i - 12) / 12.0, 2) + std::pow((j - 8) / 8.0, 2) + std::pow((k - 10) / 10.0, 2);
                    if (r2 < 1.0)
                        d.setValue({i, j, k}, float(2.0 * (1.0 - r2) * (1.0 + 0.5 * std::sin(i * 0.9 + j * 1.7))));
                    c.setValue({i, j, k}, openvdb::Vec3s(0.5f + 0.06f * i, 0.9f, 0.3f + 0.02f * k));
                }
        auto t = temperature->getAccessor();
        for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 11; ++j)
                for (int k = 0; k < 14; ++k) t.setValue({i, j, k}, float(0.2 + 0.05 * i + 0.03 * k));
        test::writeGrids(path_, {density, temperature, color});
        bounds_ = this->density().worldBounds();
    }

    FloatVdbGrid density() const { return FloatVdbGrid(path_, "density", 0, tiltedObjectToWorld()); }
    FloatVdbGrid temperature() const { return FloatVdbGrid(path_, "temperature", 0, tiltedObjectToWorld()); }
    Vec3VdbGrid color() const { return Vec3VdbGrid(path_, "Cd", 0, tiltedObjectToWorld()); }

    // A point inside the bounds, drawn from `r`.
    Vec3f randomPoint(SampleStream& r) const {
        return bounds_.lo + Vec3f(r.next(), r.next(), r.next()) * (bounds_.hi - bounds_.lo);
    }

    test::TempDir dir_{"volumes_grid_medium"};
    std::string path_ = dir_.file("fire.vdb");
    WorldBounds bounds_;
};

void expectNear(const RGB& a, const RGB& b, float relative, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(a[c], b[c], relative * std::max(std::abs(b[c]), 1e-6f)) << what << " channel " << c;
}

TEST_F(GridMediumTest, CoefficientsAreDensityTimesScaleTimesAlbedo) {
    GridMediumParams p;
    p.densityScale = 3.0f;
    p.albedo = RGB(0.9f, 0.5f, 0.2f);
    p.anisotropy = 0.4f;
    p.emissionScale = 2.0f;
    p.emissionColor = RGB(1.0f, 0.5f, 0.25f);
    GridMedium medium(density(), p);
    FloatVdbGrid grid = density();
    SampleStream r(3, 0, 0);
    int inside = 0;
    for (int n = 0; n < 1000; ++n) {
        Vec3f x = randomPoint(r);
        media::MediumProperties m = medium.at(x);
        float d = grid.sample(x);
        EXPECT_EQ(m.g, 0.4f);
        if (d <= 0.0f) {
            EXPECT_EQ(m.sigmaA + m.sigmaS, RGB(0.0f));
            continue;
        }
        ++inside;
        expectNear(m.sigmaS, p.albedo * (3.0f * d), 1e-6f, "sigmaS");
        expectNear(m.sigmaA + m.sigmaS, RGB(3.0f * d), 1e-6f, "sigmaT");  // black absorption colour
        expectNear(m.emission, RGB(2.0f, 1.0f, 0.5f), 1e-6f, "emission");
    }
    EXPECT_GT(inside, 100);
    EXPECT_EQ(medium.at(Vec3f(1e4f)).sigmaS, RGB(0.0f));
}

TEST_F(GridMediumTest, AbsorptionColourAndColourGridShapeTheCoefficients) {
    GridMediumParams p;
    p.densityScale = 2.0f;
    p.albedo = RGB(0.8f, 0.6f, 1.0f);
    p.absorptionColor = RGB(0.25f, 0.5f, 1.0f);
    GridMedium medium(density(), p, std::nullopt, color());
    FloatVdbGrid grid = density();
    Vec3VdbGrid cd = color();
    SampleStream r(4, 0, 0);
    for (int n = 0; n < 500; ++n) {
        Vec3f x = randomPoint(r);
        float d = 2.0f * grid.sample(x);
        if (d <= 0.0f) continue;
        RGB c = p.albedo * vmax(cd.sample(x), RGB(0.0f));
        media::MediumProperties m = medium.at(x);
        expectNear(m.sigmaS, c * d, 1e-6f, "sigmaS");
        expectNear(m.sigmaA, vmax(RGB(1.0f) - c, RGB(0.0f)) * (RGB(1.0f) - p.absorptionColor) * d, 1e-5f, "sigmaA");
    }
}

TEST_F(GridMediumTest, BlackbodyEmissionFollowsTheTemperatureGrid) {
    GridMediumParams p;
    p.blackbodyIntensity = 1.5f;
    p.temperatureScale = 2000.0f;
    p.temperatureOffset = 300.0f;
    GridMedium medium(density(), p, temperature());
    FloatVdbGrid grid = density(), t = temperature();
    SampleStream r(5, 0, 0);
    for (int n = 0; n < 300; ++n) {
        Vec3f x = randomPoint(r);
        if (grid.sample(x) <= 0.0f) continue;
        double kelvin = 300.0 + 2000.0 * t.sample(x);
        RGB expected =
            blackbodyRgb(kelvin) * float(1.5 * 5.670374419e-8 / std::numbers::pi * 1e-6 * std::pow(kelvin, 4.0));
        expectNear(medium.at(x).emission, expected, 2e-3f, "emission");
    }
}

TEST(BlackbodyRadiance, MatchesStefanBoltzmannTimesTheBlackbodyColour) {
    for (double kelvin = 100.0; kelvin < 30000.0; kelvin *= 1.0137) {
        RGB expected = blackbodyRgb(kelvin) * float(5.670374419e-8 / std::numbers::pi * 1e-6 * std::pow(kelvin, 4.0));
        RGB got = blackbodyRadiance(float(kelvin));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(got[c], expected[c], 1e-3f * luminance(expected)) << kelvin << " K, channel " << c;
    }
    EXPECT_EQ(blackbodyRadiance(99.0f), RGB(0.0f));
    EXPECT_EQ(blackbodyRadiance(-5.0f), RGB(0.0f));
}

TEST_F(GridMediumTest, MajorantsBoundSigmaTInEveryChannel) {
    GridMediumParams p;
    p.densityScale = 4.0f;
    p.albedo = RGB(0.7f, 1.0f, 0.4f);
    p.absorptionColor = RGB(0.1f, 0.0f, 0.6f);
    GridMedium medium(density(), p, std::nullopt, color());
    WorldBounds b = medium.bounds();
    Vec3f centre = (b.lo + b.hi) * 0.5f, size = b.hi - b.lo;
    int checked = 0;
    for (int n = 0; n < 200; ++n) {
        SampleStream r(6, 0, std::uint64_t(n));
        Vec3f o = centre + Vec3f(r.next() - 0.5f, r.next() - 0.5f, r.next() - 0.5f) * size * 2.0f;
        Vec3f d = normalize(b.lo + Vec3f(r.next(), r.next(), r.next()) * size - o);
        float previous = 0.0f;
        medium.majorants(o, d, 0.0f, INFINITY, [&](const media::MajorantSegment& s) {
            EXPECT_GE(s.tMin, previous);
            previous = s.tMax;
            for (int k = 0; k <= 24; ++k) {
                media::MediumProperties m = medium.at(o + d * (s.tMin + (s.tMax - s.tMin) * float(k) / 24.0f));
                RGB sigmaT = m.sigmaA + m.sigmaS;
                for (int c = 0; c < 3; ++c) EXPECT_LE(sigmaT[c], s.sigmaMaj[c] * (1.0f + 1e-6f));
                ++checked;
            }
            return true;
        });
    }
    EXPECT_GT(checked, 2000);
}

TEST_F(GridMediumTest, VisitingStopsWhenTheCallbackSaysSo) {
    GridMedium medium(density(), {}, std::nullopt, std::nullopt, {2.0, 64});
    WorldBounds b = medium.bounds();
    Vec3f centre = (b.lo + b.hi) * 0.5f;
    Vec3f from = centre - Vec3f(100.0f, 0.0f, 0.0f);
    int all = 0, some = 0;
    medium.majorants(from, {1.0f, 0.0f, 0.0f}, 0.0f, INFINITY,
                     [&](const media::MajorantSegment&) { return ++all, true; });
    medium.majorants(from, {1.0f, 0.0f, 0.0f}, 0.0f, INFINITY,
                     [&](const media::MajorantSegment&) { return ++some < 2; });
    EXPECT_GT(all, 2);
    EXPECT_EQ(some, 2);
}

TEST_F(GridMediumTest, RefusesBadParametersByName) {
    auto refuses = [&](GridMediumParams p, const std::string& name) {
        try {
            GridMedium medium(density(), p);
            ADD_FAILURE() << name << " accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    };
    GridMediumParams p;
    p.densityScale = -1.0f;
    refuses(p, "densityScale");
    p = {};
    p.anisotropy = 1.0f;
    refuses(p, "anisotropy");
    p = {};
    p.absorptionColor = RGB(0.5f, 1.5f, 0.0f);
    refuses(p, "absorptionColor");
    p = {};
    p.albedo = RGB(0.5f, NAN, 0.5f);
    refuses(p, "albedo");
    p = {};
    p.temperatureOffset = INFINITY;
    refuses(p, "temperatureOffset");
}

// media/majorant_check.h, the checker every medium's tests use, on rays through the medium.
TEST_F(GridMediumTest, PassesTheMediaMajorantCheck) {
    GridMediumParams p;
    p.densityScale = 4.0f;
    p.albedo = RGB(0.7f, 1.0f, 0.4f);
    p.absorptionColor = RGB(0.1f, 0.0f, 0.6f);
    // Cells of 3 voxels: the bump (22 x 14 x 18 active voxels) then has inner cells, whose minorants are
    // positive, as well as the default's.
    GridMedium medium(density(), p, std::nullopt, color());
    GridMedium smallCells(density(), p, std::nullopt, color(), {3.0, 64});
    Vec3f centre = (bounds_.lo + bounds_.hi) * 0.5f, size = bounds_.hi - bounds_.lo;
    int withMinorant = 0;  // rays that cross a cell with a positive minorant
    for (int n = 0; n < 100; ++n) {
        SampleStream r(8, 0, std::uint64_t(n));
        Vec3f o = centre + Vec3f(r.next() - 0.5f, r.next() - 0.5f, r.next() - 0.5f) * size * 2.0f;
        Vec3f d = normalize(randomPoint(r) - o);
        const GridMedium& m = n % 2 ? smallCells : medium;
        media::MajorantCheck check = media::majorantsBound(m, media::MediumRay{o, d, 4.0f * length(size)});
        EXPECT_TRUE(check.bound) << "ray " << n << "\n" << check.report;
        bool positive = false;
        m.majorants(o, d, 0.0f, INFINITY, [&](const media::MajorantSegment& s) {
            positive = positive || s.sigmaMin.x > 0.0f;
            return true;
        });
        withMinorant += positive;
    }
    EXPECT_GT(withMinorant, 5);
}

// Each transmittance estimator of media/ (media/transmittance.h: ratio tracking, unbiased ray
// marching) over GridMedium's majorants estimates the transmittance; a gap in the segments where
// the density is not 0, or a majorant below sigmaT (or a minorant above it), would bias it. The reference is exp(-optical depth) per channel, the depth
// integrated by the midpoint rule on 20000 steps (its error is far below the estimate's); the
// medium is coloured, so the three channels differ.
TEST_F(GridMediumTest, EachTransmittanceEstimatorOverTheMajorantsGivesTheTransmittance) {
    GridMediumParams p;
    p.densityScale = 1.5f;
    p.albedo = RGB(0.9f, 0.6f, 0.3f);
    p.absorptionColor = RGB(0.0f, 0.5f, 0.8f);
    GridMedium medium(density(), p, std::nullopt, std::nullopt, {3.0, 64});  // inner cells with minorants
    Vec3f centre = (bounds_.lo + bounds_.hi) * 0.5f;
    const Vec3f directions[] = {normalize(Vec3f(1.0f, 0.2f, 0.1f)), normalize(Vec3f(-0.3f, 1.0f, 0.4f)),
                                normalize(Vec3f(0.2f, -0.5f, 1.0f))};
    for (int ray = 0; ray < 3; ++ray) {
        media::MediumRay r{centre - directions[ray] * 30.0f, directions[ray], 60.0f};
        Vec3d depth(0.0);
        for (int k = 0; k < 20000; ++k) {
            media::MediumProperties m = medium.at(r.at(60.0f * (k + 0.5f) / 20000.0f));
            depth += Vec3d(m.sigmaA + m.sigmaS) * (60.0 / 20000.0);
        }
        EXPECT_GT(depth.x, 0.5) << "ray " << ray;
        for (media::TransmittanceMethod method :
             {media::TransmittanceMethod::RatioTracking, media::TransmittanceMethod::RayMarching}) {
            test::MeanEstimate estimate[3];
            for (int n = 0; n < 4000; ++n) {
                SampleStream stream(9, std::uint64_t(ray), std::uint64_t(n));
                int hero = std::min(int(stream.next() * 3.0f), 2);
                RGB t = media::estimateTransmittance(method, medium, r, hero, stream).estimate();
                for (int c = 0; c < 3; ++c) estimate[c].add(t[c]);
            }
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(estimate[c].mean(), std::exp(-depth[c]), 4.0 * estimate[c].standardError() + 1e-4)
                    << "ray " << ray << ", channel " << c << ", depth " << depth[c] << ", method " << int(method);
        }
    }
}

}  // namespace
}  // namespace fluence::volumes
