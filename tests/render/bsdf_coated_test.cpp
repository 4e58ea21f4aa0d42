// The coated (layered) BSDF: its albedo against the closed form of its approximation (clear,
// tinted, filtered), the energy bound for rough coats, and a coat over glass.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "core/sampling.h"
#include "render/bsdf_arena.h"
#include "render/bsdfs/coated.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/ggx_dielectric.h"
#include "render/bsdfs/lambertian.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::render {
namespace {

constexpr int kSamples = 400'000;

// This file makes 39 statistical checks; each allows z standard errors, for a family-wide
// false-failure rate of 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(39));

TEST(CoatedBsdf, SmoothWhitePlasticMatchesItsClosedForm) {
    // Smooth coat over a white Lambertian: albedo(wo) = F(cos o) + (1 - F(cos o)) * T, where
    // T = integral of (1 - F(cos i)) cos i / pi over the hemisphere (the share of the base's
    // light that leaves in one pass), computed here by quadrature. What a full layer simulation
    // would add, 1 - albedo, is the energy the approximation loses (printed).
    const float eta = 1.5f;
    BsdfArena arena;
    const Bsdf& plastic = arena.make<CoatedBsdf>(arena.make<LambertianBsdf>(RGB(1.0f)), eta, 0.0f);
    test::SphereIntegral T = test::integrateOverSphere([&](const Vec3f& w) {
        return w.z > 0.0f ? (1.0 - fresnelDielectric(w.z, eta)) * w.z / 3.14159265358979323846 : 0.0;
    });
    for (float theta : {0.0f, 45.0f, 80.0f}) {
        double F = fresnelDielectric(std::cos(theta * kPi / 180.0f), eta);
        double expected = F + (1.0 - F) * T.value;
        test::MeanEstimate e = test::albedoEstimate(plastic, test::incidentDirection(theta), kSamples, 41);
        std::printf(
            "[ measured ] white plastic (eta 1.5, smooth coat), theta %2.0f: albedo %.5f +- %.5f, "
            "closed form %.5f, energy lost %.5f\n",
            theta, e.mean(), e.standardError(), expected, 1.0 - expected);
        EXPECT_NEAR(e.mean(), expected, kZ * e.standardError() + T.error) << "theta " << theta;
    }
}

TEST(CoatedBsdf, RoughCoatsReflectAtMostAllTheLight) {
    BsdfArena arena;
    for (float alpha : {0.05f, 0.2f, 0.5f}) {
        arena.reset();
        const Bsdf& plastic = arena.make<CoatedBsdf>(arena.make<LambertianBsdf>(RGB(1.0f)), 1.5f, alpha);
        const Bsdf& coatedGold =
            arena.make<CoatedBsdf>(arena.make<GgxConductorBsdf>(RGB(1.0f), GgxDistribution(0.1f)), 1.5f, alpha);
        for (float theta : {0.0f, 60.0f, 85.0f}) {
            const Vec3f wo = test::incidentDirection(theta);
            test::MeanEstimate p = test::albedoEstimate(plastic, wo, kSamples, 42);
            test::MeanEstimate g = test::albedoEstimate(coatedGold, wo, kSamples, 43);
            std::printf(
                "[ measured ] coat alpha %.2f, theta %2.0f: white plastic %.5f +- %.5f, coated F0=1 metal "
                "%.5f +- %.5f\n",
                alpha, theta, p.mean(), p.standardError(), g.mean(), g.standardError());
            EXPECT_LE(p.mean(), 1.0 + kZ * p.standardError()) << "plastic, alpha " << alpha << ", theta " << theta;
            EXPECT_LE(g.mean(), 1.0 + kZ * g.standardError()) << "metal, alpha " << alpha << ", theta " << theta;
        }
    }
}

TEST(CoatedBsdf, SmoothCoatReflectsItsFresnelShareAsADelta) {
    BsdfArena arena;
    const Bsdf& plastic = arena.make<CoatedBsdf>(arena.make<LambertianBsdf>(RGB(0.5f)), 1.5f, 0.0f);
    EXPECT_EQ(plastic.flags(), unsigned(kBsdfReflection | kBsdfDiffuse | kBsdfSpecular));
    Vec3f wo = test::incidentDirection(60.0f);
    float F = fresnelDielectric(wo.z, 1.5f);
    auto s = plastic.sample(wo, 0.5f * F, Vec2f{0.3f, 0.3f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->specular);
    EXPECT_FLOAT_EQ(s->pdf, F);
    EXPECT_NEAR(s->f.x * s->wi.z / s->pdf, 1.0f, 1e-6f) << "the coat's mirror, chosen with its own reflectance";
}

// The flux albedo per channel at wo over `samples` samples: f |cos| / pdf, times eta^2 when
// refracted (render/bsdf.h), failures counting 0.
std::array<test::MeanEstimate, 3> fluxAlbedo(const Bsdf& bsdf, const Vec3f& wo, int samples, std::uint64_t seed) {
    std::array<test::MeanEstimate, 3> e;
    for (int n = 0; n < samples; ++n) {
        SampleStream rng(seed, 0, static_cast<std::uint64_t>(n));
        float uLobe = rng.next();
        auto s = bsdf.sample(wo, uLobe, rng.next2D());
        RGB w = s ? s->f * (std::abs(s->wi.z) * s->eta * s->eta / s->pdf) : RGB(0.0f);
        for (int c = 0; c < 3; ++c) e[c].add(w[c]);
    }
    return e;
}

// T(t) = integral of (1 - t F(cos i)) cos i / pi over the hemisphere: the share of a white
// Lambertian base's light that leaves through a smooth layer of reflectance t F in one pass.
test::SphereIntegral leavingShare(float t, float eta) {
    return test::integrateOverSphere([&](const Vec3f& w) {
        return w.z > 0.0f ? (1.0 - t * fresnelDielectric(w.z, eta)) * w.z / 3.14159265358979323846 : 0.0;
    });
}

TEST(CoatedBsdf, ATintedSpecularLayerTakesFromTheBaseOnlyWhatItReflects) {
    // A plastic's specular lobe scaled by specular x specular_color = t (per channel) over a white
    // Lambertian: albedo_c(wo) = t_c F(cos o) + (1 - t_c F(cos o)) T(t_c), the closed form of the
    // layer with the base losing t_c F in each direction; t = 0 (blue) leaves the white base's 1.
    const RGB tint(1.0f, 0.5f, 0.0f);
    BsdfArena arena;
    const Bsdf& plastic =
        arena.make<CoatedBsdf>(arena.make<LambertianBsdf>(RGB(1.0f)), RGB(1.5f), GgxDistribution(0.0f), tint);
    for (float theta : {0.0f, 70.0f}) {
        const Vec3f wo = test::incidentDirection(theta);
        const double F = fresnelDielectric(wo.z, 1.5f);
        auto albedo = fluxAlbedo(plastic, wo, kSamples, 44);
        for (int c = 0; c < 3; ++c) {
            test::SphereIntegral T = leavingShare(tint[c], 1.5f);
            double expected = tint[c] * F + (1.0 - tint[c] * F) * T.value;
            EXPECT_NEAR(albedo[c].mean(), expected, kZ * albedo[c].standardError() + T.error + 1e-6)
                << "theta " << theta << ", channel " << c;
        }
    }
}

TEST(CoatedBsdf, TheCoatColourFiltersWhatPassesThroughOnce) {
    // A smooth clear coat with filter (coat_color) g over a white Lambertian: the coat's own
    // reflection is untinted and the base's light is multiplied by g once (in and out):
    // albedo_c(wo) = F(cos o) + (1 - F(cos o)) g_c T(1).
    const RGB filter(0.25f, 0.5f, 1.0f);
    BsdfArena arena;
    const Bsdf& coated = arena.make<CoatedBsdf>(arena.make<LambertianBsdf>(RGB(1.0f)), RGB(1.5f), GgxDistribution(0.0f),
                                                RGB(1.0f), filter);
    test::SphereIntegral T = leavingShare(1.0f, 1.5f);
    for (float theta : {0.0f, 70.0f}) {
        const Vec3f wo = test::incidentDirection(theta);
        const double F = fresnelDielectric(wo.z, 1.5f);
        auto albedo = fluxAlbedo(coated, wo, kSamples, 45);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(albedo[c].mean(), F + (1.0 - F) * filter[c] * T.value, kZ * albedo[c].standardError() + T.error)
                << "theta " << theta << ", channel " << c;
    }
}

TEST(CoatedBsdf, ACoatOverGlassIsOneSidedAndConservesFlux) {
    // Coated glass: the coat lies on the outside only. Inside, light reflected back inside
    // crosses no coat (f is the glass's), light refracted out crosses it once; from outside the
    // flux albedo (eta^2 on refracted samples) stays <= 1.
    BsdfArena arena;
    const Bsdf& glass = arena.make<GgxDielectricBsdf>(1.5f, GgxDistribution(0.2f));
    for (float coatAlpha : {0.0f, 0.2f}) {
        const Bsdf& coated = arena.make<CoatedBsdf>(glass, 1.5f, coatAlpha);
        EXPECT_NE(coated.flags() & kBsdfTransmission, 0u);
        const Vec3f inside = test::incidentDirection(160.0f), insideOut = test::incidentDirection(150.0f, -1.0f, 0.0f);
        EXPECT_EQ(coated.f(inside, insideOut), glass.f(inside, insideOut)) << "inside: no coat";
        const Vec3f outside = test::incidentDirection(20.0f, -1.0f, 0.0f);
        // What the coat keeps from crossing light: its albedo (its Fresnel reflectance when smooth).
        const float E =
            DielectricReflectionBsdf(DielectricFresnel(RGB(1.5f)), GgxDistribution(coatAlpha)).reflectance(outside).x;
        const RGB expected = glass.f(inside, outside) * (1.0f - E);
        ASSERT_GT(expected.x, 0.0f) << "a refraction the rough glass makes";
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(coated.f(inside, outside)[c], expected[c], 1e-6f * expected[c]);
        for (float theta : {0.0f, 60.0f, 150.0f}) {
            auto albedo = fluxAlbedo(coated, test::incidentDirection(theta), kSamples, 46);
            std::printf("[ measured ] coat alpha %.1f over rough glass, theta %3.0f: flux albedo %.5f +- %.5f\n",
                        coatAlpha, theta, albedo[0].mean(), albedo[0].standardError());
            EXPECT_LE(albedo[0].mean(), 1.0 + kZ * albedo[0].standardError())
                << "coat alpha " << coatAlpha << ", theta " << theta;
        }
    }
}

}  // namespace
}  // namespace fluence::render
