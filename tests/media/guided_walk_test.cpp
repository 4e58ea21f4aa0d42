// Guided random-walk steps (media/guided_walk.h): the Dwivedi eigenvalue against its defining
// equation, the guided cosines' mean, the directions each step draws against the density stepPdf says (chi-square over the
// sphere), stepPdf's normalisation over directions and lengths and its closed form on long steps, the channels drawn against their
// probabilities (chi-square), and the step's expected weight against its closed form, which
// checks that sampleLength draws lengths with the density fly divides by.
#include "media/guided_walk.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

const Vec3f kEntry(0.0f, 0.0f, 0.0f), kNormal(0.0f, 0.0f, 1.0f);
const Vec3f kWo = normalize(Vec3f(0.3f, -0.5f, 0.8f));

// A medium of single-scattering albedo (0.3, 0.8, 0.99) and sigmaT (1, 2, 4).
MediumProperties chromaticMedium(float g = 0.0f) {
    MediumProperties m;
    const RGB sigmaT(1.0f, 2.0f, 4.0f), albedo(0.3f, 0.8f, 0.99f);
    m.sigmaS = sigmaT * albedo;
    m.sigmaA = sigmaT - m.sigmaS;
    m.g = g;
    return m;
}

// A walk whose entry ray reached the far side 1.5 below the entry: backward guiding is in play.
GuidedWalk thinWalk(const MediumProperties& m) {
    GuidedWalk walk(kEntry, kNormal, m);
    walk.sawFarSide(Vec3f(0.0f, 0.0f, -1.0f), 1.5f);
    return walk;
}

TEST(GuidedWalk, DwivediNuSolvesTheEigenvalueEquation) {
    // nu is the root above 1 of alpha nu / 2 ln((nu + 1) / (nu - 1)) = 1; the fit is good to a few
    // tenths of a percent (d'Eon & Krivanek 2020), which is all guiding needs.
    for (double albedo : {0.3, 0.5, 0.8, 0.95, 0.99}) {
        const double nu = dwivediNu(albedo);
        const double residual = albedo * nu / 2.0 * std::log((nu + 1.0) / (nu - 1.0));
        std::printf("[ measured ] albedo %.2f: nu %.5f, eigen equation %.5f\n", albedo, nu, residual);
        EXPECT_NEAR(residual, 1.0, 0.01) << albedo;
    }
    EXPECT_EQ(dwivediNu(0.0), kMinNu);
    EXPECT_EQ(dwivediNu(1.0), kMaxNu);
}

TEST(GuidedWalk, GuidedCosinesHaveTheirDensitysMean) {
    // The mean of mu under 1 / ((nu - mu) ln((nu + 1) / (nu - 1))) is nu - 2 / ln((nu + 1) / (nu - 1));
    // the sampled cosines (stratified u) have it, from nearly all towards the axis to nearly uniform.
    for (double nu : {kMinNu, dwivediNu(0.3), dwivediNu(0.99), kMaxNu}) {
        constexpr int kN = 200000;
        double mean = 0.0;
        for (int i = 0; i < kN; ++i) mean += sampleDwivediCosine(nu, (i + 0.5) / kN) / kN;
        const double expected = nu - 2.0 / std::log((nu + 1.0) / (nu - 1.0));
        std::printf("[ measured ] nu %.5f: mean cosine %.5f (exact %.5f)\n", nu, mean, expected);
        EXPECT_NEAR(mean, expected, 1e-4) << "nu " << nu;
    }
}

TEST(GuidedWalk, StepDirectionsMatchTheirDensity) {
    // The direction a step takes has the density of the strategies' mixture.
    for (float g : {0.0f, 0.6f})
        for (int hero = 0; hero < 3; ++hero) {
            const MediumProperties m = chromaticMedium(g);
            const GuidedWalk walk = thinWalk(m);
            const Vec3f p(0.1f, 0.0f, -1.0f);  // deep in the thin slab: guided both ways
            auto marginal = [&](const Vec3f& wi) {
                // reaching t = 0 has probability 1 under every strategy: the directions' mixture
                WalkStep step{p, kWo, wi, false, WalkStrategy::Classic};
                return double(walk.stepPdf(step, 0.0f, false)[hero]);
            };
            test::Chi2Result r = test::chi2SphereTest(
                [&](SampleStream& rng) {
                    const float u = rng.next();
                    return std::optional(walk.sampleStep(p, kWo, hero, u, rng.next2D()).wi);
                },
                marginal);
            std::printf("[ measured ] g %.1f, hero %d: %s\n", g, hero, r.report.c_str());
            EXPECT_GT(r.pValue, test::kChi2Alpha) << "g " << g << ", hero " << hero << ": " << r.report;
        }
}

TEST(GuidedWalk, StepPdfIntegratesToOneOverDirectionsAndLengths) {
    // Collisions before a boundary 0.7 away in every direction, plus reaching it: per channel,
    // lengths by Simpson's rule (the densities are smooth exponentials), directions adaptively.
    constexpr float kBoundary = 0.7f;
    constexpr int kIntervals = 16;
    const GuidedWalk walk = thinWalk(chromaticMedium());
    const Vec3f p(0.1f, 0.0f, -0.4f);
    for (int c = 0; c < 3; ++c) {
        auto overLengths = [&](const Vec3f& wi) {
            WalkStep step{p, kWo, wi, false, WalkStrategy::Classic};
            const double h = kBoundary / kIntervals;
            double collisions = 0.0;
            for (int i = 0; i <= kIntervals; ++i) {
                const double weight = i == 0 || i == kIntervals ? 1.0 : i % 2 ? 4.0 : 2.0;
                collisions += weight * walk.stepPdf(step, float(i * h), true)[c];
            }
            return collisions * h / 3.0 + walk.stepPdf(step, kBoundary, false)[c];
        };
        test::SphereIntegral total = test::integrateOverSphere(overLengths, 1e-3);
        std::printf("[ measured ] channel %d: integral %.7f +- %.1e\n", c, total.value, total.error);
        EXPECT_NEAR(total.value, 1.0, total.error + 2e-4) << "channel " << c;
    }
}

TEST(GuidedWalk, StepPdfHoldsItsClosedFormHundredsOfMeanFreePathsLong) {
    // A guided step nearly along the entry's normal, from halfway down the thin walk (both guiding
    // directions in play), at lengths of 0.5 to 1600 mean free paths: stepPdf, in float, against
    // the closed form of THE STEP AND ITS MIS in long double. Short steps take the guided lengths'
    // transmittances as quotients of the classic one; long ones, where that one is below float's
    // normal range, directly (kFactoredExponentLimit): as quotients they would read 0 where the
    // guided length towards the nearer side still has most of its density. Tolerance: the float
    // rounding of exponents up to 1600 (relative 6e-8 each, so 1e-4 of the value) plus the
    // smallest normal float, below which a density is 0 to a float.
    const MediumProperties m = chromaticMedium();
    const GuidedWalk walk = thinWalk(m);
    const Vec3f p(0.1f, 0.0f, -0.75f);
    const long double farDepth = 1.5L, depth = 0.75L, f = kGuidedFraction,
                      phase = 1.0L / (4.0L * 3.14159265358979323846L);
    for (float mu : {0.999f, -0.999f})
        for (float t : {0.5f, 30.0f, 120.0f, 400.0f})
            for (bool collided : {true, false}) {
                const Vec3f wi(std::sqrt(1.0f - mu * mu), 0.0f, mu);
                const WalkStep step{p, kWo, wi, false, WalkStrategy::Classic};
                const RGB pdf = walk.stepPdf(step, t, collided);
                for (int c = 0; c < 3; ++c) {
                    const long double sigmaT = m.sigmaA[c] + m.sigmaS[c], nu = dwivediNu(m.sigmaS[c] / sigmaT);
                    const long double lnRatio = std::log((nu + 1.0L) / (nu - 1.0L)), cosine = dot(wi, kNormal);
                    auto length = [&](long double rate) { return (collided ? rate : 1.0L) * std::exp(-rate * t); };
                    const long double b = 1.0L / (1.0L + std::exp((farDepth - 2.0L * depth) * sigmaT / nu));
                    const long double towards = length(sigmaT * (1.0L - cosine / nu)) /
                                                ((nu - cosine) * lnRatio * 2.0L * 3.14159265358979323846L);
                    const long double away = length(sigmaT * (1.0L + cosine / nu)) /
                                             ((nu + cosine) * lnRatio * 2.0L * 3.14159265358979323846L);
                    const long double expected =
                        (1.0L - f) * phase * length(sigmaT) + f * ((1.0L - b) * towards + b * away);
                    EXPECT_NEAR(pdf[c], double(expected), 1e-4 * double(expected) + 1.2e-38)
                        << "mu " << mu << ", t " << t << ", collided " << collided << ", channel " << c;
                }
            }
}

// The thin walk after its entry's step reached a boundary 1 below it without a collision: its
// weight exp(-sigmaT) over the step's density, chromatic, so its channels are drawn unevenly.
GuidedWalk thinWalkWithChromaticWeight(const MediumProperties& m) {
    GuidedWalk walk = thinWalk(m);
    SampleStream unused(0, 0, 0);  // fly draws nothing for a step that reaches the boundary
    walk.fly(walk.firstStep(kEntry, -kNormal, 0), 10.0f, 1.0f, unused);
    return walk;
}

TEST(GuidedWalk, ACollisionThatSurvivesForSureTakesTheRouletteDimensionUndrawn) {
    // fly plays Russian roulette at a collision with one number of the stream. A walk whose weight
    // has a channel at 1 or more survives for sure: the number's dimension is still taken (the
    // numbers after it keep theirs). The chromatic medium's entry step, colliding at once, weighs
    // its blue channel sigmaS_b / sum_c P_c sigmaT_c = 3.96 / 2.80 > 1; a grey medium of albedo 0.5
    // weighs every channel 0.5 and draws the number.
    MediumProperties grey;
    grey.sigmaS = RGB(1.0f);
    grey.sigmaA = RGB(1.0f);
    for (bool chromatic : {true, false}) {
        GuidedWalk walk = thinWalk(chromatic ? chromaticMedium() : grey);
        SampleStream stream(5, 0, 0, SamplerKind::Sobol);
        const FreeFlight flight = walk.fly(walk.firstStep(kEntry, -kNormal, 0), 0.01f, 1.0f, stream);
        EXPECT_EQ(stream.dimension(), 1u) << chromatic;
        if (chromatic) {
            EXPECT_EQ(flight.event, FlightEvent::Scattered);
            EXPECT_GT(flight.throughput[2], 1.0f);
        }
    }
}

TEST(GuidedWalk, ChannelsAreDrawnWithTheirProbabilities) {
    // P_c is proportional to alpha_c T_c; stepChannel draws c with it (a channel per step) (Pearson over 3 bins,
    // 2 degrees of freedom: Q(1, x / 2) is the p-value). A fresh walk (T = 1) follows the albedos.
    const MediumProperties m = chromaticMedium();
    const GuidedWalk fresh = thinWalk(m), chromatic = thinWalkWithChromaticWeight(m);
    const RGB albedo(0.3f, 0.8f, 0.99f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(fresh.channelProbabilities()[c], albedo[c] / 2.09f, 1e-6) << c;
    for (const GuidedWalk* walk : {&fresh, &chromatic}) {
        constexpr int kN = 100000;
        const RGB p = walk->channelProbabilities();
        std::array<int, 3> counts{};
        SampleStream rng(23, 0, 0);
        for (int n = 0; n < kN; ++n) ++counts[walk->stepChannel(rng.next())];
        double statistic = 0.0;
        for (int c = 0; c < 3; ++c) statistic += std::pow(counts[c] - kN * p[c], 2) / (kN * p[c]);
        const double pValue = test::upperIncompleteGammaQ(1.0, statistic / 2.0);
        std::printf("[ measured ] P (%.4f, %.4f, %.4f), counts %d %d %d, p-value %.3f\n", p[0], p[1], p[2], counts[0],
                    counts[1], counts[2], pValue);
        EXPECT_GT(pValue, test::kChi2Alpha);
    }
}

TEST(GuidedWalk, StepWeightsAverageTheirClosedForm) {
    // A step from p towards a boundary tB away in every direction, weighted as the path tracer
    // weighs it (fly's throughput: the balance heuristic over channels and strategies, pdfRatio
    // 1), has the expected value of an isotropic step's value: per channel,
    //   alpha (1 - exp(-sigmaT tB)) + exp(-sigmaT tB)
    // (collisions, then reaching the boundary), Russian roulette included; from a fresh walk and
    // from one whose channels are drawn unevenly. Tolerance: z standard errors of the mean, z
    // for 2 x 3 checks at a family-wide 1%.
    constexpr float kBoundary = 0.7f;
    constexpr int kN = 400000;
    const MediumProperties m = chromaticMedium();
    const Vec3f p(0.1f, 0.0f, -0.4f);
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(6));
    for (const GuidedWalk& start : {thinWalk(m), thinWalkWithChromaticWeight(m)}) {
        std::array<test::MeanEstimate, 3> weights;
        for (int n = 0; n < kN; ++n) {
            SampleStream rng(11, 0, std::uint64_t(n));
            GuidedWalk walk = start;  // fly changes the walk's weight
            const int channel = walk.stepChannel(rng.next());
            const float u = rng.next();
            const WalkStep step = walk.sampleStep(p, kWo, channel, u, rng.next2D());
            const FreeFlight flight = walk.fly(step, walk.sampleLength(step, rng.next()), kBoundary, rng);
            ASSERT_EQ(flight.pdfRatio, RGB(1.0f));
            const RGB weight = flight.event == FlightEvent::Absorbed ? RGB(0.0f) : flight.throughput;
            for (int c = 0; c < 3; ++c) weights[c].add(weight[c]);
        }
        for (int c = 0; c < 3; ++c) {
            const double sigmaT = m.sigmaA[c] + m.sigmaS[c], albedo = m.sigmaS[c] / sigmaT;
            const double reach = std::exp(-sigmaT * kBoundary), expected = albedo * (1.0 - reach) + reach;
            std::printf("[ measured ] channel %d: %.5f +- %.5f (exact %.5f)\n", c, weights[c].mean(),
                        weights[c].standardError(), expected);
            EXPECT_NEAR(weights[c].mean(), expected, z * weights[c].standardError()) << "channel " << c;
        }
    }
}

TEST(GuidedWalk, EveryScatteringChannelIsAHeroAtLeastAtTheFloorsShare) {
    // Mean free paths 10, 0.01 and 0.01: by mean free path alone green and blue would be heroes of
    // one walk in a thousand; the floor keeps each at least kHeroFloor / 3. A channel that does not
    // scatter (sigmaT 0) is never a hero.
    MediumProperties m;
    m.sigmaS = RGB(0.09f, 90.0f, 0.0f);
    m.sigmaA = RGB(0.01f, 10.0f, 0.0f);
    const RGB p = GuidedWalk(kEntry, kNormal, m, WalkChannels::Hero, 0.5f).channelProbabilities();
    EXPECT_GE(p[1], kHeroFloor / 2.0f - 1e-6f);
    EXPECT_EQ(p[2], 0.0f);
    EXPECT_NEAR(p[0] + p[1] + p[2], 1.0f, 1e-6f);
    m.sigmaS[2] = 90.0f;
    m.sigmaA[2] = 10.0f;
    const RGB q = GuidedWalk(kEntry, kNormal, m, WalkChannels::Hero, 0.5f).channelProbabilities();
    for (int c = 0; c < 3; ++c) EXPECT_GE(q[c], kHeroFloor / 3.0f - 1e-6f) << "channel " << c;
}

TEST(GuidedWalk, WalksOfThreeCollisionsAverageAlbedoCubed) {
    // A walk from the entry straight down into an unbounded medium, weighted as the path tracer
    // weighs it (the product of fly's throughputs), after its entry's step and two scatterings
    // has the expected value alpha^3 per channel (each collision's value sigmaS T phase integrates
    // to alpha over lengths and directions), Russian roulette included: with a channel per step
    // and with a hero per walk, whose weights are the balance heuristic over whole walks (THE STEP
    // AND ITS MIS; weighted as if the hero were uniform, they read 0.61 for alpha^3 = 0.97, where
    // P_h is by mean free path). Tolerance: z standard errors of the mean, z for 2 x 3 checks at a
    // family-wide 1%.
    constexpr int kN = 200000;
    constexpr float kUnbounded = std::numeric_limits<float>::infinity();
    const MediumProperties m = chromaticMedium();
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(6));
    for (WalkChannels channels : {WalkChannels::PerStep, WalkChannels::Hero}) {
        std::array<test::MeanEstimate, 3> weights;
        for (int n = 0; n < kN; ++n) {
            SampleStream rng(31, 0, std::uint64_t(n));
            GuidedWalk walk(kEntry, kNormal, m, channels, rng.next());
            walk.sawFarSide(Vec3f(0.0f, 0.0f, -1.0f), 1.5f);
            WalkStep step = walk.firstStep(kEntry, -kNormal, walk.stepChannel(rng.next()));
            RGB weight(1.0f);
            for (int collision = 0; collision < 3; ++collision) {
                const FreeFlight flight = walk.fly(step, walk.sampleLength(step, rng.next()), kUnbounded, rng);
                ASSERT_NE(flight.event, FlightEvent::Escaped);
                if (flight.event == FlightEvent::Absorbed) {
                    weight = RGB(0.0f);
                    break;
                }
                weight *= flight.throughput;
                const int channel = walk.stepChannel(rng.next());
                const float u = rng.next();
                step = walk.sampleStep(flight.p, -step.wi, channel, u, rng.next2D());
            }
            for (int c = 0; c < 3; ++c) weights[c].add(weight[c]);
        }
        for (int c = 0; c < 3; ++c) {
            const double albedo = m.sigmaS[c] / (m.sigmaA[c] + m.sigmaS[c]), expected = albedo * albedo * albedo;
            std::printf("[ measured ] channels %d, channel %d: %.5f +- %.5f (exact %.5f)\n", int(channels), c,
                        weights[c].mean(), weights[c].standardError(), expected);
            EXPECT_NEAR(weights[c].mean(), expected, z * weights[c].standardError())
                << "channels " << int(channels) << ", channel " << c;
        }
    }
}

}  // namespace
}  // namespace fluence::media
