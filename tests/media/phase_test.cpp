// The Henyey-Greenstein phase function (media/phase.h): sampling against its pdf (chi-square over
// the sphere), normalisation, the direction convention (forward = wi near -wo, mean cosine g), the
// sample record, reciprocity and the clamp of g.
#include "media/phase.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/sampling.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

constexpr float kGs[] = {-0.7f, 0.0f, 0.3f, 0.9f};
const Vec3f kWo = normalize(Vec3f(0.3f, -0.5f, 0.8f));

// 4 mean-cosine checks in this file, each at z standard errors, for a family-wide rate of 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(4));

TEST(HenyeyGreenstein, SamplingMatchesItsPdf) {
    for (float g : kGs) {
        HenyeyGreenstein hg(g);
        test::Chi2Result r = test::chi2SphereTest([&](Vec2f u) { return std::optional(hg.sample(kWo, u).wi); },
                                                  [&](const Vec3f& wi) { return double(hg.pdf(kWo, wi)); });
        std::printf("[ measured ] HG g %+.1f: %s\n", g, r.report.c_str());
        EXPECT_GT(r.pValue, test::kChi2Alpha) << "g " << g << ": " << r.report;
    }
}

TEST(HenyeyGreenstein, IntegratesToOneOverTheSphere) {
    for (float g : {-0.7f, 0.0f, 0.3f, 0.9f, 0.99f}) {
        HenyeyGreenstein hg(g);
        test::SphereIntegral total = test::integrateOverSphere([&](const Vec3f& wi) { return double(hg.p(kWo, wi)); });
        EXPECT_NEAR(total.value, 1.0, total.error + test::kFloatDensityRounding) << "g " << g;
    }
}

TEST(HenyeyGreenstein, ScattersForwardForPositiveGWithMeanCosineG) {
    // Forward is wi = -wo (the path goes on straight): the lobe's peak for g > 0, with the closed
    // value (1 + g) / (4 pi (1 - g)^2) (along an axis, so that cos theta is exactly 1); and
    // E[dot(-wo, wi)] = g.
    constexpr int kSamples = 200'000;
    const Vec3f up(0.0f, 0.0f, 1.0f);
    for (float g : kGs) {
        HenyeyGreenstein hg(g);
        const double peak = (1.0 + g) / (4.0 * 3.14159265358979323846 * (1.0 - g) * (1.0 - g));
        EXPECT_NEAR(hg.p(up, -up), peak, peak * 1e-6) << "g " << g;
        if (g > 0.0f) {
            EXPECT_GT(hg.p(kWo, -kWo), hg.p(kWo, kWo)) << "g " << g;
        }
        test::MeanEstimate cosine;
        for (int n = 0; n < kSamples; ++n) {
            SampleStream rng(21, 0, n);
            cosine.add(-dot(kWo, hg.sample(kWo, rng.next2D()).wi));
        }
        std::printf("[ measured ] HG g %+.1f: mean cos theta %.5f +- %.5f\n", g, cosine.mean(), cosine.standardError());
        EXPECT_NEAR(cosine.mean(), g, kZ * cosine.standardError()) << "g " << g;
    }
}

TEST(HenyeyGreenstein, SampleRecordIsConsistentAndReciprocal) {
    for (float g : kGs) {
        HenyeyGreenstein hg(g);
        for (int n = 0; n < 1000; ++n) {
            SampleStream rng(22, 0, n);
            PhaseSample s = hg.sample(kWo, rng.next2D());
            ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
            ASSERT_EQ(s.p, s.pdf);                // weight p / pdf is exactly 1
            ASSERT_EQ(s.pdf, hg.pdf(kWo, s.wi));  // the record's pdf is pdf()'s
            ASSERT_EQ(hg.p(kWo, s.wi), hg.p(s.wi, kWo));
        }
    }
}

TEST(HenyeyGreenstein, IsotropicValueIsTheGeneralExpressionsBitForBit) {
    // henyeyGreenstein(cos, 0) skips the square root and the division: its value must be what the
    // general expression gives at g = 0 (and -0), bit for bit, for every cosine; NaN stays NaN.
    for (float g : {0.0f, -0.0f})
        for (int i = -1200; i <= 1200; ++i) {
            const float cosTheta = float(i) / 1000.0f;  // past +-1 too: rounding puts dot products there
            const float d = (1.0f - g) * (1.0f - g) + 2.0f * g * (1.0f - cosTheta);
            const float general = (1.0f - g * g) / (4.0f * kPi * d * std::sqrt(d));
            EXPECT_EQ(henyeyGreenstein(cosTheta, g), general) << cosTheta;
        }
    EXPECT_TRUE(std::isnan(henyeyGreenstein(std::nanf(""), 0.0f)));
}

TEST(HenyeyGreenstein, ClampsGBelowOne) {
    EXPECT_EQ(HenyeyGreenstein(1.0f).g(), HenyeyGreenstein::kMaxG);
    EXPECT_EQ(HenyeyGreenstein(-2.0f).g(), -HenyeyGreenstein::kMaxG);
    EXPECT_TRUE(std::isfinite(HenyeyGreenstein(1.0f).p(kWo, -kWo)));
}

}  // namespace
}  // namespace fluence::media
