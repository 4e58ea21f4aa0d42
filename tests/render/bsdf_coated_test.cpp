// The coated (layered) BSDF: its albedo against the closed form of its approximation, the energy
// bound for rough coats, and its construction rules.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

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



// This file makes 21 statistical checks; each allows z standard errors, for a family-wide
// false-failure rate of 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(21));

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
        std::printf("[ measured ] white plastic (eta 1.5, smooth coat), theta %2.0f: albedo %.5f +- %.5f, "
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
        const Bsdf& coatedGold = arena.make<CoatedBsdf>(arena.make<GgxConductorBsdf>(RGB(1.0f), 0.1f), 1.5f, alpha);
        for (float theta : {0.0f, 60.0f, 85.0f}) {
            const Vec3f wo = test::incidentDirection(theta);
            test::MeanEstimate p = test::albedoEstimate(plastic, wo, kSamples, 42);
            test::MeanEstimate g = test::albedoEstimate(coatedGold, wo, kSamples, 43);
            std::printf("[ measured ] coat alpha %.2f, theta %2.0f: white plastic %.5f +- %.5f, coated F0=1 metal "
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

TEST(CoatedBsdf, RejectsATransmittingBase) {
    BsdfArena arena;
    const Bsdf& glass = arena.make<GgxDielectricBsdf>(1.5f, 0.1f);
    EXPECT_THROW(CoatedBsdf(glass, 1.5f, 0.1f), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::render
