// The normalized diffusion profile (media/normalized_diffusion.h): sampled radii against
// pdfRadius (chi-square in r, expected counts by quadrature of the density), the density's
// normalisation and the constant sample weight A, the profile's total reflectance A, the energy
// within maxRadius, the behaviour at r -> 0, and the scaling s(A).
#include "media/normalized_diffusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <utility>
#include <vector>

#include "core/random.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Material {
    RGB albedo, meanFreePath;
};
// Albedos from near-black to near-white, mean free paths from 0.01 to 4 scene units.
const Material kMaterials[] = {
    {RGB(0.1f, 0.5f, 0.8f), RGB(1.0f, 0.5f, 2.0f)},
    {RGB(0.99f, 0.3f, 0.05f), RGB(0.01f, 3.0f, 0.2f)},
    {RGB(0.8f, 0.65f, 0.5f), RGB(4.0f, 1.5f, 0.75f)},
};
constexpr int kChannelTests = 3 * 3;  // materials x channels

// Chi-square tests: one per material and channel, for a family-wide false-failure rate of 1%.
const double kChi2Level = test::sidakAlpha(kChannelTests);
// Normal-theory checks: the mean weight and the mean radius per material and channel.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(2 * kChannelTests));

// The integral over [a, b] of f, the radius density p(r) = e^(-r/d) / (4d) + e^(-r/(3d)) / (12d)
// of a profile with shape parameter d or a multiple of it (R 2 pi r = A p), by composite 3-point
// Gauss-Legendre on intervals of about d / 8 (open: f is never evaluated at a or b, where the
// profile diverges). errorBound is the rule's, (b - a) h^6 max|p^(6)| / 2016000 with
// |p^(6)| <= (1/4 + 1/(12 3^6)) / d^7, for f = p: below 1e-10 of the integral; times A for R 2 pi r.
struct Quadrature {
    double value = 0.0, errorBound = 0.0;
};
Quadrature integrate(const std::function<double(double)>& f, double a, double b, double d) {
    const int intervals = std::max(1, int(std::ceil((b - a) / (d / 8.0))));
    const double width = (b - a) / intervals, offset = 0.5 * width * std::sqrt(0.6);
    Quadrature q;
    for (int i = 0; i < intervals; ++i) {
        const double mid = a + (i + 0.5) * width;
        q.value += width * (5.0 * f(mid - offset) + 8.0 * f(mid) + 5.0 * f(mid + offset)) / 18.0;
    }
    const double sixthDerivativeBound = (0.25 + 1.0 / (12.0 * 729.0)) / std::pow(d, 7);
    q.errorBound = (b - a) * std::pow(width, 6) * sixthDerivativeBound / 2016000.0;
    return q;
}

// Where the integrals over [0, inf) stop: the energy beyond it, below e^(-r/(3d)), is < 1e-17.
double farRadius(double d) { return 120.0 * d; }

// A float value computed in a few operations, and the float radius it is evaluated at, are each
// good to a few ulps; over an integral of a density, that is a relative error of a few ulps too
// (for the radius: int |p'(r)| r dr = 1).
constexpr double kRounding = test::kFloatDensityRounding;

// Pearson's statistic and its p-value, with cells of expected count below 5 pooled.
test::Chi2Result chi2(const std::vector<double>& observed, const std::vector<double>& expected) {
    test::Chi2Result result;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    for (std::size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        result.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooledExpected >= 5.0) {
        result.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++cells;
    }
    result.degreesOfFreedom = cells - 1;
    result.pValue = test::upperIncompleteGammaQ(0.5 * result.degreesOfFreedom, 0.5 * result.statistic);
    return result;
}

TEST(NormalizedDiffusion, SampledRadiiFollowPdfRadius) {
    // kBins equal bins in r over [0, maxRadius) and one for the tail; expected counts integrate
    // pdfRadius itself (not the closed-form CDF), so that the sampler is held to the density.
    constexpr int kBins = 40, kSamples = 1'000'000;
    std::uint64_t seed = 101;
    for (const Material& m : kMaterials) {
        NormalizedDiffusion profile(m.albedo, m.meanFreePath);
        for (int c = 0; c < 3; ++c, ++seed) {
            const double d = profile.shapeParameter()[c], rMax = profile.maxRadius(c), width = rMax / kBins;
            std::vector<double> observed(kBins + 1, 0.0), expected(kBins + 1, 0.0);
            for (int n = 0; n < kSamples; ++n) {
                SampleStream rng(seed, 0, n);
                const double r = profile.sampleRadius(c, rng.next());
                ASSERT_GE(r, 0.0);
                observed[r < rMax ? std::min(kBins - 1, int(r / width)) : kBins] += 1.0;
            }
            auto pdf = [&](double r) { return double(profile.pdfRadius(c, float(r))); };
            for (int i = 0; i < kBins; ++i)
                expected[i] = kSamples * integrate(pdf, i * width, (i + 1) * width, d).value;
            expected[kBins] = kSamples * integrate(pdf, rMax, rMax + farRadius(d), d).value;
            const test::Chi2Result result = chi2(observed, expected);
            std::printf("[ measured ] A %.2f, l %.2f (d %.4f): chi2 %.1f, dof %d, p = %.3f\n", m.albedo[c],
                        m.meanFreePath[c], d, result.statistic, result.degreesOfFreedom, result.pValue);
            EXPECT_GT(result.pValue, kChi2Level) << "A " << m.albedo[c] << ", l " << m.meanFreePath[c];
        }
    }
}

TEST(NormalizedDiffusion, PdfRadiusIntegratesToOneAndEverySampleWeighsA) {
    constexpr int kSamples = 200'000;
    std::uint64_t seed = 201;
    for (const Material& m : kMaterials) {
        NormalizedDiffusion profile(m.albedo, m.meanFreePath);
        for (int c = 0; c < 3; ++c, ++seed) {
            const double d = profile.shapeParameter()[c], a = profile.totalReflectance()[c];
            Quadrature total =
                integrate([&](double r) { return double(profile.pdfRadius(c, float(r))); }, 0.0, farRadius(d), d);
            EXPECT_NEAR(total.value, 1.0, total.errorBound + std::exp(-farRadius(d) / (3.0 * d)) + kRounding);

            // The estimate R(r) 2 pi r / pdfRadius(r) of the total reflectance is A at every
            // sample (up to the rounding of R and pdfRadius to float), so its mean is A within
            // its (rounding-sized) standard error. The mean radius, 1/4 d + 3/4 3d = 2.5 d, is
            // the sampler's first moment.
            test::MeanEstimate weight, radius;
            for (int n = 0; n < kSamples; ++n) {
                SampleStream rng(seed, 0, n);
                const float r = profile.sampleRadius(c, rng.next());
                const double w = double(profile.profile(r)[c]) * kTwoPi * r / profile.pdfRadius(c, r);
                ASSERT_NEAR(w, a, a * kRounding) << "r " << r;
                weight.add(w);
                radius.add(r);
            }
            std::printf(
                "[ measured ] A %.2f, l %.2f: pdfRadius integrates to %.9f (bound %.1e); mean weight "
                "%.8f +- %.1e; mean r / d %.4f +- %.4f (exact 2.5)\n",
                a, m.meanFreePath[c], total.value, total.errorBound, weight.mean(), weight.standardError(),
                radius.mean() / d, radius.standardError() / d);
            EXPECT_NEAR(weight.mean(), a, kZ * weight.standardError() + a * kRounding);
            EXPECT_NEAR(radius.mean(), 2.5 * d, kZ * radius.standardError());
        }
    }
}

TEST(NormalizedDiffusion, ProfileIntegratesToTheAlbedo) {
    // Each channel its own albedo and mean free path.
    for (float albedo : {0.1f, 0.5f, 0.8f, 0.99f}) {
        NormalizedDiffusion profile(RGB(albedo), RGB(0.3f, 1.0f, 2.5f));
        for (int c = 0; c < 3; ++c) {
            const double d = profile.shapeParameter()[c], a = profile.totalReflectance()[c];
            ASSERT_EQ(a, albedo);
            auto integrand = [&](double r) { return profile.profile(float(r))[c] * kTwoPi * float(r); };
            Quadrature total = integrate(integrand, 0.0, farRadius(d), d);
            std::printf("[ measured ] A %.2f, d %.4f: int R 2 pi r dr = %.9f (bound %.1e)\n", albedo, d, total.value,
                        a * total.errorBound);
            EXPECT_NEAR(total.value, a, a * (total.errorBound + std::exp(-farRadius(d) / (3.0 * d)) + kRounding));
        }
    }
}

TEST(NormalizedDiffusion, MaxRadiusHoldsTheDocumentedEnergyFraction) {
    constexpr double f = NormalizedDiffusion::kMaxRadiusEnergyFraction;
    for (const Material& m : kMaterials) {
        NormalizedDiffusion profile(m.albedo, m.meanFreePath);
        for (int c = 0; c < 3; ++c) {
            const double d = profile.shapeParameter()[c], rMax = profile.maxRadius(c);
            // F at the float nearest the exact radius: off by at most p(r) times half an ulp of r.
            const double cdf = normalizedDiffusionCdf(rMax, d);
            EXPECT_NEAR(cdf, f, profile.pdfRadius(c, float(rMax)) * rMax * 0x1p-24);
            // The closed form is the integral of pdfRadius.
            Quadrature inside =
                integrate([&](double r) { return double(profile.pdfRadius(c, float(r))); }, 0.0, rMax, d);
            EXPECT_NEAR(inside.value, cdf, inside.errorBound + kRounding);
            std::printf("[ measured ] d %.4f: maxRadius %.5f = %.4f d, F = %.9f, int_0^maxRadius p = %.9f\n", d, rMax,
                        rMax / d, cdf, inside.value);
        }
    }
}

TEST(NormalizedDiffusion, DivergesAsOneOverRAtTheEntryPoint) {
    NormalizedDiffusion profile(RGB(0.1f, 0.5f, 0.99f), RGB(0.01f, 1.0f, 30.0f));
    for (int c = 0; c < 3; ++c) {
        const double d = profile.shapeParameter()[c], a = profile.totalReflectance()[c];
        // R ~ A / (4 pi d r) (1 - 2/3 r/d + ...) and p(0) = 1 / (2d).
        const float r = float(1e-4 * d);
        EXPECT_NEAR(profile.profile(r)[c], a / (2.0 * kTwoPi * d * r), a / (2.0 * kTwoPi * d * r) * 1e-4);
        EXPECT_NEAR(profile.pdfRadius(c, 0.0f), 0.5 / d, 0.5 / d * kRounding);
        EXPECT_NEAR(profile.pdfArea(c, r), profile.pdfRadius(c, r) / (kTwoPi * r), profile.pdfArea(c, r) * kRounding);
        // u = 0 and u = 1/4 start each component's inversion at r = 0, where R and pdfArea are
        // held finite with R / pdfArea = A.
        for (float u : {0.0f, 0.25f}) {
            const float r0 = profile.sampleRadius(c, u);
            EXPECT_EQ(r0, 0.0f);
            EXPECT_FALSE(std::signbit(r0));
            EXPECT_TRUE(std::isfinite(profile.pdfArea(c, r0)));
            EXPECT_NEAR(profile.profile(r0)[c] / profile.pdfArea(c, r0), a, a * kRounding);
        }
    }
}

TEST(NormalizedDiffusion, ScalingFollowsTheSearchlightFitAndStaysPositive) {
    // s(A) = 1.85 - A + 7 |A - 0.8|^3 at a few albedos, worked by hand.
    const std::pair<float, double> spots[] = {{0.0f, 5.434}, {0.5f, 1.539}, {0.8f, 1.05}, {1.0f, 0.906}};
    for (auto [albedo, s] : spots) EXPECT_NEAR(normalizedDiffusionScale(albedo), s, s * kRounding) << "A " << albedo;
    // Decreasing on [0, 1] (s' = -1 - 21 (0.8 - A)^2 below 0.8, -1 + 21 (A - 0.8)^2 < 0 up to
    // A = 0.8 + 1/sqrt(21) > 1), so positive, its minimum s(1) = 0.906.
    float previous = normalizedDiffusionScale(0.0f);
    for (int i = 1; i <= 1000; ++i) {
        const float s = normalizedDiffusionScale(i / 1000.0f);
        ASSERT_LT(s, previous) << "A " << i / 1000.0f;
        ASSERT_GT(s, 0.9f);
        previous = s;
    }
    // d = l / s(A), with A clamped to [0, 1].
    NormalizedDiffusion profile(RGB(-0.2f, 0.4f, 1.5f), RGB(2.0f, 0.5f, 1.0f));
    EXPECT_EQ(profile.totalReflectance(), RGB(0.0f, 0.4f, 1.0f));
    EXPECT_EQ(profile.shapeParameter(),
              RGB(2.0f / normalizedDiffusionScale(0.0f), 0.5f / normalizedDiffusionScale(0.4f),
                  1.0f / normalizedDiffusionScale(1.0f)));
}

}  // namespace
}  // namespace fluence::media
