// Random walks built from free-flight sampling and Henyey-Greenstein phase sampling, as a volume
// path tracer would take them (media/tracking.h, HOW A PATH TRACER USES THEM): the white furnace
// (albedo 1, gray: every path's weight stays exactly 1, in an infinite medium and out of a
// sphere), and in chromatic media the spectral MIS estimates stay unbiased through many
// scatterings (an albedo-1 sphere lets everything out; an infinite emitting medium has L = Le).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/sampling.h"
#include "media/free_flight.h"
#include "media/homogeneous_medium.h"
#include "media/phase.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

// 2 x 3 per-channel checks in this file, each at z standard errors, family-wide 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(6));
constexpr int kMaxScatterings = 100'000;  // a safety net: the walks below end long before

// The distance from p inside a sphere of `radius` about the origin to its surface along unit w.
float distanceToSphere(const Vec3f& p, const Vec3f& w, float radius) {
    float b = dot(p, w), c = dot(p, p) - radius * radius;
    return -b + std::sqrt(std::max(0.0f, b * b - c));
}

TEST(RandomWalk, FurnaceKeepsEveryWeightExactlyOneInAnInfiniteMedium) {
    HomogeneousMedium fog({RGB(0.0f), RGB(1.0f), RGB(0.0f), 0.5f});
    for (int n = 0; n < 1000; ++n) {
        SampleStream rng(61, 0, n);
        test::Walk walk;
        walk.hero = sampleHeroChannel(rng.next());
        for (int i = 0; i < 100; ++i) {
            FreeFlight flight = walk.step(fog, std::numeric_limits<float>::infinity(), rng);
            ASSERT_EQ(flight.event, FlightEvent::Scattered);
            ASSERT_EQ(walk.beta, RGB(1.0f)) << "path " << n << ", scattering " << i;
            ASSERT_EQ(walk.rU, RGB(1.0f)) << "path " << n << ", scattering " << i;
        }
    }
}

TEST(RandomWalk, FurnaceSphereLetsEveryPathOutWithWeightOne) {
    // From the centre of a purely scattering sphere of radius 3 (optical radius 3, g = 0.5).
    const float radius = 3.0f;
    HomogeneousMedium fog({RGB(0.0f), RGB(1.0f), RGB(0.0f), 0.5f});
    test::MeanEstimate scatterings;
    for (int n = 0; n < 2000; ++n) {
        SampleStream rng(62, 0, n);
        test::Walk walk;
        walk.hero = sampleHeroChannel(rng.next());
        while (walk.step(fog, distanceToSphere(walk.p, walk.w, radius), rng).event != FlightEvent::Escaped)
            ASSERT_LT(walk.scatterings, kMaxScatterings);
        ASSERT_EQ(walk.beta, RGB(1.0f)) << "path " << n;
        ASSERT_EQ(walk.rU, RGB(1.0f)) << "path " << n;
        scatterings.add(walk.scatterings);
    }
    std::printf("[ measured ] furnace sphere: %.1f scatterings per path\n", scatterings.mean());
}

// Per channel, the mean of the spectral MIS estimates of `walks` walks from the origin, each
// scored by `score` when it ends (escape from a sphere of `radius`, or absorption).
template <typename Score>
void expectWalkMeans(const Medium& medium, float radius, const Score& score, const RGB& expected, std::uint64_t seed,
                     const char* what) {
    constexpr int kWalks = 20'000;
    test::MeanEstimate means[3], scatterings;
    for (int n = 0; n < kWalks; ++n) {
        SampleStream rng(seed, 0, n);
        test::Walk walk;
        walk.hero = sampleHeroChannel(rng.next());
        walk.w = sampleUniformSphere(rng.next2D());
        FreeFlight flight;
        do {
            ASSERT_LT(walk.scatterings, kMaxScatterings);
            flight = walk.step(medium, distanceToSphere(walk.p, walk.w, radius), rng);
        } while (flight.event == FlightEvent::Scattered);
        const RGB estimate = score(flight) * walk.beta / channelAverage(walk.rU);
        for (int c = 0; c < 3; ++c) means[c].add(estimate[c]);
        scatterings.add(walk.scatterings);
    }
    for (int c = 0; c < 3; ++c) {
        std::printf("[ measured ] %s, channel %d: %.5f +- %.5f (exact %.5f), %.1f scatterings per path\n", what, c,
                    means[c].mean(), means[c].standardError(), expected[c], scatterings.mean());
        EXPECT_NEAR(means[c].mean(), expected[c], kZ * means[c].standardError()) << what << ", channel " << c;
    }
}

TEST(RandomWalk, ChromaticAlbedoOneSphereLetsEverythingOut) {
    // sigmaS = (0.5, 1, 2), sigmaA = 0: every channel escapes with probability 1, but each path's
    // estimate varies with the channels' different optical depths.
    HomogeneousMedium fog({RGB(0.0f), RGB(0.5f, 1.0f, 2.0f), RGB(0.0f), 0.5f});
    expectWalkMeans(
        fog, 1.5f, [](const FreeFlight& f) { return f.event == FlightEvent::Escaped ? RGB(1.0f) : RGB(0.0f); },
        RGB(1.0f), 63, "chromatic albedo-1 sphere");
}

TEST(RandomWalk, InfiniteEmittingMediumGlowsWithItsEmission) {
    // Uniform radiance L solves 0 = -sigmaT L + sigmaA Le + sigmaS L, so L = Le in every channel,
    // whatever the albedo and g; scored where each walk is absorbed.
    const RGB le(1.0f, 2.0f, 3.0f);
    HomogeneousMedium glow({RGB(0.2f, 0.5f, 1.0f), RGB(1.0f, 0.5f, 0.25f), le, -0.3f});
    expectWalkMeans(
        glow, std::numeric_limits<float>::infinity(),
        [](const FreeFlight& f) { return f.event == FlightEvent::Absorbed ? f.properties.emission : RGB(0.0f); }, le,
        64, "infinite emitting medium");
}

}  // namespace
}  // namespace fluence::media
