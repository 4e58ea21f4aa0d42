// Random-walk subsurface scattering in a semi-infinite slab against its exact solution, and the
// albedo inversion of media/subsurface_medium.h measured against the same.
//
// THE REFERENCE. A half-space of isotropically scattering medium with single-scattering albedo
// alpha and an index-matched boundary, lit by uniform diffuse light, reflects (Chandrasekhar 1950,
// "Radiative Transfer", chapter IV: the plane albedo for incidence mu is 1 - H(mu) sqrt(1 - alpha),
// averaged over cosine-weighted incidence)
//     R(alpha) = 1 - 2 sqrt(1 - alpha) integral_0^1 H(mu) mu dmu,
// with H the solution of 1 / H(mu) = sqrt(1 - alpha) + (alpha / 2) integral_0^1 mu' H(mu') / (mu + mu') dmu',
// solved here by fixed-point iteration on a Gauss-Legendre rule (and checked by its known
// zeroth moment, integral_0^1 H = (2 / alpha)(1 - sqrt(1 - alpha))).
#include "media/subsurface_medium.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/sampling.h"
#include "media/homogeneous_medium.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

// Nodes and weights of the n-point Gauss-Legendre rule on [0, 1] (Newton on P_n's roots).
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(n, 0.0);
    w.assign(n, 0.0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), derivative = 0.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = 0.0;
            for (int k = 1; k <= n; ++k) {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
            }
            derivative = n * (z * p0 - p1) / (z * z - 1.0);
            const double step = p0 / derivative;
            z -= step;
            if (std::abs(step) < 1e-15) break;
        }
        x[i] = 0.5 * (1.0 - z);
        w[i] = 1.0 / ((1.0 - z * z) * derivative * derivative);  // 2 / ((1 - z^2) P'^2), halved for [0, 1]
    }
}

// R(alpha) above.
double slabReflectance(double alpha) {
    std::vector<double> mu, w;
    gaussLegendre(96, mu, w);
    const double root = std::sqrt(1.0 - alpha);
    std::vector<double> h(mu.size(), 1.0), next(mu.size());
    for (int iteration = 0; iteration < 20000; ++iteration) {
        double change = 0.0;
        for (std::size_t i = 0; i < mu.size(); ++i) {
            double sum = 0.0;
            for (std::size_t j = 0; j < mu.size(); ++j) sum += w[j] * mu[j] * h[j] / (mu[i] + mu[j]);
            next[i] = 1.0 / (root + 0.5 * alpha * sum);
            change = std::max(change, std::abs(next[i] - h[i]));
        }
        h.swap(next);
        if (change < 1e-13) break;
    }
    double h0 = 0.0, h1 = 0.0;
    for (std::size_t j = 0; j < mu.size(); ++j) {
        h0 += w[j] * h[j];
        h1 += w[j] * h[j] * mu[j];
    }
    EXPECT_NEAR(h0, 2.0 / alpha * (1.0 - root), 1e-9) << "the H-function solver, alpha " << alpha;
    return 1.0 - 2.0 * root * h1;
}

TEST(SubsurfaceMedium, HalfSpaceWalkReflectsChandrasekharsAlbedo) {
    // Diffuse light enters the half-space z < 0 (cosine-weighted), walks by delta tracking and
    // Henyey-Greenstein (g = 0) sampling, and is scored 1 when it leaves through z = 0.
    const std::vector<float> albedos{0.2f, 0.5f, 0.8f, 0.95f, 0.99f};
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(static_cast<double>(albedos.size())));
    for (float alpha : albedos) {
        HomogeneousMedium slab({RGB(1.0f - alpha), RGB(alpha), RGB(0.0f), 0.0f});
        test::MeanEstimate reflected, scatterings;
        for (int n = 0; n < 40000; ++n) {
            SampleStream rng(71, 0, std::uint64_t(n));
            test::Walk walk;
            walk.hero = sampleHeroChannel(rng.next());
            walk.w = sampleCosineHemisphere(rng.next2D());
            walk.w.z = -walk.w.z;
            FreeFlight flight;
            do {
                const float tMax = walk.w.z > 0.0f ? -walk.p.z / walk.w.z : std::numeric_limits<float>::infinity();
                flight = walk.step(slab, tMax, rng);
            } while (flight.event == FlightEvent::Scattered);
            reflected.add(flight.event == FlightEvent::Escaped ? walk.beta.x / channelAverage(walk.rU) : 0.0);
            scatterings.add(walk.scatterings);
        }
        const double exact = slabReflectance(alpha);
        std::printf("[ measured ] alpha %.2f: R = %.5f +- %.5f (exact %.5f), %.1f scatterings per walk\n", alpha,
                    reflected.mean(), reflected.standardError(), exact, scatterings.mean());
        EXPECT_NEAR(reflected.mean(), exact, z * reflected.standardError()) << "alpha " << alpha;
    }
}

TEST(SubsurfaceMedium, AlbedoInversionGivesTheSlabTheRequestedColour) {
    // The fit is exact at 0 and 1; in between, the exact slab reflectance of the inverted albedo
    // stays within kFitError of the colour asked for (measured: at most +0.0020, at colour 0.2;
    // under 1e-4 from 0.8 up).
    constexpr double kFitError = 0.0025;
    EXPECT_NEAR(singleScatteringAlbedo(0.0f), 0.0f, 1e-5f);
    EXPECT_NEAR(singleScatteringAlbedo(1.0f), 1.0f, 1e-5f);
    float previous = -1.0f;
    for (float a : {0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.65f, 0.8f, 0.9f, 0.95f, 0.99f}) {
        const float alpha = singleScatteringAlbedo(a);
        EXPECT_GT(alpha, previous) << "the inversion increases with the colour";
        previous = alpha;
        const double r = slabReflectance(alpha);
        std::printf("[ measured ] colour %.2f: alpha %.5f, slab reflectance %.5f (%+.4f)\n", a, alpha, r, r - a);
        EXPECT_NEAR(r, a, kFitError) << "colour " << a;
    }
}

TEST(SubsurfaceMedium, CoefficientsFollowTheMeanFreePath) {
    MediumProperties m = subsurfaceMedium(RGB(0.8f, 0.45f, 0.35f), RGB(0.5f, 0.1f, 0.05f), 0.3f);
    const RGB mfp(0.5f, 0.1f, 0.05f), colour(0.8f, 0.45f, 0.35f);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(m.sigmaA[c] + m.sigmaS[c], 1.0f / mfp[c], 1e-4f) << c;
        EXPECT_NEAR(m.sigmaS[c] / (m.sigmaA[c] + m.sigmaS[c]), singleScatteringAlbedo(colour[c]), 1e-6f) << c;
    }
    EXPECT_FLOAT_EQ(m.g, 0.3f);
    EXPECT_FLOAT_EQ(subsurfaceMedium(RGB(1.0f), RGB(1.0f), 5.0f).g, kMaxSubsurfaceAnisotropy);
    EXPECT_TRUE(std::isfinite(subsurfaceMedium(RGB(0.5f), RGB(0.0f), 0.0f).sigmaS.x)) << "a zero radius is clamped";
}

}  // namespace
}  // namespace fluence::media
