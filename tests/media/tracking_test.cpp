// The one majorant-tracking routine (media/tracking.h): tentative collisions form a Poisson process
// at the hero's rate, in order, within the medium's segments; the transmittances handed to the
// callback and returned multiply to the closed form over the whole ray; the residual rate draws
// nothing where the minorant equals the majorant; the callback can stop the walk; one random
// number per exponential step; unbounded rays through channels without extinction stay finite.
#include "media/tracking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "media/homogeneous_medium.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

const RGB kSigma(0.5f, 1.0f, 2.0f);
constexpr float kDepth = 1.5f;

// 3 statistical checks in this file (one per hero), each at z standard errors, family-wide 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(3));

TEST(TrackMajorants, DrawsAPoissonProcessAtTheHerosMajorant) {
    HomogeneousMedium medium({RGB(0.0f), kSigma});
    const MediumRay ray{Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), kDepth};
    constexpr int kRays = 100'000;
    for (int hero = 0; hero < 3; ++hero) {
        test::MeanEstimate count;
        for (int n = 0; n < kRays; ++n) {
            SampleStream rng(31, hero, n);
            RGB tMaj(1.0f), tResidual(1.0f);
            float previous = 0.0f;
            int collisions = 0;
            MajorantTransmittance end =
                trackMajorants(medium, ray, TrackingRate::Majorant, hero, rng, [&](const TentativeCollision& c) {
                    EXPECT_GE(c.t, previous);
                    EXPECT_LT(c.t, kDepth);
                    EXPECT_EQ(c.p, ray.at(c.t));
                    EXPECT_EQ(c.sigmaMaj, kSigma);
                    EXPECT_NEAR(c.tMaj.y, std::exp(-kSigma.y * (c.t - previous)), 1e-5f);
                    tMaj *= c.tMaj;
                    tResidual *= c.tResidual;
                    previous = c.t;
                    ++collisions;
                    return true;
                });
            tMaj *= end.tMaj;
            tResidual *= end.tResidual;
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(tMaj[c], std::exp(-kSigma[c] * kDepth), 2e-6f) << c;
            ASSERT_EQ(tResidual, RGB(1.0f));  // the homogeneous medium's minorant is its majorant
            ASSERT_EQ(rng.dimension(), std::uint32_t(collisions + 1));  // one number per step
            count.add(collisions);
        }
        std::printf("[ measured ] hero %d: %.4f +- %.4f collisions (expected %.4f)\n", hero, count.mean(),
                    count.standardError(), kSigma[hero] * kDepth);
        EXPECT_NEAR(count.mean(), kSigma[hero] * kDepth, kZ * count.standardError()) << "hero " << hero;
    }
}

TEST(TrackMajorants, ResidualRateDrawsNothingWhereTheBoundsMeet) {
    HomogeneousMedium medium({RGB(0.0f), kSigma});
    SampleStream rng(32, 0, 0);
    int collisions = 0;
    MajorantTransmittance end = trackMajorants(medium, {Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f), kDepth},
                                               TrackingRate::Residual, 1, rng, [&](const TentativeCollision&) {
                                                   ++collisions;
                                                   return true;
                                               });
    EXPECT_EQ(collisions, 0);
    EXPECT_EQ(rng.dimension(), 0u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(end.tMaj[c], std::exp(-kSigma[c] * kDepth));
    EXPECT_EQ(end.tResidual, RGB(1.0f));
}

TEST(TrackMajorants, StaysWithinSegmentsAndSkipsGaps) {
    // A ramp slab 0 <= x < 2 seen from x = -1: vacuum, eight segments, vacuum; the ray ends at x = 4.
    const RGB kA(0.5f, 1.0f, 0.0f), kB(1.0f, 0.0f, 0.5f);
    test::RampMedium ramp(kA, kB, 2.0f, 8, false);
    const MediumRay ray{Vec3f(-1.0f, 0.0f, 0.0f), Vec3f(1.0f, 0.0f, 0.0f), 5.0f};
    for (int n = 0; n < 1000; ++n) {
        SampleStream rng(33, 0, n);
        RGB tMaj(1.0f);
        MajorantTransmittance end =
            trackMajorants(ramp, ray, TrackingRate::Majorant, n % 3, rng, [&](const TentativeCollision& c) {
                EXPECT_GE(c.p.x, 0.0f);
                EXPECT_LT(c.p.x, 2.0f);
                tMaj *= c.tMaj;
                return true;
            });
        tMaj *= end.tMaj;
        // Optical depth of the majorants: each of the 8 pieces of length 1/4 at the larger end.
        for (int c = 0; c < 3; ++c) {
            double depth = 0.0;
            for (int i = 0; i < 8; ++i)
                depth += 0.25 * std::max(kA[c] + kB[c] * 0.25 * i, kA[c] + kB[c] * 0.25 * (i + 1));
            ASSERT_NEAR(tMaj[c], std::exp(-depth), 2e-6) << "channel " << c;
        }
    }
}

TEST(TrackMajorants, StopsWhenTheCallbackSaysSo) {
    HomogeneousMedium medium({RGB(0.0f), kSigma});
    SampleStream rng(34, 0, 0);
    int calls = 0;
    MajorantTransmittance end = trackMajorants(medium, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f)}, TrackingRate::Majorant,
                                               2, rng, [&](const TentativeCollision&) {
                                                   ++calls;
                                                   return false;
                                               });
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(end.tMaj, RGB(1.0f));
    EXPECT_EQ(end.tResidual, RGB(1.0f));
}

TEST(TrackMajorants, UnboundedRayWithAnEmptyHeroChannelEndsFinite) {
    // The hero's channel has no extinction: no collision, and exp(-0 * inf) must be 1, not NaN.
    HomogeneousMedium medium({RGB(0.0f), RGB(0.0f, 1.0f, 0.0f)});
    SampleStream rng(35, 0, 0);
    MajorantTransmittance end = trackMajorants(medium, {Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f)}, TrackingRate::Majorant,
                                               0, rng, [](const TentativeCollision&) {
                                                   ADD_FAILURE() << "no collision expected";
                                                   return true;
                                               });
    EXPECT_EQ(end.tMaj, RGB(1.0f, 0.0f, 1.0f));
}

}  // namespace
}  // namespace fluence::media
