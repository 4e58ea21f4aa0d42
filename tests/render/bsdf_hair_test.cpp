// The hair BSDF (render/bsdfs/hair.h): its sampling against its pdf (chi-square over the whole
// sphere), its sample record against f and pdf, its pdf's normalisation, its longitudinal lobe's
// normalisation and symmetry (the part of the model that is reciprocal), the white furnace (no
// absorption: every bit of light scattered, measured by uniform sphere sampling independent of
// the model's own sampler), and absorption from colour.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/sampling.h"
#include "render/bsdfs/hair.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::render {
namespace {

struct HairCase {
    float h, roughness;
    RGB absorption;
};

std::vector<HairCase> cases() {
    return {{0.0f, 0.3f, RGB(0.0f)},
            {0.6f, 0.2f, RGB(0.0f)},
            {-0.9f, 0.5f, RGB(0.0f)},
            {0.3f, 0.3f, RGB(0.4f, 1.0f, 2.5f)},
            {-0.4f, 0.8f, RGB(0.1f)}};
}

HairBsdf bsdfOf(const HairCase& c) {
    HairParams p;
    p.offset = c.h;
    p.longitudinalRoughness = p.azimuthalRoughness = c.roughness;
    p.absorption = c.absorption;
    return HairBsdf(p);
}

std::string describe(const HairCase& c, const Vec3f& wo) {
    char text[160];
    std::snprintf(text, sizeof text, "h %.2f roughness %.2f sigma_a (%.2f %.2f %.2f) wo (%.3f %.3f %.3f)", c.h,
                  c.roughness, c.absorption.x, c.absorption.y, c.absorption.z, wo.x, wo.y, wo.z);
    return text;
}

// Views of the fibre: across it, along it at a slant, nearly along it, and from its far side.
std::vector<Vec3f> outgoing() {
    return {Vec3f(0.0f, 0.0f, 1.0f), normalize(Vec3f(0.5f, 0.3f, 0.8f)), normalize(Vec3f(-0.9f, 0.1f, 0.3f)),
            normalize(Vec3f(0.2f, -0.7f, -0.4f))};
}

// 5 cases x 4 directions of chi-square, 20 of the furnace and normalisation: Sidak-corrected.
const double kChi2Level = test::sidakAlpha(20);
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(20));

TEST(HairBsdf, SamplingMatchesPdfChiSquare) {
    for (const HairCase& c : cases())
        for (const Vec3f& wo : outgoing()) {
            const HairBsdf b = bsdfOf(c);
            auto r = test::chi2SphereTest(
                [&](SampleStream& rng) -> std::optional<Vec3f> {
                    float uLobe = rng.next();
                    auto s = b.sample(wo, uLobe, rng.next2D());
                    return s ? std::optional(s->wi) : std::nullopt;
                },
                [&](const Vec3f& wi) { return double(b.pdf(wo, wi)); }, test::Chi2Options{400'000});
            EXPECT_GT(r.pValue, kChi2Level) << describe(c, wo) << ": " << r.report;
        }
}

TEST(HairBsdf, SampleAgreesWithEvalAndPdf) {
    for (const HairCase& c : cases())
        for (const Vec3f& wo : outgoing()) {
            const HairBsdf b = bsdfOf(c);
            for (int n = 0; n < 500; ++n) {
                SampleStream rng(3, 0, n);
                float uLobe = rng.next();
                auto s = b.sample(wo, uLobe, rng.next2D());
                ASSERT_TRUE(s) << describe(c, wo);
                EXPECT_NEAR(length(s->wi), 1.0f, 1e-5f);
                EXPECT_FALSE(s->specular);
                const RGB f = b.f(wo, s->wi);
                EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi), 1e-4f * s->pdf) << describe(c, wo);
                for (int k = 0; k < 3; ++k) EXPECT_NEAR(s->f[k], f[k], 1e-4f * f[k] + 1e-7f) << describe(c, wo);
            }
        }
}

TEST(HairBsdf, PdfIntegratesToOne) {
    for (const HairCase& c : cases())
        for (const Vec3f& wo : outgoing()) {
            const HairBsdf b = bsdfOf(c);
            if (wo.z < 1.0f && wo.y > 0.0f) continue;  // two views per case keep the quadrature's time down
            test::SphereIntegral total =
                test::integrateOverSphere([&](const Vec3f& wi) { return double(b.pdf(wo, wi)); });
            EXPECT_NEAR(total.value, 1.0, 1e-3 + total.error) << describe(c, wo);
        }
}

TEST(HairBsdf, LongitudinalLobeIsNormalisedAndSymmetric) {
    // integral over theta_i in [-pi/2, pi/2] of M(theta_i, theta_o) cos theta_i = 1, by Simpson's
    // rule on 20000 intervals (its error is far below the tolerance for these widths).
    for (float v : {0.005f, 0.04f, 0.3f, 1.5f})
        for (float thetaO : {0.0f, 0.4f, 1.3f}) {
            const int intervals = 20000;
            double sum = 0.0;
            for (int i = 0; i <= intervals; ++i) {
                const double theta = -kPi / 2 + kPi * i / intervals;
                const double weight = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
                sum += weight *
                       HairBsdf::longitudinal(std::cos(float(theta)), std::cos(thetaO), std::sin(float(theta)),
                                              std::sin(thetaO), v) *
                       std::cos(theta);
            }
            EXPECT_NEAR(sum * kPi / intervals / 3.0, 1.0, 2e-4) << "v " << v << " theta_o " << thetaO;
            const float a =
                HairBsdf::longitudinal(std::cos(0.3f), std::cos(thetaO), std::sin(0.3f), std::sin(thetaO), v);
            const float b =
                HairBsdf::longitudinal(std::cos(thetaO), std::cos(0.3f), std::sin(thetaO), std::sin(0.3f), v);
            EXPECT_NEAR(a, b, 1e-5f * a) << "v " << v;
        }
}

TEST(HairBsdf, WhiteFurnaceScattersAllTheLight) {
    // sigma_a = 0: the integral of f |cos| over the sphere is 1. Uniform sphere sampling, so the
    // estimate does not lean on the model's own sampler; the tolerance is kZ standard errors.
    constexpr int kSamples = 400'000;
    for (float roughness : {0.2f, 0.5f, 0.9f})
        for (float h : {-0.7f, 0.0f, 0.5f}) {
            HairParams p;
            p.offset = h;
            p.longitudinalRoughness = p.azimuthalRoughness = roughness;
            const HairBsdf b(p);
            const Vec3f wo = normalize(Vec3f(0.4f, 0.2f, 0.9f));
            test::MeanEstimate albedo;
            for (int n = 0; n < kSamples; ++n) {
                SampleStream rng(11, 0, n);
                const Vec3f wi = sampleUniformSphere(rng.next2D());
                albedo.add(double(b.f(wo, wi).x) * std::abs(wi.z) / kUniformSpherePdf);
            }
            std::printf("[ measured ] hair furnace roughness %.1f h %+.1f: %.5f +- %.5f\n", roughness, h, albedo.mean(),
                        albedo.standardError());
            EXPECT_NEAR(albedo.mean(), 1.0, kZ * albedo.standardError()) << "roughness " << roughness << " h " << h;
        }
}

TEST(HairBsdf, AbsorptionFromColourDarkensToThatColour) {
    // Chiang et al.'s fit: white is no absorption, darker colours absorb more, per channel; the
    // fibre's albedo follows the colour's order.
    EXPECT_EQ(hairAbsorptionFromColour(RGB(1.0f), 0.3f).x, 0.0f);
    const RGB sigma = hairAbsorptionFromColour(RGB(0.8f, 0.4f, 0.1f), 0.3f);
    EXPECT_LT(sigma.x, sigma.y);
    EXPECT_LT(sigma.y, sigma.z);
    HairParams p;
    p.absorption = sigma;
    const HairBsdf b(p);
    const Vec3f wo(0.0f, 0.0f, 1.0f);
    // Importance-sampled albedo per channel (f |cos| / pdf over the model's own samples).
    RGB albedo(0.0f);
    constexpr int kSamples = 100'000;
    for (int n = 0; n < kSamples; ++n) {
        SampleStream rng(5, 0, n);
        const float uLobe = rng.next();
        if (auto s = b.sample(wo, uLobe, rng.next2D())) albedo += s->f * (std::abs(s->wi.z) / s->pdf / kSamples);
    }
    std::printf("[ measured ] hair of colour (0.8 0.4 0.1): albedo (%.4f %.4f %.4f)\n", albedo.x, albedo.y, albedo.z);
    EXPECT_GT(albedo.x, albedo.y);
    EXPECT_GT(albedo.y, albedo.z);
    EXPECT_LT(albedo.x, 1.0f);
}

}  // namespace
}  // namespace fluence::render
