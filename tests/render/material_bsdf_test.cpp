// The BSDF a MaterialParams builds: which layers it has, that each parameter reaches the model
// it drives (the same f and pdf as the layers built by hand), and that the blend of every lobe
// at once stays a valid BSDF.
#include "render/material_bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "render/bsdfs/coated.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/ggx_dielectric.h"
#include "render/bsdfs/ggx_dielectric_multiple_scattering.h"
#include "render/bsdfs/ggx_multiple_scattering.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/layered.h"
#include "render/bsdfs/mix.h"
#include "render/bsdfs/sheen.h"
#include "render/bsdfs/thin_dielectric_multiple_scattering.h"
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

// SubsurfaceShare::Diffuse turns a solid's subsurface share into diffuse reflection of the
// subsurface colour and leaves the other lobes alone: half metal (F0 = the base colour, 0.2) and
// half subsurface of colour (0.9, 0.6, 0.3) reflects half the metal's f plus half that colour / pi.
// A thin wall transmits as it did.
TEST(MaterialBsdf, ASubsurfaceShareMadeDiffuseReflectsItsColourAndLeavesTheOtherLobes) {
    BsdfArena arena;
    MaterialParams m = lambertianParams(RGB(0.2f));
    m.subsurface = 1.0f;
    m.subsurfaceColor = RGB(0.9f, 0.6f, 0.3f);
    m.metallic = 0.5f;
    m.roughness = 0.4f;
    MaterialParams metal = m;
    metal.metallic = 1.0f;
    const Bsdf& share = materialBsdf(m, arena, SubsurfaceShare::Diffuse);
    const Bsdf& pure = materialBsdf(metal, arena);
    const Vec3f wo = test::incidentDirection(30.0f);
    for (float theta : {5.0f, 40.0f, 75.0f}) {
        const Vec3f wi = test::incidentDirection(theta);
        const RGB expected = pure.f(wo, wi) * 0.5f + m.subsurfaceColor * (0.5f * kInvPi);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(share.f(wo, wi)[c], expected[c], 1e-5f * expected[c]) << "theta " << theta << ", channel " << c;
        EXPECT_TRUE(isBlack(share.f(wo, -wi))) << "a solid's share made diffuse transmits nothing";
    }
    m.metallic = 0.0f;
    m.thinWalled = true;
    const Bsdf& wall = materialBsdf(m, arena, SubsurfaceShare::Diffuse);
    const Bsdf& walked = materialBsdf(m, arena);
    const Vec3f through = -test::incidentDirection(20.0f);
    EXPECT_EQ(wall.f(wo, through), walked.f(wo, through)) << "a thin wall transmits as it did";
    EXPECT_FALSE(isBlack(wall.f(wo, through)));
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
        test::MeanEstimate a = test::albedoEstimate(pure, wo, kSamples, 4),
                           b = test::albedoEstimate(matte, wo, kSamples, 5);
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

TEST(MaterialBsdf, TransmissionSheenAndThinWallsAddTheirLobes) {
    BsdfArena arena;
    MaterialParams glass;
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    EXPECT_EQ(bsdfOf(glass, RGB(0.5f), arena).flags(), unsigned(kBsdfReflection | kBsdfTransmission | kBsdfSpecular))
        << "transmission 1 replaces the diffuse base";
    MaterialParams sheet = glass;
    sheet.thinWalled = true;
    sheet.transmission = 0.5f;
    arena.reset();
    const unsigned sheetFlags = bsdfOf(sheet, RGB(0.5f), arena).flags();
    EXPECT_NE(sheetFlags & kBsdfTransmission, 0u);
    EXPECT_NE(sheetFlags & kBsdfDiffuse, 0u) << "half the weight stays diffuse";
    MaterialParams cloth = lambertOnly();
    cloth.sheen = 1.0f;
    arena.reset();
    EXPECT_EQ(bsdfOf(cloth, RGB(0.5f), arena).flags(), unsigned(kBsdfReflection | kBsdfDiffuse | kBsdfGlossy));
}

// Each lobe alone over the plain diffuse base is laid over it: materialBsdf returns the bare base
// only when every one is off (its shortcut for plain walls, render/material_bsdf.cpp).
TEST(MaterialBsdf, EachLobeAloneOverThePlainBaseIsLaid) {
    const auto with = [](void (*set)(MaterialParams&)) {
        MaterialParams m = lambertOnly();
        set(m);
        return m;
    };
    const std::pair<const char*, MaterialParams> lobes[] = {
        {"subsurface", with([](MaterialParams& m) { m.subsurface = 0.5f; })},
        {"sheen", with([](MaterialParams& m) { m.sheen = 0.5f; })},
        {"specular", with([](MaterialParams& m) { m.specular = 0.5f; })},
        {"transmission", with([](MaterialParams& m) { m.transmission = 0.5f; })},
        {"metallic", with([](MaterialParams& m) { m.metallic = 0.5f; })},
        {"coat", with([](MaterialParams& m) { m.coat = 0.5f; })},
    };
    for (const auto& [name, m] : lobes) {
        BsdfArena arena;
        EXPECT_NE(materialBsdf(m, arena).flags(), unsigned(kBsdfReflection | kBsdfDiffuse)) << name;
    }
}

// Direction pairs on both sides, reflected and transmitted, off every axis.
std::vector<std::pair<Vec3f, Vec3f>> directionPairs() {
    std::vector<std::pair<Vec3f, Vec3f>> pairs;
    for (float thetaO : {10.0f, 55.0f, 80.0f, 140.0f})
        for (float thetaI : {20.0f, 50.0f, 120.0f, 170.0f})
            pairs.emplace_back(test::incidentDirection(thetaO, 0.6f, 0.8f),
                               test::incidentDirection(thetaI, -0.8f, 0.6f));
    return pairs;
}

// The material's BSDF against the same layers built by hand: equal f and pdf everywhere.
void expectSameBsdf(const Bsdf& material, const Bsdf& byHand) {
    EXPECT_EQ(material.flags(), byHand.flags());
    for (const auto& [wo, wi] : directionPairs()) {
        RGB a = material.f(wo, wi), b = byHand.f(wo, wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6f * b[c]) << "wo.z " << wo.z << ", wi.z " << wi.z;
        EXPECT_NEAR(material.pdf(wo, wi), byHand.pdf(wo, wi), 1e-6f * byHand.pdf(wo, wi));
    }
}

TEST(MaterialBsdf, EachParameterDrivesItsLayer) {
    const RGB albedo(0.6f, 0.4f, 0.3f);
    const GgxDistribution ggx = GgxDistribution::fromRoughness(0.4f, 0.5f);
    BsdfArena a, b;
    // Specular weight x colour tints the dielectric lobe (and the base keeps what it does not
    // reflect); anisotropy stretches it.
    MaterialParams plastic = lambertOnly();
    plastic.specular = 0.7f;
    plastic.specularColor = RGB(1.0f, 0.5f, 0.2f);
    plastic.roughness = 0.4f;
    plastic.anisotropy = 0.5f;
    // Over the diffuse base, every layer conserves energy (DiffuseBase).
    expectSameBsdf(bsdfOf(plastic, albedo, a), b.make<CoatedBsdf>(b.make<LambertianBsdf>(albedo), RGB(1.5f), ggx,
                                                                  RGB(0.7f, 0.35f, 0.14f), RGB(1.0f), DiffuseBase{}));
    // The specular workflow: specularColor is F0, one index per channel.
    MaterialParams workflow = plastic;
    workflow.specularWorkflow = true;
    workflow.specularColor = RGB(0.04f, 0.1f, 0.5f);
    a.reset(), b.reset();
    const RGB eta(etaFromF0(0.04f), etaFromF0(0.1f), etaFromF0(0.5f));
    expectSameBsdf(bsdfOf(workflow, albedo, a),
                   b.make<CoatedBsdf>(b.make<LambertianBsdf>(albedo), eta, ggx, RGB(1.0f), RGB(1.0f), DiffuseBase{}));
    EXPECT_NEAR(fresnelDielectric(1.0f, eta.z), 0.5f, 1e-6f);
    // Transmission replaces the (tinted, plastic) base by weight; its colour is split over the
    // two crossings of a solid, which keeps its multiple scattering; a thin wall filters once, and
    // keeps its multiple scattering too.
    MaterialParams glass = plastic;
    glass.transmission = 0.6f;
    glass.transmissionColor = RGB(0.81f, 0.49f, 0.25f);
    a.reset(), b.reset();
    const Bsdf& opaque = b.make<CoatedBsdf>(b.make<LambertianBsdf>(albedo), RGB(1.5f), ggx, RGB(0.7f, 0.35f, 0.14f),
                                            RGB(1.0f), DiffuseBase{});
    const DielectricTints solidTints{RGB(0.7f, 0.35f, 0.14f), RGB(0.9f, 0.7f, 0.5f)};
    expectSameBsdf(bsdfOf(glass, albedo, a),
                   b.make<MixBsdf>(opaque, b.make<CompensatedGgxDielectricBsdf>(1.5f, ggx, solidTints), 0.6f));
    glass.thinWalled = true;
    a.reset();
    const DielectricTints sheetTints{RGB(0.7f, 0.35f, 0.14f), glass.transmissionColor};
    expectSameBsdf(bsdfOf(glass, albedo, a),
                   b.make<MixBsdf>(opaque, b.make<CompensatedThinDielectricBsdf>(1.5f, ggx, sheetTints), 0.6f));
    // Sheen lies on the diffuse base, beneath the specular lobe; metal (with its multiple
    // scattering) by weight; the coat on top, its colour filtering what passes through it, over a
    // base that is no longer diffuse alone.
    MaterialParams all = plastic;
    all.sheen = 0.5f;
    all.sheenColor = RGB(1.0f, 0.8f, 0.6f);
    all.sheenRoughness = 0.4f;
    all.metallic = 0.25f;
    all.coat = 0.8f;
    all.coatColor = RGB(0.9f, 0.8f, 0.7f);
    all.coatRoughness = 0.2f;
    a.reset(), b.reset();
    const Bsdf& sheened = b.make<LayeredBsdf<CharlieSheenBsdf>>(
        CharlieSheenBsdf(RGB(0.5f, 0.4f, 0.3f), 0.4f), b.make<LambertianBsdf>(albedo), RGB(1.0f), DiffuseBase{});
    const Bsdf& specular =
        b.make<CoatedBsdf>(sheened, RGB(1.5f), ggx, RGB(0.7f, 0.35f, 0.14f), RGB(1.0f), DiffuseBase{});
    const Bsdf& metal = b.make<MixBsdf>(specular, energyCompensatedConductor(albedo, ggx, b), 0.25f);
    const Bsdf& coated = b.make<CoatedBsdf>(metal, RGB(1.5f), GgxDistribution(0.04f), RGB(1.0f), all.coatColor);
    // Over that glossy base the coat also returns what its underside sends back down
    // (render/bsdfs/coat_return.h): the material is the stack built by hand plus a lobe that is
    // positive on either side (the stack reflects only, two-sided), reciprocal, and nothing
    // between the sides.
    const Bsdf& material = bsdfOf(all, albedo, a);
    const Bsdf& byHand = b.make<MixBsdf>(metal, coated, 0.8f);
    for (const auto& [wo, wi] : directionPairs()) {
        const RGB returned = material.f(wo, wi) - byHand.f(wo, wi), back = material.f(wi, wo) - byHand.f(wi, wo);
        for (int c = 0; c < 3; ++c) {
            if (wo.z * wi.z > 0.0f)
                EXPECT_GT(returned[c], 0.0f) << "wo.z " << wo.z << ", wi.z " << wi.z;
            else
                EXPECT_NEAR(returned[c], 0.0f, 1e-6f * byHand.f(wo, wi)[c] + 1e-9f) << "wo.z " << wo.z;
            EXPECT_NEAR(returned[c], back[c], 1e-4f * (std::abs(returned[c]) + 1e-6f)) << "reciprocal";
        }
    }
}

// A rough metal's multiple-scattering lobe is light its microfacets reflect: glossy, never
// diffuse, so a light path expression counts it as RG (render/bsdfs/ggx_multiple_scattering.h).
TEST(MaterialBsdf, CompensatedMetalsMultipleScatteringIsGlossy) {
    BsdfArena arena;
    const Bsdf& metal = energyCompensatedConductor(RGB(0.9f, 0.6f, 0.3f), GgxDistribution(0.6f), arena);
    EXPECT_FALSE(metal.flags() & kBsdfDiffuse);
    EXPECT_TRUE(metal.flags() & kBsdfGlossy);
    const Vec3f wo = normalize(Vec3f(0.3f, 0.1f, 0.9f)), wi = normalize(Vec3f(-0.8f, 0.2f, 0.3f));
    const LobeSplit split = metal.fByKind(wo, wi);
    EXPECT_TRUE(isBlack(split.diffuse));
    const RGB f = metal.f(wo, wi);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(split.glossy[c], f[c]) << "channel " << c;
    const GgxConductorBsdf single(RGB(0.9f, 0.6f, 0.3f), GgxDistribution(0.6f));
    EXPECT_GT(f.x, single.f(wo, wi).x) << "the multiple-scattering lobe adds to the single-scattering one";
}

// The light a clear coat returns to the base (render/bsdfs/coat_return.h, LABELS) is labelled by
// the base's lobe it comes from: over a metal, whose lobes are all glossy, none of it is diffuse
// (a light path expression's C<RD> must not catch a coated metal); over a plastic part of it comes
// from the diffuse base and part from the specular lobe: the returned light (the material less
// the same layers built by hand, which return nothing) has a diffuse and a glossy part. Either
// way the parts sum to f.
TEST(MaterialBsdf, CoatReturnedLightIsLabelledByTheBaseLobeItComesFrom) {
    MaterialParams coatedMetal = lambertOnly();
    coatedMetal.metallic = 1.0f;
    coatedMetal.roughness = 0.4f;
    coatedMetal.coat = 1.0f;
    coatedMetal.coatRoughness = 0.3f;
    MaterialParams coatedPlastic = lambertOnly();
    coatedPlastic.specular = 1.0f;
    coatedPlastic.roughness = 0.4f;
    coatedPlastic.coat = 1.0f;
    coatedPlastic.coatRoughness = 0.3f;
    BsdfArena metalArena, plasticArena;
    const Bsdf& metal = bsdfOf(coatedMetal, RGB(0.9f, 0.6f, 0.3f), metalArena);
    EXPECT_EQ(metal.flags() & kBsdfDiffuse, 0u);
    const Bsdf& plastic = bsdfOf(coatedPlastic, RGB(0.8f), plasticArena);
    const Bsdf& specularLayer =
        plasticArena.make<CoatedBsdf>(plasticArena.make<LambertianBsdf>(RGB(0.8f)), RGB(1.5f),
                                      GgxDistribution::fromRoughness(0.4f, 0.0f), RGB(1.0f), RGB(1.0f), DiffuseBase{});
    const Bsdf& plasticByHand =
        plasticArena.make<CoatedBsdf>(specularLayer, RGB(1.5f), GgxDistribution(0.09f), RGB(1.0f), RGB(1.0f));
    RGB returnedDiffuse(0.0f), returnedGlossy(0.0f);
    for (const auto& [wo, wi] : directionPairs()) {
        const LobeSplit metalSplit = metal.fByKind(wo, wi), plasticSplit = plastic.fByKind(wo, wi);
        const LobeSplit byHandSplit = plasticByHand.fByKind(wo, wi);
        const RGB metalF = metal.f(wo, wi), plasticF = plastic.f(wo, wi);
        EXPECT_TRUE(isBlack(metalSplit.diffuse)) << "wo.z " << wo.z << ", wi.z " << wi.z;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(metalSplit.glossy[c], metalF[c], 1e-6f * metalF[c]);
            EXPECT_NEAR(plasticSplit.diffuse[c] + plasticSplit.glossy[c], plasticF[c], 1e-6f * plasticF[c]);
        }
        if (wo.z * wi.z <= 0.0f) continue;
        EXPECT_GT(plastic.f(wo, wi).x, plasticByHand.f(wo, wi).x) << "the coat returns light";
        returnedDiffuse += plasticSplit.diffuse - byHandSplit.diffuse;
        returnedGlossy += plasticSplit.glossy - byHandSplit.glossy;
    }
    EXPECT_GT(returnedDiffuse.x, 0.0f);
    EXPECT_GT(returnedGlossy.x, 0.0f);
}

// Glass (thin or solid), metal, sheen, a tinted anisotropic specular lobe and a coloured coat at
// once: it fits in the arena, its samples follow its pdf (chi-square, from outside for the sheet
// and from inside for the solid) and agree with f and pdf.
void expectEveryLobeAtOnceIsValid(bool thinWalled, float thetaO) {
    MaterialParams m = lambertOnly();
    m.specular = 0.8f;
    m.specularColor = RGB(1.0f, 0.7f, 0.5f);
    m.roughness = 0.45f;
    m.anisotropy = 0.6f;
    m.transmission = 0.4f;
    m.thinWalled = thinWalled;
    m.metallic = 0.3f;
    m.sheen = 0.6f;
    m.coat = 0.5f;
    m.coatColor = RGB(0.9f, 0.8f, 0.6f);
    m.coatRoughness = 0.25f;
    BsdfArena arena;
    const Bsdf& bsdf = bsdfOf(m, RGB(0.7f, 0.5f, 0.3f), arena);
    const Vec3f wo = test::incidentDirection(thetaO, 0.6f, 0.8f);
    auto r = test::chi2SphereTest(
        [&](SampleStream& rng) -> std::optional<Vec3f> {
            float uLobe = rng.next();
            auto s = bsdf.sample(wo, uLobe, rng.next2D());
            return s && !s->specular ? std::optional(s->wi) : std::nullopt;
        },
        [&](const Vec3f& wi) { return double(bsdf.pdf(wo, wi)); }, test::Chi2Options{200'000, 21, 41});
    EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    int checked = 0;
    for (int n = 0; n < 500; ++n) {
        SampleStream rng(10, 0, static_cast<std::uint64_t>(n));
        float uLobe = rng.next();
        auto s = bsdf.sample(wo, uLobe, rng.next2D());
        if (!s || s->specular) continue;
        ++checked;
        EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-4f * s->pdf);
        RGB f = bsdf.f(wo, s->wi);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c], f[c], 1e-4f * f[c] + 1e-7f);
    }
    EXPECT_GT(checked, 300);
}

TEST(MaterialBsdf, EveryLobeAtOnceIsAValidBsdfThroughASolid) { expectEveryLobeAtOnceIsValid(false, 135.0f); }
TEST(MaterialBsdf, EveryLobeAtOnceIsAValidBsdfThroughAThinWall) { expectEveryLobeAtOnceIsValid(true, 35.0f); }

}  // namespace
}  // namespace fluence::render
