// Free-flight sampling by delta tracking (media/free_flight.h), in both forms (a number from the
// stream at each tentative collision, or one event number remapped from collision to collision):
// real-collision distances follow the exponential in a homogeneous medium and
// 1 - exp(-(a t + b t^2 / 2)) in a linear ramp (chi-square), with exact and loose majorants;
// absorption and scattering in proportion to sigmaA and sigmaS; the escape probability of a slab
// is exp(-sigmaT d) (binomial error); in chromatic media the spectral MIS estimates of
// transmittance and of emission are unbiased per channel; and with one event number, the event
// is an inverse-CDF function of it over the tentative collisions.
#include "media/free_flight.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "media/homogeneous_medium.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

// Normal-theory checks in this file, per form: 2 absorption fractions + 2 escape probabilities +
// 3 x 4 chromatic channels, each at z standard errors, for a family-wide false-failure rate of 1%.
constexpr int kForms = 2;
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(16 * kForms));
// Chi-square tests: 3 per form, and 3 of the one-number form under the Sobol sampler, at the level
// that keeps the same family-wide rate.
const double kChi2Level = test::sidakAlpha(3 * kForms + 3);
constexpr double kRounding = 1e-6;

// The two forms of sampleFreeFlight (media/free_flight.h).
enum class Form { PerCollision, OneEventNumber };
constexpr Form kBothForms[kForms] = {Form::PerCollision, Form::OneEventNumber};
const char* name(Form form) { return form == Form::PerCollision ? "per collision" : "one event number"; }

FreeFlight fly(Form form, const Medium& medium, const MediumRay& ray, int hero, SampleStream& rng) {
    if (form == Form::PerCollision) return sampleFreeFlight(medium, ray, hero, rng);
    const float uEvent = rng.next();
    SampleStream steps = rng.independentStream();
    return sampleFreeFlight(medium, ray, hero, uEvent, steps);
}

// Pearson's chi-square of flights' outcomes against a distribution over [0, length) given by its
// CDF, in kBins equal-probability bins, plus one bin for escapes (probability 1 - cdf(length)).
// The flights are the samples 0, 1, ... of one pixel drawn by `sampler`. Returns the p-value.
double chi2OfFlights(Form form, const Medium& medium, const MediumRay& ray, const std::function<double(double)>& cdf,
                     std::uint64_t seed, const std::string& what, SamplerKind sampler = SamplerKind::Independent) {
    constexpr int kBins = 31, kFlights = 100'000;
    const double total = std::isinf(ray.tMax) ? 1.0 : cdf(ray.tMax);
    std::vector<double> observed(kBins + 1, 0.0);
    for (int n = 0; n < kFlights; ++n) {
        SampleStream rng(seed, 0, n, sampler);
        FreeFlight flight = fly(form, medium, ray, 0, rng);
        if (flight.event == FlightEvent::Escaped) {
            observed[kBins] += 1.0;
            continue;
        }
        // Gray media: every weight is 1 (the hero's choice is every channel's).
        EXPECT_EQ(flight.throughput, RGB(1.0f));
        observed[std::min(kBins - 1, int(cdf(flight.t) / total * kBins))] += 1.0;
    }
    double statistic = 0.0;
    int cells = 0;
    for (int i = 0; i <= kBins; ++i) {
        double expected = kFlights * (i < kBins ? total / kBins : 1.0 - total);
        if (expected < 5.0) continue;  // an unbounded ray never escapes
        statistic += (observed[i] - expected) * (observed[i] - expected) / expected;
        ++cells;
    }
    double p = test::upperIncompleteGammaQ(0.5 * (cells - 1), 0.5 * statistic);
    std::printf("[ measured ] %s, %s: chi2 %.1f over %d cells, p = %.3f\n", what.c_str(), name(form), statistic, cells,
                p);
    return p;
}

TEST(FreeFlight, CollisionDistancesAreExponentialInAHomogeneousMedium) {
    const float sigmaT = 1.3f;
    HomogeneousMedium exact({RGB(0.4f * sigmaT), RGB(0.6f * sigmaT)});
    test::RescaledBoundsMedium loose(exact, 2.5f, 0.0f);  // 60% of tentative collisions null
    const MediumRay ray{Vec3f(0.0f), normalize(Vec3f(-1.0f, 2.0f, 0.5f))};
    auto cdf = [&](double t) { return 1.0 - std::exp(-sigmaT * t); };
    for (Form form : kBothForms) {
        EXPECT_GT(chi2OfFlights(form, exact, ray, cdf, 51, "homogeneous, exact majorant"), kChi2Level);
        EXPECT_GT(chi2OfFlights(form, loose, ray, cdf, 52, "homogeneous, majorant 2.5 sigmaT"), kChi2Level);
    }
}

TEST(FreeFlight, CollisionDistancesFollowALinearRamp) {
    // sigmaT(x) = 0.2 + 0.8 x over 0 <= x < 3, five segments bounded at their larger end.
    test::RampMedium ramp(RGB(0.2f), RGB(0.8f), 3.0f, 5, true, RGB(0.5f));
    auto cdf = [](double t) { return 1.0 - std::exp(-(0.2 * t + 0.4 * t * t)); };
    for (Form form : kBothForms)
        EXPECT_GT(chi2OfFlights(form, ramp, {Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 2.5f}, cdf, 53, "linear ramp"),
                  kChi2Level);
}

// Under the Sobol sampler the one event number is a stratified dimension of the pixel's samples
// (as the path tracer draws it), the exponential steps independent numbers beside it: each flight
// still follows the distance law, with exact and loose majorants and in the ramp. (Stratified
// numbers make the counts closer to their expectations than independent ones: Pearson's test stays
// valid, conservative; a flight whose steps reused the event number fails it.)
TEST(FreeFlight, OneEventNumberKeepsTheDistanceLawUnderTheSobolSampler) {
    const float sigmaT = 1.3f;
    HomogeneousMedium exact({RGB(0.4f * sigmaT), RGB(0.6f * sigmaT)});
    test::RescaledBoundsMedium loose(exact, 2.5f, 0.0f);
    const MediumRay ray{Vec3f(0.0f), normalize(Vec3f(-1.0f, 2.0f, 0.5f))};
    auto cdf = [&](double t) { return 1.0 - std::exp(-sigmaT * t); };
    const Form form = Form::OneEventNumber;
    EXPECT_GT(chi2OfFlights(form, exact, ray, cdf, 61, "homogeneous, exact majorant, Sobol", SamplerKind::Sobol),
              kChi2Level);
    EXPECT_GT(chi2OfFlights(form, loose, ray, cdf, 62, "homogeneous, majorant 2.5 sigmaT, Sobol", SamplerKind::Sobol),
              kChi2Level);
    test::RampMedium ramp(RGB(0.2f), RGB(0.8f), 3.0f, 5, true, RGB(0.5f));
    auto rampCdf = [](double t) { return 1.0 - std::exp(-(0.2 * t + 0.4 * t * t)); };
    EXPECT_GT(chi2OfFlights(form, ramp, {Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 2.5f}, rampCdf, 63, "linear ramp, Sobol",
                            SamplerKind::Sobol),
              kChi2Level);
}

TEST(FreeFlight, AbsorbsAndScattersInProportion) {
    // Albedo 0.6: the fraction of real collisions that scatter is 0.6, binomial error.
    constexpr int kFlights = 100'000;
    const float sigmaT = 1.3f;
    HomogeneousMedium exact({RGB(0.4f * sigmaT), RGB(0.6f * sigmaT)});
    test::RescaledBoundsMedium loose(exact, 2.5f, 0.0f);
    for (Form form : kBothForms)
        for (const Medium* medium : {static_cast<const Medium*>(&exact), static_cast<const Medium*>(&loose)}) {
            test::MeanEstimate scattered;
            for (int n = 0; n < kFlights; ++n) {
                SampleStream rng(54, 0, n);
                FreeFlight flight = fly(form, *medium, {Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f)}, 1, rng);
                ASSERT_NE(flight.event, FlightEvent::Escaped);  // an unbounded medium
                scattered.add(flight.event == FlightEvent::Scattered ? 1.0 : 0.0);
            }
            const double sd = std::sqrt(0.6 * 0.4 / kFlights);
            std::printf("[ measured ] scattered fraction %.5f +- %.5f (exact 0.6)\n", scattered.mean(), sd);
            EXPECT_NEAR(scattered.mean(), 0.6, kZ * sd);
        }
}

TEST(FreeFlight, EscapesASlabWithProbabilityExpMinusSigmaTD) {
    constexpr int kFlights = 100'000;
    const float sigmaT = 0.8f, d = 1.5f;
    const double exact = std::exp(-double(sigmaT) * d), sd = std::sqrt(exact * (1.0 - exact) / kFlights);
    HomogeneousMedium slab({RGB(0.5f * sigmaT), RGB(0.5f * sigmaT)});
    test::RescaledBoundsMedium loose(slab, 3.0f, 0.0f);
    for (Form form : kBothForms)
        for (const Medium* medium : {static_cast<const Medium*>(&slab), static_cast<const Medium*>(&loose)}) {
            test::MeanEstimate escaped;
            for (int n = 0; n < kFlights; ++n) {
                SampleStream rng(55, 0, n);
                FreeFlight flight = fly(form, *medium, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), d}, 2, rng);
                if (flight.event == FlightEvent::Escaped) {
                    ASSERT_EQ(flight.t, d);
                    ASSERT_EQ(flight.throughput, RGB(1.0f));
                }
                escaped.add(flight.event == FlightEvent::Escaped ? 1.0 : 0.0);
            }
            std::printf("[ measured ] slab escape %.5f +- %.5f (exact %.5f)\n", escaped.mean(), sd, exact);
            EXPECT_NEAR(escaped.mean(), exact, kZ * sd);
        }
}

// Per channel, the mean of a score of sampleFreeFlight()'s result over flights with a uniform hero.
void expectChromaticMeans(const Medium& medium, const MediumRay& ray,
                          const std::function<RGB(const FreeFlight&)>& score, const RGB& expected, std::uint64_t seed,
                          const std::string& what) {
    constexpr int kFlights = 40'000;
    for (Form form : kBothForms) {
        test::MeanEstimate means[3];
        for (int n = 0; n < kFlights; ++n) {
            SampleStream rng(seed, 0, n);
            const int hero = sampleHeroChannel(rng.next());
            const RGB s = score(fly(form, medium, ray, hero, rng));
            for (int c = 0; c < 3; ++c) means[c].add(s[c]);
        }
        for (int c = 0; c < 3; ++c) {
            std::printf("[ measured ] %s, %s, channel %d: %.5f +- %.5f (exact %.5f)\n", what.c_str(), name(form), c,
                        means[c].mean(), means[c].standardError(), expected[c]);
            EXPECT_NEAR(means[c].mean(), expected[c], kZ * means[c].standardError() + kRounding)
                << what << ", " << name(form) << ", channel " << c;
        }
    }
}

// The spectral MIS estimate of transmittance from one flight: its weight if it escaped, else 0.
RGB escapeScore(const FreeFlight& f) {
    return f.event == FlightEvent::Escaped ? f.throughput / channelAverage(f.pdfRatio) : RGB(0.0f);
}

TEST(FreeFlight, TransmittanceIsUnbiasedPerChannelInChromaticMedia) {
    // A chromatic ramp (null collisions, sigmaT from 0.1 to 6 across channels) and a chromatic
    // homogeneous slab whose red channel is empty (the red hero draws no collision at all).
    const float d = 2.0f;
    test::RampMedium ramp(RGB(0.1f, 1.0f, 2.0f), RGB(1.5f, 0.0f, -0.6f), 3.0f, 4, false, RGB(0.3f, 0.9f, 0.5f));
    expectChromaticMeans(
        ramp, {Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), d}, escapeScore,
        RGB(std::exp(-(0.1f * d + 0.75f * d * d)), std::exp(-1.0f * d), std::exp(-(2.0f * d - 0.3f * d * d))), 56,
        "chromatic ramp transmittance");
    HomogeneousMedium slab({RGB(0.0f, 0.2f, 1.0f), RGB(0.0f, 0.6f, 0.5f)});
    expectChromaticMeans(slab, {Vec3f(0.0f), Vec3f(0.0f, -1.0f, 0.0f), d}, escapeScore,
                         RGB(1.0f, std::exp(-0.8f * d), std::exp(-1.5f * d)), 57, "slab with an empty channel");
}

TEST(FreeFlight, EmissionIsUnbiasedPerChannelInChromaticMedia) {
    // A purely absorbing, emitting slab of optical depth tau glows with Le (1 - e^-tau) (media/medium.h);
    // scored where a flight is absorbed: throughput Le / average(pdfRatio). Exact and loose bounds.
    const RGB sigmaA(0.5f, 1.5f, 3.0f), le(1.0f, 2.0f, 0.5f);
    const float d = 1.0f;
    HomogeneousMedium slab({sigmaA, RGB(0.0f), le});
    test::RescaledBoundsMedium loose(slab, 1.5f, 0.0f);
    RGB expected;
    for (int c = 0; c < 3; ++c) expected[c] = le[c] * (1.0f - std::exp(-sigmaA[c] * d));
    auto emissionScore = [](const FreeFlight& f) {
        return f.event == FlightEvent::Absorbed ? f.throughput * f.properties.emission / channelAverage(f.pdfRatio)
                                                : RGB(0.0f);
    };
    const MediumRay ray{Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), d};
    expectChromaticMeans(slab, ray, emissionScore, expected, 58, "emitting slab");
    expectChromaticMeans(loose, ray, emissionScore, expected, 59, "emitting slab, loose bounds");
}

TEST(FreeFlight, OneEventNumberIsAnInverseCdfOverTheTentativeCollisions) {
    // The same tentative collisions (one steps stream) for every event number u on a grid of
    // kGrid midpoints: the flight must stop at a later collision (or escape) as u grows, and the
    // share of the grid that stops at the k-th tentative collision must be its probability,
    // prod_{j<k} (1 - pStop) times pAbsorb or pScatter, to the grid's resolution (a count of grid
    // midpoints within an interval is its length times kGrid, +-1; the boundaries' float rounding,
    // amplified by the remaps, moves them by far less than a cell here). Homogeneous, majorant
    // 3 sigmaT: pStop = 1/3 at every point (pAbsorb 0.4/3, pScatter 0.6/3).
    constexpr int kGrid = 1 << 14;
    const float sigmaT = 0.5f;
    HomogeneousMedium exact({RGB(0.4f * sigmaT), RGB(0.6f * sigmaT)});
    test::RescaledBoundsMedium loose(exact, 3.0f, 0.0f);
    const MediumRay ray{Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 4.0f};
    for (std::uint64_t seed = 60; seed < 64; ++seed) {
        std::vector<float> points;  // the tentative collisions' distances, in order
        std::vector<int> absorbed, scattered;
        int escaped = 0, tentative = 0;  // tentative: the escaping flights' count of collisions
        float lastT = 0.0f;
        for (int i = 0; i < kGrid; ++i) {
            SampleStream steps(seed, 0, 0);
            const FreeFlight flight = sampleFreeFlight(loose, ray, 0, (i + 0.5f) / kGrid, steps);
            ASSERT_GE(flight.t, lastT) << "u " << (i + 0.5f) / kGrid;  // monotone in u
            lastT = flight.t;
            if (flight.event == FlightEvent::Escaped) {
                ++escaped;
                tentative = flight.collisions;
                continue;
            }
            const int k = flight.collisions - 1;  // the flight stopped at its last tentative collision
            if (k >= int(points.size())) {
                points.resize(k + 1, -1.0f);
                absorbed.resize(k + 1, 0);
                scattered.resize(k + 1, 0);
            }
            if (points[k] < 0.0f) points[k] = flight.t;
            ASSERT_EQ(points[k], flight.t);  // the same tentative collisions for every u
            ++(flight.event == FlightEvent::Absorbed ? absorbed : scattered)[k];
        }
        ASSERT_EQ(int(points.size()), tentative) << "seed " << seed;  // every collision stops some u
        double reach = 1.0;  // the probability of passing the collisions before the k-th
        for (std::size_t k = 0; k < points.size(); ++k) {
            EXPECT_NEAR(absorbed[k], kGrid * reach * 0.4 / 3.0, 1.5) << "seed " << seed << ", collision " << k;
            EXPECT_NEAR(scattered[k], kGrid * reach * 0.6 / 3.0, 1.5) << "seed " << seed << ", collision " << k;
            reach *= 2.0 / 3.0;
        }
        std::printf(
            "[ measured ] seed %d: %d tentative collisions (the first at %.4f), escapes %d of %d (exact %.1f)\n",
            int(seed), tentative, points.empty() ? 0.0 : points[0], escaped, kGrid, kGrid * reach);
        EXPECT_NEAR(escaped, kGrid * reach, 1.5);
    }
}

TEST(FreeFlight, OneEventNumberHandsOverToFreshNumbersWithoutBias) {
    // Once the null collisions passed leave less than 2^-12 of the event number's range, fresh
    // numbers from the steps stream decide. Here (majorant 50 sigmaT, so pStop = 1/50 per tentative
    // collision, optical depth tau = 12 ln 2 over about 416 tentative collisions) escapes happen
    // after that hand-over (the escaping event numbers are the top exp(-tau) = 2^-12 of [0, 1),
    // where the remaps run out; a flight with so few collisions that its escapes reach below the
    // top 2^-10 is 3.6 standard deviations of their Poisson count away), so the escape fraction of
    // event numbers drawn evenly from the top 2^-10 is exp(-tau) 2^10 = 0.25 only if the fresh
    // numbers keep delta tracking's probabilities. Each seed (its own tentative collisions) gives
    // one fraction over kGrid event numbers; the seeds are independent, so the mean's standard
    // error comes from their spread: within 4 of them.
    constexpr int kGrid = 256, kSeeds = 400;
    const double tau = 12.0 * std::log(2.0), top = std::ldexp(1.0, -10);
    HomogeneousMedium exact({RGB(0.0f), RGB(0.5f)});
    test::RescaledBoundsMedium loose(exact, 50.0f, 0.0f);
    const MediumRay ray{Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), float(tau / 0.5)};
    test::MeanEstimate fraction;
    for (int seed = 0; seed < kSeeds; ++seed) {
        int escaped = 0;
        for (int i = 0; i < kGrid; ++i) {
            SampleStream steps(std::uint64_t(700 + seed), 0, 0);
            const float u = float(1.0 - top * (i + 0.5) / kGrid);
            escaped += sampleFreeFlight(loose, ray, 0, u, steps).event == FlightEvent::Escaped;
        }
        fraction.add(double(escaped) / kGrid);
    }
    const double expected = std::exp(-tau) / top;
    std::printf("[ measured ] escape fraction of the top 2^-10: %.4f +- %.4f (exact %.4f)\n", fraction.mean(),
                fraction.standardError(), expected);
    EXPECT_NEAR(fraction.mean(), expected, 4.0 * fraction.standardError());
}

}  // namespace
}  // namespace fluence::media
