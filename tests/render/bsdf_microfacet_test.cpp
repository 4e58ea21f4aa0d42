// Microfacet distributions and the GGX conductor: normalisation of D and of the visible normals
// (isotropic and anisotropic), visible-normal sampling, the roughness/anisotropy mapping, the
// white furnace of a perfectly reflecting conductor, and the smooth limit.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/sampling.h"
#include "render/bsdfs/beckmann.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx.h"
#include "render/bsdfs/ggx_conductor.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::render {
namespace {

TEST(BsdfMicrofacetDistribution, ProjectedAreaIsOne) {
    // The integral of D(h) cos theta_h over the hemisphere is the area of the macro-surface (1).
    for (float a : {0.05f, 0.3f, 1.0f}) {
        GgxDistribution ggx(a);
        BeckmannDistribution beckmann(a);
        test::SphereIntegral g =
            test::integrateOverSphere([&](const Vec3f& h) { return double(ggx.D(h)) * std::max(0.0f, h.z); });
        test::SphereIntegral b =
            test::integrateOverSphere([&](const Vec3f& h) { return double(beckmann.normalPdf(h)); });
        EXPECT_NEAR(g.value, 1.0, g.error + test::kFloatDensityRounding) << "GGX alpha " << a;
        EXPECT_NEAR(b.value, 1.0, b.error + test::kFloatDensityRounding) << "Beckmann m " << a;
    }
}

TEST(BsdfMicrofacetDistribution, VisibleNormalsIntegrateToOne) {
    // Smith's G1 makes the visible projected area of the microfacets equal that of the
    // macro-surface, cos theta_o: D_wo(h) = G1(wo) max(0, wo.h) D(h) / cos theta_o is a density
    // (the "weak white furnace" of Heitz 2014), at every angle including grazing ones.
    for (float a : {0.05f, 0.3f, 1.0f})
        for (float theta : {0.0f, 45.0f, 80.0f, 89.0f, 89.9f}) {
            GgxDistribution ggx(a);
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            test::SphereIntegral v =
                test::integrateOverSphere([&](const Vec3f& h) { return double(ggx.visibleNormalPdf(wo, h)); });
            EXPECT_NEAR(v.value, 1.0, v.error + test::kFloatDensityRounding) << "alpha " << a << ", theta " << theta;
        }
}

TEST(BsdfMicrofacetDistribution, VisibleNormalSamplingMatchesItsDensity) {
    for (float a : {0.1f, 0.5f})
        for (float theta : {10.0f, 70.0f}) {
            GgxDistribution ggx(a);
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            auto r = test::chi2SphereTest([&](Vec2f u) { return std::optional(ggx.sampleVisibleNormal(wo, u)); },
                                          [&](const Vec3f& h) { return double(ggx.visibleNormalPdf(wo, h)); }, 400'000);
            EXPECT_GT(r.pValue, test::sidakAlpha(5)) << "alpha " << a << ", theta " << theta << ": " << r.report;
        }
    BeckmannDistribution beckmann(0.3f);
    auto r = test::chi2SphereTest([&](Vec2f u) { return std::optional(beckmann.sampleNormal(u)); },
                                  [&](const Vec3f& h) { return double(beckmann.normalPdf(h)); }, 400'000);
    EXPECT_GT(r.pValue, test::sidakAlpha(5)) << "Beckmann: " << r.report;
}

// Anisotropic widths: stretched along x, along y, and strongly so.
const GgxDistribution kAnisotropic[] = {GgxDistribution(0.3f, 0.05f), GgxDistribution(0.05f, 0.5f),
                                        GgxDistribution(1.0f, 0.035f)};

TEST(BsdfMicrofacetDistribution, AnisotropicDistributionsAreNormalised) {
    // The projected area of D and the density of the visible normals integrate to 1 with
    // different widths along x and y too, at oblique and grazing wo (off both axes).
    for (const GgxDistribution& ggx : kAnisotropic) {
        SCOPED_TRACE(testing::Message() << "alpha (" << ggx.alphaX() << ", " << ggx.alphaY() << ")");
        test::SphereIntegral area =
            test::integrateOverSphere([&](const Vec3f& h) { return double(ggx.D(h)) * std::max(0.0f, h.z); });
        EXPECT_NEAR(area.value, 1.0, area.error + test::kFloatDensityRounding);
        for (float theta : {40.0f, 88.0f}) {
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            test::SphereIntegral v =
                test::integrateOverSphere([&](const Vec3f& h) { return double(ggx.visibleNormalPdf(wo, h)); });
            EXPECT_NEAR(v.value, 1.0, v.error + test::kFloatDensityRounding) << "theta " << theta;
        }
    }
}

TEST(BsdfMicrofacetDistribution, AnisotropicVisibleNormalSamplingMatchesItsDensity) {
    for (const GgxDistribution& ggx : {kAnisotropic[0], kAnisotropic[1]})
        for (float theta : {20.0f, 70.0f}) {
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            auto r = test::chi2SphereTest([&](Vec2f u) { return std::optional(ggx.sampleVisibleNormal(wo, u)); },
                                          [&](const Vec3f& h) { return double(ggx.visibleNormalPdf(wo, h)); }, 400'000);
            EXPECT_GT(r.pValue, test::sidakAlpha(4))
                << "alpha (" << ggx.alphaX() << ", " << ggx.alphaY() << "), theta " << theta << ": " << r.report;
        }
}

TEST(BsdfMicrofacetDistribution, RoughnessAndAnisotropyMapAsMaterialXDoes) {
    // alpha = r^2; aspect = sqrt(1 - min(a, 0.98)); alpha_x = min(alpha / aspect, 1), alpha_y =
    // alpha * aspect (MaterialX's roughness_anisotropy); no anisotropy: isotropic.
    GgxDistribution iso = GgxDistribution::fromRoughness(0.5f);
    EXPECT_FLOAT_EQ(iso.alphaX(), 0.25f);
    EXPECT_FLOAT_EQ(iso.alphaY(), 0.25f);
    GgxDistribution half = GgxDistribution::fromRoughness(0.5f, 0.5f);
    EXPECT_FLOAT_EQ(half.alphaX(), 0.25f / std::sqrt(0.5f));
    EXPECT_FLOAT_EQ(half.alphaY(), 0.25f * std::sqrt(0.5f));
    GgxDistribution full = GgxDistribution::fromRoughness(0.9f, 1.0f);
    EXPECT_FLOAT_EQ(full.alphaX(), 1.0f) << "clamped to 1";
    EXPECT_NEAR(full.alphaY(), 0.81f * std::sqrt(0.02f), 1e-6f);
    EXPECT_TRUE(GgxDistribution::fromRoughness(0.0f, 0.7f).isSmooth())
        << "no roughness: a mirror whatever the anisotropy";
    // The highlight stretches along x: microfacets tilted along x are likelier than along y.
    Vec3f tiltX = normalize(Vec3f(0.3f, 0.0f, 1.0f)), tiltY = normalize(Vec3f(0.0f, 0.3f, 1.0f));
    EXPECT_GT(half.D(tiltX), 2.0f * half.D(tiltY));
}

TEST(GgxConductorBsdf, AnisotropicWhiteFurnaceReflectsAtMostAllTheLight) {
    // F0 = 1 with anisotropic widths: albedo <= 1 and equal to the quadrature of f cos.
    constexpr int kSamples = 200'000;
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(12));
    for (const GgxDistribution& ggx : kAnisotropic)
        for (float theta : {0.0f, 75.0f}) {
            GgxConductorBsdf metal(RGB(1.0f), ggx);
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            test::MeanEstimate albedo = test::albedoEstimate(metal, wo, kSamples, 22);
            test::SphereIntegral reference = test::integrateOverSphere(
                [&](const Vec3f& wi) { return double(metal.f(wo, wi).x) * std::max(0.0f, wi.z); });
            std::printf("[ measured ] GGX conductor F0 = 1, alpha (%.3f, %.3f), theta %2.0f: albedo %.5f +- %.5f\n",
                        ggx.alphaX(), ggx.alphaY(), theta, albedo.mean(), albedo.standardError());
            SCOPED_TRACE(testing::Message()
                         << "alpha (" << ggx.alphaX() << ", " << ggx.alphaY() << "), theta " << theta);
            EXPECT_LE(albedo.mean(), 1.0 + z * albedo.standardError());
            EXPECT_NEAR(albedo.mean(), reference.value,
                        z * albedo.standardError() + reference.error + test::kFloatDensityRounding);
        }
}

TEST(GgxConductorBsdf, WhiteFurnaceWithF0OfOne) {
    // F0 = 1: every sample's weight is G2 / G1(wo) <= 1, and samples reflected below the horizon
    // count 0, so the albedo is at most 1. What it misses is the light that would scatter between
    // microfacets more than once (single scattering), a deficit that vanishes with alpha: at
    // normal incidence the visible normals tilted past 45 degrees, which reflect below the
    // horizon, are exactly a share alpha^2 / (1 + alpha^2) of them (the GGX slope distribution).
    // Checked: albedo <= 1; albedo == the quadrature of f cos (an independent path through f());
    // the share lost below the horizon at normal incidence == alpha^2 / (1 + alpha^2).
    constexpr int kSamples = 200'000;
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(27));
    for (float a : {0.05f, 0.1f, 0.3f})
        for (float theta : {0.0f, 45.0f, 75.0f, 88.0f}) {
            GgxConductorBsdf metal(RGB(1.0f), GgxDistribution(a));
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            test::MeanEstimate albedo, lost;
            for (int n = 0; n < kSamples; ++n) {
                SampleStream rng(21, 0, n);
                float uLobe = rng.next();
                auto s = metal.sample(wo, uLobe, rng.next2D());
                albedo.add(s ? s->f.x * s->wi.z / s->pdf : 0.0);
                lost.add(s ? 0.0 : 1.0);
            }
            test::SphereIntegral reference = test::integrateOverSphere(
                [&](const Vec3f& wi) { return double(metal.f(wo, wi).x) * std::max(0.0f, wi.z); });
            std::printf(
                "[ measured ] GGX conductor F0 = 1, alpha %.2f, theta %2.0f: albedo %.5f +- %.5f "
                "(quadrature %.5f), deficit %.5f\n",
                a, theta, albedo.mean(), albedo.standardError(), reference.value, 1.0 - albedo.mean());
            SCOPED_TRACE(testing::Message() << "alpha " << a << ", theta " << theta);
            EXPECT_LE(albedo.mean(), 1.0 + z * albedo.standardError());
            EXPECT_NEAR(albedo.mean(), reference.value,
                        z * albedo.standardError() + reference.error + test::kFloatDensityRounding);
            if (theta == 0.0f) {
                double share = double(a) * a / (1.0 + double(a) * a);
                EXPECT_NEAR(lost.mean(), share, z * std::sqrt(share * (1.0 - share) / kSamples));
            }
        }
}

TEST(GgxConductorBsdf, SmoothIsAMirrorWithSchlickReflectance) {
    GgxConductorBsdf mirror(RGB(0.9f, 0.6f, 0.3f), GgxDistribution(0.0f));
    EXPECT_EQ(mirror.flags(), unsigned(kBsdfReflection | kBsdfSpecular));
    for (float theta : {0.0f, 60.0f, 120.0f}) {
        Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
        auto s = mirror.sample(wo, 0.3f, Vec2f{0.2f, 0.7f});
        ASSERT_TRUE(s);
        EXPECT_TRUE(s->specular);
        EXPECT_FLOAT_EQ(s->pdf, 1.0f);
        EXPECT_EQ(s->wi, Vec3f(-wo.x, -wo.y, wo.z));
        RGB weight = s->f * (std::abs(s->wi.z) / s->pdf);
        RGB expected = fresnelSchlick(RGB(0.9f, 0.6f, 0.3f), std::abs(wo.z));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(weight[c], expected[c], 1e-6f);
        EXPECT_EQ(mirror.f(wo, s->wi), RGB(0.0f));
        EXPECT_EQ(mirror.pdf(wo, s->wi), 0.0f);
    }
}

}  // namespace
}  // namespace fluence::render
