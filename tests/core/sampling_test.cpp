#include "core/sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/random.h"
#include "tests/support/chi2.h"

namespace fluence {
namespace {

using test::chi2SphereTest;
using test::kChi2Alpha;

TEST(Sampling, CosineHemisphereMatchesItsPdf) {
    auto r = chi2SphereTest([](Vec2f u) { return std::optional(sampleCosineHemisphere(u)); },
                            [](const Vec3f& w) { return double(cosineHemispherePdf(w.z)); });
    EXPECT_GT(r.pValue, kChi2Alpha) << r.report;
}

TEST(Sampling, UniformSphereMatchesItsPdf) {
    auto r = chi2SphereTest([](Vec2f u) { return std::optional(sampleUniformSphere(u)); },
                            [](const Vec3f&) { return double(kUniformSpherePdf); });
    EXPECT_GT(r.pValue, kChi2Alpha) << r.report;
}

TEST(Sampling, UniformConeMatchesItsPdf) {
    for (float cosMax : {0.9f, 0.3f, -0.5f}) {
        auto r = chi2SphereTest([&](Vec2f u) { return std::optional(sampleUniformCone(u, cosMax)); },
                                [&](const Vec3f& w) { return w.z >= cosMax ? double(uniformConePdf(cosMax)) : 0.0; });
        EXPECT_GT(r.pValue, kChi2Alpha) << "cosMax " << cosMax << ": " << r.report;
    }
}

TEST(Sampling, Chi2HarnessRejectsAWrongPdf) {
    // The harness must be able to fail: cosine-distributed samples against a uniform pdf.
    auto r = chi2SphereTest([](Vec2f u) { return std::optional(sampleCosineHemisphere(u)); },
                            [](const Vec3f& w) { return w.z > 0 ? 1.0 / (2.0 * kPi) : 0.0; }, 100000);
    EXPECT_LT(r.pValue, 1e-6) << r.report;
}

TEST(Sampling, UniformTriangleIsUniform) {
    // Chi-square over a grid of the unit square's lower triangle (b0 + b1 < 1): each of the
    // n(n+1)/2 lower cells... use cells fully inside the triangle, whose expected share is
    // cellArea / triangleArea.
    constexpr int kGrid = 20, kSamples = 400000;
    std::vector<double> counts(kGrid * kGrid, 0.0);
    for (int n = 0; n < kSamples; ++n) {
        SampleStream rng(3, 0, n);
        Vec2f b = sampleUniformTriangle(rng.next2D());
        ASSERT_GE(b.x, 0.0f);
        ASSERT_GE(b.y, 0.0f);
        ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
        counts[std::min(kGrid - 1, int(b.x * kGrid)) * kGrid + std::min(kGrid - 1, int(b.y * kGrid))] += 1.0;
    }
    double chi2 = 0.0;
    int cells = 0;
    const double expected = kSamples * (1.0 / (kGrid * kGrid)) / 0.5;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j + i + 1 < kGrid; ++j) {  // cells entirely below the diagonal
            double d = counts[i * kGrid + j] - expected;
            chi2 += d * d / expected;
            ++cells;
        }
    // Cells are a subset, so the statistic is chi-square with `cells` degrees of freedom
    // (approximately; the remaining mass is not constrained).
    double p = test::upperIncompleteGammaQ(0.5 * cells, 0.5 * chi2);
    EXPECT_GT(p, kChi2Alpha) << "chi2 " << chi2 << " over " << cells << " cells";
}

TEST(Sampling, UniformDiskStaysInsideAndCoversTheDisk) {
    double sumR2 = 0.0;
    constexpr int kN = 200000;
    for (int n = 0; n < kN; ++n) {
        SampleStream rng(5, 0, n);
        Vec2f d = sampleUniformDisk(rng.next2D());
        double r2 = double(d.x) * d.x + double(d.y) * d.y;
        ASSERT_LE(r2, 1.0 + 1e-6);
        sumR2 += r2;
    }
    // E[r^2] = 1/2 for a uniform disk; Var[r^2] = 1/12, so the standard error is sqrt(1/12/N).
    EXPECT_NEAR(sumR2 / kN, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / kN));
}

// The mapping's sine and cosine are polynomials (core/sampling.cpp), not std::sin/std::cos: on a
// fine grid of the square, every point is Shirley and Chiu's concentric mapping computed in double
// precision, to a few float ulps.
TEST(Sampling, UniformDiskIsTheConcentricMappingToAFewUlps) {
    constexpr int kGrid = 1001;
    double worst = 0.0;
    for (int i = 0; i <= kGrid; ++i)
        for (int j = 0; j <= kGrid; ++j) {
            const Vec2f u(float(i) / kGrid, float(j) / kGrid);
            const double ox = 2.0 * double(u.x) - 1.0, oy = 2.0 * double(u.y) - 1.0;
            double x = 0.0, y = 0.0;
            if (ox != 0.0 || oy != 0.0) {
                const double r = std::abs(ox) > std::abs(oy) ? ox : oy;
                const double theta =
                    std::abs(ox) > std::abs(oy) ? M_PI / 4.0 * (oy / ox) : M_PI / 2.0 - M_PI / 4.0 * (ox / oy);
                x = r * std::cos(theta);
                y = r * std::sin(theta);
            }
            const Vec2f d = sampleUniformDisk(u);
            worst = std::max({worst, std::abs(d.x - x), std::abs(d.y - y)});
        }
    EXPECT_LT(worst, 4.0 * std::numeric_limits<float>::epsilon()) << "largest error " << worst;
}

TEST(Sampling, PowerHeuristic) {
    EXPECT_FLOAT_EQ(powerHeuristic(1.0f, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(powerHeuristic(3.0f, 1.0f), 0.9f);
    EXPECT_FLOAT_EQ(powerHeuristic(0.0f, 0.0f), 0.0f);
    EXPECT_FLOAT_EQ(powerHeuristic(std::numeric_limits<float>::infinity(), 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(powerHeuristic(1.0f, std::numeric_limits<float>::infinity()), 0.0f);
    // Densities whose squares overflow a float (a grazing area-light sample) stay finite.
    EXPECT_FLOAT_EQ(powerHeuristic(2.1e20f, 0.31831f), 1.0f);
    EXPECT_NEAR(powerHeuristic(0.31831f, 2.1e20f), 0.0f, 1e-30f);
    EXPECT_FLOAT_EQ(powerHeuristic(3e20f, 1e20f), 0.9f);
}

TEST(DiscreteDistribution, SamplesInProportionToWeights) {
    DiscreteDistribution d({1.0, 0.0, 3.0, 6.0});
    EXPECT_FLOAT_EQ(d.pmf(0), 0.1f);
    EXPECT_FLOAT_EQ(d.pmf(1), 0.0f);
    EXPECT_FLOAT_EQ(d.pmf(2), 0.3f);
    EXPECT_FLOAT_EQ(d.pmf(3), 0.6f);
    constexpr int kN = 100000;
    std::vector<double> counts(4, 0.0);
    for (int n = 0; n < kN; ++n) counts[d.sample(SampleStream(9, 0, n).next())] += 1.0;
    EXPECT_EQ(counts[1], 0.0);
    double chi2 = 0.0;
    for (int i : {0, 2, 3}) {
        double e = kN * d.pmf(i);
        chi2 += (counts[i] - e) * (counts[i] - e) / e;
    }
    EXPECT_GT(test::upperIncompleteGammaQ(1.0, 0.5 * chi2), kChi2Alpha) << "chi2 " << chi2;
    EXPECT_EQ(d.sample(0.0f), 0u);
    EXPECT_EQ(d.sample(0.99999994f), 3u);
}

TEST(DiscreteDistribution, AllZeroWeightsFallBackToUniformAndNegativeWeightsThrow) {
    DiscreteDistribution d({0.0, 0.0});
    EXPECT_FLOAT_EQ(d.pmf(0), 0.5f);
    EXPECT_THROW(DiscreteDistribution({1.0, -1.0}), std::invalid_argument);
}

TEST(Chi2, IncompleteGammaMatchesKnownValues) {
    // Q(k/2, x/2) is the chi-square survival function: for 1 dof, P(X > 3.841459) = 0.05;
    // for 10 dof, P(X > 23.209251) = 0.01; for 2 dof it is exp(-x/2).
    EXPECT_NEAR(test::upperIncompleteGammaQ(0.5, 3.841459 / 2), 0.05, 1e-6);
    EXPECT_NEAR(test::upperIncompleteGammaQ(5.0, 23.209251 / 2), 0.01, 1e-6);
    EXPECT_NEAR(test::upperIncompleteGammaQ(1.0, 1.5), std::exp(-1.5), 1e-12);
}

}  // namespace
}  // namespace fluence
