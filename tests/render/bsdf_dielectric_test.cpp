// The dielectric interface: Fresnel against known values, and the smooth and rough GGX
// dielectric's energy balance and Fresnel-proportional choice of reflection and refraction.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/sampling.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_dielectric.h"
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
    GgxDielectricBsdf glass(1.5f, 0.0f);
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
    GgxDielectricBsdf glass(1.5f, 0.0f);
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
            GgxDielectricBsdf glass(1.5f, alpha);
            FluxEstimate e = fluxAlbedo(glass, test::incidentDirection(theta, 0.8f, -0.6f), kSamples, 32);
            std::printf("[ measured ] rough dielectric eta 1.5, alpha %.2f, theta %3.0f: flux albedo %.6f +- %.6f\n",
                        alpha, theta, e.albedo.mean(), e.albedo.standardError());
            EXPECT_LE(e.albedo.mean(), 1.0 + z * e.albedo.standardError()) << "alpha " << alpha << ", theta " << theta;
        }
}

}  // namespace
}  // namespace fluence::render
