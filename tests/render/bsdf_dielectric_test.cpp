// The dielectric interface: Fresnel against known values, the smooth and rough GGX dielectric's
// energy balance and Fresnel-proportional choice of reflection and refraction, its tints, and
// the thin dielectric sheet.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/sampling.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_dielectric.h"
#include "render/bsdfs/thin_dielectric.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::render {
namespace {

TEST(BsdfFresnel, NormalIncidenceIsTheSquaredIndexRatio) {
    for (float eta : {1.33f, 1.5f, 2.4f, 1.0f / 1.5f}) {
        float expected = (eta - 1.0f) * (eta - 1.0f) / ((eta + 1.0f) * (eta + 1.0f));
        EXPECT_NEAR(fresnelDielectric(1.0f, eta), expected, 1e-6f) << "eta " << eta;
    }
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnelDielectric(0.3f, 1.0f), 0.0f, 1e-12f) << "index-matched: no reflection";
    EXPECT_NEAR(fresnelDielectric(0.0f, 1.5f), 1.0f, 1e-6f) << "grazing incidence reflects everything";
}

TEST(BsdfFresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    // From glass (n = 1.5) into air: sin theta_c = 1 / 1.5, theta_c = 41.81 degrees.
    const float eta = 1.0f / 1.5f, cosCritical = std::sqrt(1.0f - eta * eta);
    EXPECT_EQ(fresnelDielectric(cosCritical - 1e-4f, eta), 1.0f);
    EXPECT_EQ(fresnelDielectric(std::cos(60.0f * kPi / 180.0f), eta), 1.0f);
    EXPECT_LT(fresnelDielectric(cosCritical + 1e-3f, eta), 1.0f);
}

TEST(BsdfFresnel, AgreesWithTheSineAndTangentForms) {
    // Fresnel's equations in the angle form: r_s = -sin(i - t) / sin(i + t),
    // r_p = tan(i - t) / tan(i + t), with Snell's sin t = sin i / eta (an independent derivation
    // of what fresnel.cpp computes from cosines).
    for (float eta : {1.5f, 1.0f / 1.5f, 2.4f})
        for (float degrees : {10.0f, 30.0f, 40.0f, 70.0f}) {
            double i = degrees * 3.14159265358979323846 / 180.0, sinT = std::sin(i) / eta;
            if (sinT >= 1.0) continue;
            double t = std::asin(sinT);
            double rs = std::sin(i - t) / std::sin(i + t), rp = std::tan(i - t) / std::tan(i + t);
            FresnelPolarized r = fresnelDielectricPolarized(float(std::cos(i)), eta);
            EXPECT_NEAR(r.s, rs * rs, 1e-6) << "eta " << eta << ", " << degrees << " degrees";
            EXPECT_NEAR(r.p, rp * rp, 1e-6) << "eta " << eta << ", " << degrees << " degrees";
        }
}

TEST(BsdfFresnel, BrewsterAngleCancelsParallelPolarisation) {
    for (float eta : {1.5f, 1.33f, 1.0f / 1.5f}) {
        float thetaB = std::atan(eta);  // tan theta_B = n_t / n_i
        FresnelPolarized r = fresnelDielectricPolarized(std::cos(thetaB), eta);
        EXPECT_NEAR(r.p, 0.0f, 1e-7f) << "eta " << eta;
        EXPECT_GT(r.s, 0.01f);
        // The s reflectance there has the closed form ((eta^2 - 1) / (eta^2 + 1))^2.
        float e2 = eta * eta;
        EXPECT_NEAR(r.s, (e2 - 1) * (e2 - 1) / ((e2 + 1) * (e2 + 1)), 1e-6f) << "eta " << eta;
    }
}

TEST(BsdfFresnel, SchlickMatchesAtNormalIncidenceAndGoesToOneAtGrazing) {
    RGB f0(0.04f, 0.5f, 1.0f);
    EXPECT_EQ(fresnelSchlick(f0, 1.0f), f0);
    EXPECT_EQ(fresnelSchlick(f0, 0.0f), RGB(1.0f));
}

// Flux albedo over samples: f |cos| / pdf, times eta^2 when refracted (render/bsdf.h).
struct FluxEstimate {
    test::MeanEstimate albedo, reflected;
};
FluxEstimate fluxAlbedo(const Bsdf& bsdf, const Vec3f& wo, int samples, std::uint64_t seed) {
    FluxEstimate e;
    for (int n = 0; n < samples; ++n) {
        SampleStream rng(seed, 0, n);
        float uLobe = rng.next();
        auto s = bsdf.sample(wo, uLobe, rng.next2D());
        bool reflected = s && s->wi.z * wo.z > 0.0f;
        e.albedo.add(s ? s->f.x * std::abs(s->wi.z) * s->eta * s->eta / s->pdf : 0.0);
        e.reflected.add(reflected ? 1.0 : 0.0);
    }
    return e;
}

TEST(GgxDielectricBsdf, SmoothReflectsPlusTransmitsExactlyOne) {
    // Every sample's flux weight is F / F or (1 - F) / eta^2 * eta^2 / (1 - F) = 1: zero
    // variance. Reflection is chosen with probability F.
    constexpr int kSamples = 100'000;
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(5));
    GgxDielectricBsdf glass(1.5f, GgxDistribution(0.0f));
    for (float theta : {0.0f, 50.0f, 85.0f, 150.0f, 120.0f}) {
        Vec3f wo = test::incidentDirection(theta, 0.8f, -0.6f);
        FluxEstimate e = fluxAlbedo(glass, wo, kSamples, 31);
        EXPECT_NEAR(e.albedo.mean(), 1.0, 1e-6) << "theta " << theta;
        float eta = wo.z > 0.0f ? 1.5f : 1.0f / 1.5f;
        double F = fresnelDielectric(std::abs(wo.z), eta);
        if (F < 1.0)
            EXPECT_NEAR(e.reflected.mean(), F, z * std::sqrt(F * (1.0 - F) / kSamples) + 1e-9) << "theta " << theta;
        else
            EXPECT_EQ(e.reflected.mean(), 1.0) << "theta " << theta << ": total internal reflection";
    }
}

TEST(GgxDielectricBsdf, SmoothRefractionFollowsSnellAndScalesRadiance) {
    GgxDielectricBsdf glass(1.5f, GgxDistribution(0.0f));
    Vec3f wo = test::incidentDirection(40.0f, 0.8f, -0.6f);
    auto s = glass.sample(wo, 0.99f, Vec2f{0.5f, 0.5f});
    ASSERT_TRUE(s);
    ASSERT_TRUE(s->specular);
    EXPECT_LT(s->wi.z, 0.0f);
    EXPECT_FLOAT_EQ(s->eta, 1.5f);
    float sinO = std::sqrt(1.0f - wo.z * wo.z), sinI = std::sqrt(1.0f - s->wi.z * s->wi.z);
    EXPECT_NEAR(sinO, 1.5f * sinI, 1e-6f) << "Snell";
    EXPECT_NEAR(s->wi.x / sinI, -wo.x / sinO, 1e-5f) << "in the plane of incidence, across the normal";
    // Radiance weight (1 - F) / eta^2.
    float F = fresnelDielectric(wo.z, 1.5f);
    EXPECT_NEAR(s->f.x * std::abs(s->wi.z) / s->pdf, 1.0f / (1.5f * 1.5f), 1e-6f);
    EXPECT_NEAR(s->pdf, 1.0f - F, 1e-6f);
}

TEST(GgxDielectricBsdf, RoughConservesFluxUpToItsSingleScatteringDeficit) {
    // The flux albedo is at most 1 at every roughness and side, and at low roughness it tends
    // to the smooth interface's exact 1.
    constexpr int kSamples = 200'000;
    const double z = test::normalQuantile(test::sidakAlpha(12));
    for (float alpha : {0.01f, 0.2f, 0.6f})
        for (float theta : {0.0f, 60.0f, 85.0f, 150.0f}) {
            GgxDielectricBsdf glass(1.5f, GgxDistribution(alpha));
            FluxEstimate e = fluxAlbedo(glass, test::incidentDirection(theta, 0.8f, -0.6f), kSamples, 32);
            std::printf("[ measured ] rough dielectric eta 1.5, alpha %.2f, theta %3.0f: flux albedo %.6f +- %.6f\n",
                        alpha, theta, e.albedo.mean(), e.albedo.standardError());
            EXPECT_LE(e.albedo.mean(), 1.0 + z * e.albedo.standardError()) << "alpha " << alpha << ", theta " << theta;
        }
}

// The flux albedo per channel (f |cos| eta^2 / pdf, failures 0) and the share of samples that
// went straight through (wi == -wo).
struct ChannelFlux {
    test::MeanEstimate albedo[3], straight;
};
ChannelFlux channelFlux(const Bsdf& bsdf, const Vec3f& wo, int samples, std::uint64_t seed) {
    ChannelFlux e;
    for (int n = 0; n < samples; ++n) {
        SampleStream rng(seed, 0, n);
        float uLobe = rng.next();
        auto s = bsdf.sample(wo, uLobe, rng.next2D());
        RGB w = s ? s->f * (std::abs(s->wi.z) * s->eta * s->eta / s->pdf) : RGB(0.0f);
        for (int c = 0; c < 3; ++c) e.albedo[c].add(w[c]);
        e.straight.add(s && s->wi == -wo ? 1.0 : 0.0);
    }
    return e;
}

// 30 statistical checks below, each at z standard errors, for a family-wide rate of 1%.
const double kTintZ = test::normalQuantile(0.5 * test::sidakAlpha(30));

TEST(GgxDielectricBsdf, TintsSplitFresnelBetweenReflectionAndTransmission) {
    // Smooth glass with reflection tint R and transmission tint T: the flux albedo per channel is
    // R F + T (1 - R F); from inside beyond the critical angle (F = 1) it is R, the rest lost.
    const DielectricTints tints{RGB(1.0f, 0.5f, 0.0f), RGB(0.2f, 0.6f, 1.0f)};
    GgxDielectricBsdf glass(1.5f, GgxDistribution(0.0f), tints);
    for (float theta : {0.0f, 70.0f, 160.0f, 130.0f}) {
        Vec3f wo = test::incidentDirection(theta, 0.8f, -0.6f);
        double F = fresnelDielectric(std::abs(wo.z), wo.z > 0.0f ? 1.5f : 1.0f / 1.5f);
        ChannelFlux e = channelFlux(glass, wo, 100'000, 33);
        for (int c = 0; c < 3; ++c) {
            double expected = F == 1.0
                                  ? tints.reflection[c]
                                  : tints.reflection[c] * F + tints.transmission[c] * (1.0 - tints.reflection[c] * F);
            EXPECT_NEAR(e.albedo[c].mean(), expected, kTintZ * e.albedo[c].standardError() + 1e-6)
                << "theta " << theta << ", channel " << c << (F == 1.0 ? " (total internal reflection)" : "");
        }
    }
}

TEST(ThinDielectricBsdf, SmoothSheetReflectsTheSlabShareAndPassesTheRestStraight) {
    // A smooth sheet of index 1.5: the slab reflects R_s = 2F / (1 + F) (inter-reflections
    // summed), the rest goes straight through (wi = -wo, eta 1); every sample weighs exactly 1.
    ThinDielectricBsdf sheet(1.5f, GgxDistribution(0.0f));
    constexpr int kSamples = 100'000;
    for (float theta : {0.0f, 60.0f, 85.0f, 120.0f}) {
        Vec3f wo = test::incidentDirection(theta, 0.8f, -0.6f);
        double F = fresnelDielectric(std::abs(wo.z), 1.5f), slab = 2.0 * F / (1.0 + F);
        ChannelFlux e = channelFlux(sheet, wo, kSamples, 34);
        EXPECT_NEAR(e.albedo[0].mean(), 1.0, 1e-6) << "theta " << theta;
        EXPECT_NEAR(e.albedo[0].standardError(), 0.0, 1e-6) << "theta " << theta;
        EXPECT_NEAR(1.0 - e.straight.mean(), slab, kTintZ * std::sqrt(slab * (1.0 - slab) / kSamples))
            << "theta " << theta;
    }
}

TEST(ThinDielectricBsdf, RoughSheetBlursOnlyItsReflectionAndKeepsFluxAtMostOne) {
    // Rough faces, locally parallel: the transmitted light still leaves along -wo; the flux albedo
    // (reflection with its single-scattering deficit, plus the straight-through share) is <= 1;
    // with tints it is at most R R_s + T (1 - R R_s) per microfacet, so below 1 with T < 1.
    constexpr int kSamples = 100'000;
    const DielectricTints tints{RGB(1.0f), RGB(1.0f, 0.5f, 0.25f)};
    for (float alpha : {0.1f, 0.5f})
        for (float theta : {0.0f, 70.0f, 140.0f}) {
            ThinDielectricBsdf sheet(1.5f, GgxDistribution(alpha), tints);
            Vec3f wo = test::incidentDirection(theta, 0.8f, -0.6f);
            ChannelFlux e = channelFlux(sheet, wo, kSamples, 35);
            for (int n = 0; n < 1000; ++n) {
                SampleStream rng(36, 0, n);
                float uLobe = rng.next();
                auto s = sheet.sample(wo, uLobe, rng.next2D());
                if (s && s->wi.z * wo.z < 0.0f) {
                    ASSERT_EQ(s->wi, -wo) << "transmitted light keeps its direction";
                }
            }
            std::printf(
                "[ measured ] thin sheet eta 1.5, alpha %.1f, theta %3.0f: flux albedo %.5f +- %.5f "
                "(straight through %.4f)\n",
                alpha, theta, e.albedo[0].mean(), e.albedo[0].standardError(), e.straight.mean());
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(e.albedo[c].mean(), 1.0 + kTintZ * e.albedo[c].standardError())
                    << "alpha " << alpha << ", theta " << theta << ", channel " << c;
        }
}

}  // namespace
}  // namespace fluence::render
