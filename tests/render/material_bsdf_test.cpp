// The BSDF a MaterialParams builds: which layers it has, and that the blend stays a valid BSDF.
#include "render/material_bsdf.h"

#include <gtest/gtest.h>

#include "render/bsdfs/mix.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

constexpr int kSamples = 200'000;
// 6 statistical checks, each at z standard errors, for a family-wide false-failure rate of 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(6));

MaterialParams lambertOnly() { return lambertianParams(RGB(0.18f)); }

// The BSDF of `m` with `albedo` as its diffuse colour.
const Bsdf& bsdfOf(MaterialParams m, const RGB& albedo, BsdfArena& arena) {
    m.diffuse = albedo;
    return materialBsdf(m, arena);
}

TEST(MaterialBsdf, LayersFollowTheMaterial) {
    BsdfArena arena;
    const unsigned diffuse = kBsdfReflection | kBsdfDiffuse;
    EXPECT_EQ(bsdfOf(lambertOnly(), RGB(0.5f), arena).flags(), diffuse) << "every lobe off: exactly Lambertian";
    MaterialParams blackSpecular;
    blackSpecular.specularWorkflow = true;
    blackSpecular.specularColor = RGB(0.0f);
    arena.reset();
    EXPECT_EQ(bsdfOf(blackSpecular, RGB(0.5f), arena).flags(), diffuse);
    MaterialParams plastic;  // UsdPreviewSurface's metallic workflow: a dielectric lobe over diffuse
    arena.reset();
    EXPECT_NE(bsdfOf(plastic, RGB(0.5f), arena).flags() & kBsdfGlossy, 0u);
    MaterialParams mirror = lambertOnly();
    mirror.metallic = 1.0f;
    mirror.roughness = 0.0f;
    arena.reset();
    EXPECT_EQ(bsdfOf(mirror, RGB(0.9f), arena).flags() & kBsdfDiffuse, 0u) << "a pure metal has no diffuse lobe";
}

TEST(MaterialBsdf, AHalfMetalReflectsTheMeanOfItsParts) {
    BsdfArena arena;
    MaterialParams half = lambertOnly();
    half.metallic = 0.5f;
    half.roughness = 0.4f;
    MaterialParams metal = half;
    metal.metallic = 1.0f;
    const Bsdf& mixed = bsdfOf(half, RGB(0.8f), arena);
    const Bsdf& pure = bsdfOf(metal, RGB(0.8f), arena);
    const Bsdf& matte = bsdfOf(lambertOnly(), RGB(0.8f), arena);
    for (float theta : {10.0f, 60.0f}) {
        Vec3f wo = test::incidentDirection(theta);
        test::MeanEstimate m = test::albedoEstimate(mixed, wo, kSamples, 3);
        test::MeanEstimate a = test::albedoEstimate(pure, wo, kSamples, 4), b = test::albedoEstimate(matte, wo, kSamples, 5);
        double expected = 0.5 * (a.mean() + b.mean());
        double se = std::sqrt(m.standardError() * m.standardError() +
                              0.25 * (a.standardError() * a.standardError() + b.standardError() * b.standardError()));
        EXPECT_NEAR(m.mean(), expected, kZ * se) << "theta " << theta;
        EXPECT_LE(m.mean(), 0.8 + kZ * m.standardError()) << "theta " << theta;
    }
}

TEST(MaterialBsdf, MixedSamplesMatchTheBlendsFAndPdf) {
    BsdfArena arena;
    MaterialParams coated = lambertOnly();
    coated.metallic = 0.3f;
    coated.roughness = 0.5f;
    coated.coat = 0.6f;
    coated.coatRoughness = 0.3f;
    const Bsdf& bsdf = bsdfOf(coated, RGB(0.7f, 0.5f, 0.3f), arena);
    Vec3f wo = test::incidentDirection(35.0f);
    int checked = 0;
    for (int n = 0; n < 2000; ++n) {
        SampleStream rng(9, 0, static_cast<std::uint64_t>(n));
        float uLobe = rng.next();
        auto s = bsdf.sample(wo, uLobe, rng.next2D());
        if (!s || s->specular) continue;
        ++checked;
        RGB f = bsdf.f(wo, s->wi);
        EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-4f * s->pdf);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c], f[c], 1e-4f * f[c] + 1e-7f);
    }
    EXPECT_GT(checked, 1500);
}

TEST(MaterialBsdf, MixSamplesMatchItsPdf) {
    BsdfArena arena;
    MaterialParams half = lambertOnly();
    half.metallic = 0.5f;
    half.roughness = 0.5f;
    const Bsdf& bsdf = bsdfOf(half, RGB(0.6f), arena);
    Vec3f wo = test::incidentDirection(40.0f);
    auto r = test::chi2SphereTest(
        [&](SampleStream& rng) -> std::optional<Vec3f> {
            float uLobe = rng.next();
            auto s = bsdf.sample(wo, uLobe, rng.next2D());
            return s && !s->specular ? std::optional(s->wi) : std::nullopt;
        },
        [&](const Vec3f& wi) { return double(bsdf.pdf(wo, wi)); }, test::Chi2Options{400'000});
    EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
}

}  // namespace
}  // namespace fluence::render
