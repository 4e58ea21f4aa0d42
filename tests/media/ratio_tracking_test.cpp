// Ratio tracking (media/ratio_tracking.h): exact through a homogeneous medium (its minorant is its
// majorant), unbiased per channel with loose bounds, through a heterogeneous ramp against its
// closed form (gray and chromatic, with and without minorants, one or several segments, along an
// axis and obliquely), and bounded by 3 as the spectral MIS derivation says.
#include "media/ratio_tracking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "media/homogeneous_medium.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

// Statistical checks in this file: 3 channels x (1 loose homogeneous + 5 ramp configurations),
// each at z standard errors, for a family-wide false-failure rate of 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(18));
// What float rounding adds to a channel whose estimate has no variance.
constexpr double kRounding = 1e-6;

// The mean of `samples` standalone estimates (a fresh uniform hero each), per channel.
struct ChannelMeans {
    test::MeanEstimate channel[3];
    float largest = 0.0f;
};
ChannelMeans estimateTransmittance(const Medium& medium, const MediumRay& ray, int samples, std::uint64_t seed) {
    ChannelMeans means;
    for (int n = 0; n < samples; ++n) {
        SampleStream rng(seed, 0, n);
        const int hero = sampleHeroChannel(rng.next());
        const RGB t = ratioTrackingTransmittance(medium, ray, hero, rng).estimate();
        for (int c = 0; c < 3; ++c) means.channel[c].add(t[c]);
        means.largest = std::max(means.largest, maxComponent(t));
    }
    return means;
}

void expectTransmittance(const ChannelMeans& means, const RGB& expected, const std::string& what) {
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate& e = means.channel[c];
        std::printf("[ measured ] %s, channel %d: T = %.5f +- %.5f (exact %.5f)\n", what.c_str(), c, e.mean(),
                    e.standardError(), expected[c]);
        EXPECT_NEAR(e.mean(), expected[c], kZ * e.standardError() + kRounding) << what << ", channel " << c;
    }
    EXPECT_LE(means.largest, 3.0f + 1e-5f) << what;  // F_c <= 3 f_c / p_c <= 3 (media/tracking.h)
}

TEST(RatioTracking, IsExactThroughAHomogeneousMedium) {
    // sigmaMaj == sigmaMin == sigmaT: no tentative collision, zero variance, exp(-sigmaT d) exactly.
    const MediumProperties fog{RGB(0.1f, 0.5f, 2.0f), RGB(0.2f, 0.5f, 0.5f)};
    const RGB sigmaT = fog.sigmaA + fog.sigmaS;
    HomogeneousMedium medium(fog);
    for (float d : {0.5f, 1.7f, 6.0f})
        for (int hero = 0; hero < 3; ++hero) {
            SampleStream rng(41, hero, 0);
            TransmittanceEstimate e =
                ratioTrackingTransmittance(medium, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, -1.0f), d}, hero, rng);
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(e.estimate()[c], std::exp(-sigmaT[c] * d)) << "d " << d << ", hero " << hero;
            EXPECT_EQ(rng.dimension(), 0u);
        }
}

TEST(RatioTracking, IsUnbiasedPerChannelWithLooseBounds) {
    // The same slab with its majorant doubled and no minorant: plain ratio tracking, with null
    // collisions in every channel and a different rate per hero.
    const RGB sigmaT(0.3f, 1.0f, 2.5f);
    const float d = 1.2f;
    HomogeneousMedium exact({RGB(0.0f), sigmaT});
    test::RescaledBoundsMedium loose(exact, 2.0f, 0.0f);
    ChannelMeans means = estimateTransmittance(loose, {Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), d}, 20'000, 42);
    expectTransmittance(means, RGB(std::exp(-0.3f * d), std::exp(-1.0f * d), std::exp(-2.5f * d)), "loose slab");
}

TEST(RatioTracking, MatchesTheClosedFormThroughALinearRamp) {
    // sigmaT(x) = a + b x against its closed form (test::RampCase).
    for (const test::RampCase& k : test::kRampCases)
        expectTransmittance(estimateTransmittance(k.medium(), k.ray(), 20'000, 43), k.transmittance(), k.name);
}

}  // namespace
}  // namespace fluence::media
