#include "render/bsdf.h"

#include <gtest/gtest.h>

#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

// The convention of bsdf.h: sample() returns f and pdf consistent with f() and pdf().
TEST(LambertianBsdf, SampleAgreesWithEvalAndPdf) {
    LambertianBsdf bsdf(RGB(0.2f, 0.5f, 0.8f));
    for (const Vec3f& wo : {Vec3f(0, 0, 1), normalize(Vec3f(1, 2, 0.3f)), normalize(Vec3f(0.5f, -1, -2))})
        for (int n = 0; n < 1000; ++n) {
            SampleStream rng(1, 0, n);
            auto s = bsdf.sample(wo, rng.next2D());
            ASSERT_TRUE(s);
            EXPECT_GT(s->wi.z * wo.z, 0.0f) << "reflection stays on the side of wo";
            EXPECT_FLOAT_EQ(s->pdf, bsdf.pdf(wo, s->wi));
            EXPECT_EQ(s->f, bsdf.f(wo, s->wi));
        }
}

TEST(LambertianBsdf, SamplingMatchesPdfOnBothSides) {
    LambertianBsdf bsdf(RGB(1.0f));
    for (const Vec3f& wo : {normalize(Vec3f(0.3f, 0.1f, 1)), normalize(Vec3f(0.3f, 0.1f, -1))}) {
        auto r = test::chi2SphereTest(
            [&](Vec2f u) -> std::optional<Vec3f> {
                auto s = bsdf.sample(wo, u);
                return s ? std::optional(s->wi) : std::nullopt;
            },
            [&](const Vec3f& wi) { return double(bsdf.pdf(wo, wi)); });
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    }
}

TEST(LambertianBsdf, ConservesEnergyExactlyWithAlbedoOne) {
    // Hemispherical reflectance = integral of f cos over the hemisphere = albedo. With cosine
    // sampling every sample's weight f cos / pdf equals the albedo exactly (zero variance).
    LambertianBsdf bsdf(RGB(1.0f, 0.5f, 0.25f));
    Vec3f wo = normalize(Vec3f(0.2f, 0.3f, 0.9f));
    for (int n = 0; n < 100; ++n) {
        auto s = bsdf.sample(wo, SampleStream(2, 0, n).next2D());
        ASSERT_TRUE(s);
        RGB weight = s->f * (std::abs(s->wi.z) / s->pdf);
        EXPECT_NEAR(weight.x, 1.0f, 1e-5f);
        EXPECT_NEAR(weight.y, 0.5f, 1e-5f);
        EXPECT_NEAR(weight.z, 0.25f, 1e-5f);
    }
}

TEST(LambertianBsdf, IsReciprocalAndZeroAcrossTheSurface) {
    LambertianBsdf bsdf(RGB(0.7f));
    Vec3f a = normalize(Vec3f(1, 0, 1)), b = normalize(Vec3f(0, 1, 3)), below = normalize(Vec3f(0, 1, -1));
    EXPECT_EQ(bsdf.f(a, b), bsdf.f(b, a));
    EXPECT_EQ(bsdf.f(a, below), RGB(0.0f));
    EXPECT_EQ(bsdf.pdf(a, below), 0.0f);
}

}  // namespace
}  // namespace fluence::render
