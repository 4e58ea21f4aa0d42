// The Charlie sheen lobe (render/bsdfs/sheen.h): its distribution's normalisation, its tabulated
// albedo against quadrature, its furnace (albedo <= 1), and a sheen layered over a base taking
// exactly its albedo from it. Its sampling is chi-square tested against its pdf, alone and
// layered, with every other model in bsdf_properties_test.cpp (CharlieSheen_*, SheenOverLambertian).
#include <gtest/gtest.h>

#include <cstdio>

#include "core/sampling.h"
#include "render/bsdf_arena.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/layered.h"
#include "render/bsdfs/sheen.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::render {
namespace {

// The albedo table's stated accuracy (render/bsdfs/sheen.h) for cos theta >= 0.001: its bilinear
// interpolation between quadrature nodes, measured at most 0.0048 on a dense scan.
constexpr double kTableTolerance = 0.005;

// 24 statistical checks in this file, each at z standard errors, for a family-wide rate of 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(24));

TEST(CharlieSheen, DistributionIsNormalisedAsProjectedArea) {
    for (float r : {0.1f, 0.3f, 1.0f}) {
        CharlieSheenBsdf lobe(RGB(1.0f), r);
        test::SphereIntegral area =
            test::integrateOverSphere([&](const Vec3f& h) { return h.z > 0.0f ? double(lobe.D(h)) * h.z : 0.0; });
        EXPECT_NEAR(area.value, 1.0, area.error + test::kFloatDensityRounding) << "r " << r;
    }
}

TEST(CharlieSheen, TabulatedAlbedoMatchesQuadrature) {
    // E(cos theta, r) = integral of f cos theta_i, by the adaptive quadrature of the test harness
    // (independent of the table's own fixed rule), between and on the table's nodes.
    for (float r : {0.1f, 0.23f, 1.0f})
        for (float cosTheta : {0.002f, 0.03f, 0.3f, 1.0f}) {
            CharlieSheenBsdf lobe(RGB(1.0f), r);
            Vec3f wo(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
            test::SphereIntegral e = test::integrateOverSphere(
                [&](const Vec3f& wi) { return double(lobe.f(wo, wi).x) * std::max(0.0f, wi.z); }, 1e-3);
            EXPECT_NEAR(charlieSheenAlbedo(cosTheta, r), e.value, kTableTolerance + e.error)
                << "r " << r << ", cos theta " << cosTheta;
        }
}

TEST(CharlieSheen, ReflectsAtMostAllTheLightAndWhatItsTableSays) {
    // The white lobe's Monte Carlo albedo, up to grazing incidence, is <= 1 and agrees with the
    // table. Below r = 0.1 the fitted shadowing would not keep it <= 1: the roughness is clamped.
    constexpr int kSamples = 100'000;
    for (float r : {0.1f, 0.4f, 1.0f})
        for (float theta : {0.0f, 60.0f, 85.0f, 89.5f}) {
            CharlieSheenBsdf lobe(RGB(1.0f), r);
            Vec3f wo = test::incidentDirection(theta, 0.6f, 0.8f);
            test::MeanEstimate albedo = test::albedoEstimate(lobe, wo, kSamples, 51);
            std::printf("[ measured ] Charlie sheen r %.1f, theta %4.1f: albedo %.5f +- %.5f (table %.5f)\n", r, theta,
                        albedo.mean(), albedo.standardError(), charlieSheenAlbedo(wo.z, r));
            EXPECT_LE(albedo.mean(), 1.0 + kZ * albedo.standardError()) << "r " << r << ", theta " << theta;
            EXPECT_NEAR(albedo.mean(), charlieSheenAlbedo(wo.z, r), kZ * albedo.standardError() + kTableTolerance)
                << "r " << r << ", theta " << theta;
        }
    const Vec3f wo = test::incidentDirection(70.0f), wi = test::incidentDirection(40.0f, -1.0f, 0.0f);
    EXPECT_EQ(CharlieSheenBsdf(RGB(1.0f), 0.01f).f(wo, wi), CharlieSheenBsdf(RGB(1.0f), kSheenMinRoughness).f(wo, wi));
}

TEST(CharlieSheen, ALayerTakesTheSheensAlbedoFromItsBase) {
    // Sheen of tint t over a white Lambertian (Standard Surface's sheen over diffuse): albedo(wo) =
    // t E(wo) + (1 - t E(wo)) * integral of (1 - t E(wi)) cos / pi, the closed form of the layer
    // (quadrature of the table for the integral); it is <= 1.
    constexpr int kSamples = 200'000;
    const float r = 0.3f, t = 0.8f;
    BsdfArena arena;
    const Bsdf& cloth =
        arena.make<LayeredBsdf<CharlieSheenBsdf>>(CharlieSheenBsdf(RGB(t), r), arena.make<LambertianBsdf>(RGB(1.0f)));
    test::SphereIntegral leaving = test::integrateOverSphere([&](const Vec3f& w) {
        return w.z > 0.0f ? (1.0 - t * charlieSheenAlbedo(w.z, r)) * w.z / 3.14159265358979323846 : 0.0;
    });
    for (float theta : {0.0f, 45.0f, 75.0f, 88.0f}) {
        Vec3f wo = test::incidentDirection(theta);
        double E = t * charlieSheenAlbedo(wo.z, r);
        double expected = E + (1.0 - E) * leaving.value;
        test::MeanEstimate albedo = test::albedoEstimate(cloth, wo, kSamples, 52);
        std::printf(
            "[ measured ] sheen (t %.1f, r %.1f) over white Lambertian, theta %2.0f: albedo %.5f +- %.5f, "
            "closed form %.5f\n",
            t, r, theta, albedo.mean(), albedo.standardError(), expected);
        EXPECT_NEAR(albedo.mean(), expected, kZ * albedo.standardError() + 2.0 * kTableTolerance + leaving.error)
            << "theta " << theta;
        EXPECT_LE(albedo.mean(), 1.0 + kZ * albedo.standardError()) << "theta " << theta;
    }
}

}  // namespace
}  // namespace fluence::render
