// Regular tracking (media/exact_tracking.h) on a medium whose extinction is known in closed form:
// cubic pieces along x with a gap, chromatic. Exact transmittance against the closed-form optical
// depth; the flight's distances against the density sigmaT_h(t) exp(-tau_h(t)) by the chi-square
// test; its escape probability against T_h; its weights (pdfRatio, throughput, absorption) against
// their definitions; the homogeneous medium as one constant piece.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/random.h"
#include "media/exact_tracking.h"
#include "media/homogeneous_medium.h"
#include "tests/support/chi2.h"

namespace fluence::media {
namespace {

// sigmaT_c(x) over [0, 1): a_c (1 + 3 x - 2 x^2 + x^3 / 2); over [1, 1.5) vacuum; over [1.5, 3): b_c (x -
// 1.5)^2 (a quadratic with a zero, where inversion meets a vanishing density); elsewhere 0. Along +x
// from x = 0, so t = x. sigmaS = albedo sigmaT, sigmaA the rest, constant emission.
class CubicSlabs final : public Medium {
public:
    static constexpr double kEnd = 3.0;
    CubicSlabs(const Vec3d& a, const Vec3d& b, const RGB& albedo) : a_(a), b_(b), albedo_(albedo) {}

    Vec3d sigmaT(double x) const {
        if (x >= 0.0 && x < 1.0) return a_ * (1.0 + 3.0 * x - 2.0 * x * x + 0.5 * x * x * x);
        if (x >= 1.5 && x < kEnd) return b_ * ((x - 1.5) * (x - 1.5));
        return Vec3d(0.0);
    }
    Vec3d depth(double x) const {  // the integral of sigmaT over [0, x]
        const auto first = [](double s) { return s + 1.5 * s * s - 2.0 / 3.0 * s * s * s + s * s * s * s / 8.0; };
        Vec3d tau = a_ * first(std::min(std::max(x, 0.0), 1.0));
        const double u = std::min(std::max(x, 1.5), kEnd) - 1.5;
        return tau + b_ * (u * u * u / 3.0);
    }

    MediumProperties at(const Vec3f& p) const override {
        const Vec3d s = sigmaT(p.x);
        const RGB t(float(s.x), float(s.y), float(s.z));
        return {t * (RGB(1.0f) - albedo_), t * albedo_, RGB(2.0f), 0.0f};
    }
    void majorants(const Vec3f&, const Vec3f&, float, float, FunctionRef<bool(const MajorantSegment&)>) const override {
    }
    bool hasExactExtinction() const override { return true; }
    void extinctionPieces(const Vec3f& origin, const Vec3f&, float tMin, float tMax,
                          FunctionRef<bool(const ExtinctionPiece&)> visit) const override {
        // Pieces in t for a ray along +x from origin.x (the tests' rays).
        const double x0 = origin.x;
        const double cuts[][2] = {{0.0, 1.0}, {1.5, kEnd}};
        for (int i = 0; i < 2; ++i) {
            const double t0 = std::max(double(tMin), cuts[i][0] - x0), t1 = std::min(double(tMax), cuts[i][1] - x0);
            if (!(t0 < t1)) continue;
            const double x = x0 + t0;  // expand about x: s = t - t0
            ExtinctionPiece piece{t0, t1, {}};
            if (i == 0) {
                piece.scale = a_;
                const double k[4] = {1.0 + 3.0 * x - 2.0 * x * x + 0.5 * x * x * x, 3.0 - 4.0 * x + 1.5 * x * x,
                                     -2.0 + 1.5 * x, 0.5};
                std::copy(k, k + 4, piece.polynomial);
            } else {
                piece.scale = b_;
                const double k[4] = {(x - 1.5) * (x - 1.5), 2.0 * (x - 1.5), 1.0, 0.0};
                std::copy(k, k + 4, piece.polynomial);
            }
            if (!visit(piece)) return;
        }
    }

private:
    Vec3d a_, b_;
    RGB albedo_;
};

const CubicSlabs kSlabs(Vec3d(0.6, 0.9, 0.3), Vec3d(0.8, 0.2, 1.1), RGB(0.7f, 0.5f, 0.9f));
const MediumRay kRay{Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 2.8f};

TEST(ExactTracking, TransmittanceIsTheClosedForm) {
    for (float tMax : {0.5f, 1.2f, 2.0f, 2.8f}) {
        const TransmittanceEstimate tr = exactTransmittance(kSlabs, {kRay.origin, kRay.direction, tMax});
        const Vec3d tau = kSlabs.depth(tMax);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(tr.throughput[c], std::exp(-tau[c]), 1e-6) << tMax << " " << c;
        EXPECT_EQ(tr.pdfRatio, RGB(1.0f));
    }
}

// Distances of each hero's flights against sigmaT_h exp(-tau_h), over the whole ray (the gap
// included, where the density is 0); a single family of 3 tests at the suite's level.
TEST(ExactTracking, FlightDistancesFollowSigmaTTimesTransmittance) {
    for (int hero = 0; hero < 3; ++hero) {
        const test::Chi2Result r = test::chi2IntervalTest(
            [&](SampleStream& rng) -> std::optional<double> {
                const FreeFlight f = sampleExactFlight(kSlabs, kRay, hero, rng.next());
                if (f.event == FlightEvent::Escaped) return std::nullopt;
                return double(f.t);
            },
            [&](double t) { return kSlabs.sigmaT(t)[hero] * std::exp(-kSlabs.depth(t)[hero]); }, 0.0, kRay.tMax, 101,
            200'000, 11 + std::uint64_t(hero));
        std::printf("[ measured ] hero %d: chi2 p = %.3f\n", hero, r.pValue);
        EXPECT_GT(r.pValue, test::sidakAlpha(3)) << r.report;
    }
}

// P(escape) = T_h(tMax): the count of N flights is binomial, so it lies within 4 standard
// deviations sqrt(N T (1 - T)) of N T but for a 6e-5 chance.
TEST(ExactTracking, EscapesWithProbabilityTransmittance) {
    constexpr int kFlights = 200'000;
    for (int hero = 0; hero < 3; ++hero) {
        int escaped = 0;
        for (int n = 0; n < kFlights; ++n) {
            SampleStream rng(21, std::uint64_t(hero), std::uint64_t(n));
            escaped += sampleExactFlight(kSlabs, kRay, hero, rng.next()).event == FlightEvent::Escaped;
        }
        const double t = std::exp(-kSlabs.depth(kRay.tMax)[hero]);
        EXPECT_NEAR(escaped, kFlights * t, 4.0 * std::sqrt(kFlights * t * (1.0 - t))) << "hero " << hero;
    }
}

// The weights are f_c / p_h with the exact densities: at a stop, pdfRatio = sigmaT_c T_c / (sigmaT_h
// T_h), throughput = sigmaS_c T_c / (sigmaT_h T_h), absorbedThroughput = sigmaA_c T_c / (sigmaT_h
// T_h); on escape, throughput = pdfRatio = T_c / T_h and lightPdfRatio = 1 / T_h. The flight is a
// monotone function of u (inversion).
TEST(ExactTracking, WeightsAreTheExactDensityRatios) {
    float previous = -1.0f;
    for (int i = 0; i < 400; ++i) {
        const float u = (i + 0.5f) / 400.0f;
        const int hero = 1;
        const FreeFlight f = sampleExactFlight(kSlabs, kRay, hero, u);
        if (f.event == FlightEvent::Escaped) {
            const Vec3d tau = kSlabs.depth(kRay.tMax);
            for (int c = 0; c < 3; ++c) {
                const double ratio = std::exp(tau[hero] - tau[c]);
                EXPECT_NEAR(f.throughput[c], ratio, 1e-5 * ratio);
                EXPECT_NEAR(f.pdfRatio[c], ratio, 1e-5 * ratio);
            }
            EXPECT_NEAR(f.lightPdfRatio.x, std::exp(tau[hero]), 1e-5 * std::exp(tau[hero]));
            previous = INFINITY;
            continue;
        }
        ASSERT_EQ(f.event, FlightEvent::Scattered);
        EXPECT_GT(f.t, previous) << "u " << u;  // monotone in u
        previous = f.t;
        // The stop solves tau_h(t) = -log(1 - u).
        EXPECT_NEAR(kSlabs.depth(f.t)[hero], -std::log1p(-double(u)), 1e-5);
        const Vec3d sigma = kSlabs.sigmaT(f.t), tau = kSlabs.depth(f.t);
        const double pHero = sigma[hero] * std::exp(-tau[hero]);
        const RGB albedo(0.7f, 0.5f, 0.9f);
        for (int c = 0; c < 3; ++c) {
            const double pc = sigma[c] * std::exp(-tau[c]);
            EXPECT_NEAR(f.pdfRatio[c], pc / pHero, 1e-4 * pc / pHero);
            EXPECT_NEAR(f.throughput[c], albedo[c] * pc / pHero, 1e-4 * pc / pHero);
            EXPECT_NEAR(f.absorbedThroughput[c], (1.0f - albedo[c]) * pc / pHero, 1e-4 * pc / pHero);
        }
    }
}

// A homogeneous medium is one constant piece: exp(-sigmaT d), distances exponential (inverted
// directly: t = -log(1 - u) / sigmaT), and in an infinite medium no escape.
TEST(ExactTracking, HomogeneousMediumIsOneConstantPiece) {
    const RGB sigmaA(0.2f, 0.5f, 0.1f), sigmaS(0.6f, 0.3f, 1.0f);
    HomogeneousMedium medium({sigmaA, sigmaS});
    const TransmittanceEstimate tr = exactTransmittance(medium, {Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f), 1.7f});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tr.throughput[c], std::exp(-(sigmaA[c] + sigmaS[c]) * 1.7f), 1e-6);
    for (float u : {0.0f, 0.3f, 0.999f}) {
        const FreeFlight f = sampleExactFlight(medium, {Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f)}, 2, u);
        ASSERT_EQ(f.event, FlightEvent::Scattered);
        EXPECT_NEAR(f.t, -std::log1p(-double(u)) / 1.1, 1e-5 * (1.0 + f.t));
    }
    // Through all of an infinite medium nothing is transmitted (0, not the NaN of 0 x infinity), and
    // through a medium that does not attenuate one channel, everything in it.
    const TransmittanceEstimate all = exactTransmittance(medium, {Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f)});
    EXPECT_EQ(all.throughput, RGB(0.0f));
    HomogeneousMedium clearInGreen({RGB(0.2f, 0.0f, 0.1f), RGB(0.6f, 0.0f, 1.0f)});
    EXPECT_EQ(exactTransmittance(clearInGreen, {Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f)}).throughput,
              RGB(0.0f, 1.0f, 0.0f));
}

}  // namespace
}  // namespace fluence::media
