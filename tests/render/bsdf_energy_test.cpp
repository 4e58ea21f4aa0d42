// Energy preservation of the materials' BSDFs (render/bsdfs/ggx_albedo.h and
// ggx_anisotropic_albedo.h, the energy-preserving layering of render/bsdfs/layered.h, the
// multiple-scattering metal of render/bsdfs/ggx_multiple_scattering.h, the coat's returned light
// of render/bsdfs/coat_return.h, the thin sheet's multiple scattering of
// render/bsdfs/thin_dielectric_multiple_scattering.h): the albedo tables against independent Monte Carlo estimates,
// and the white furnace grid of every configuration a UsdPreviewSurface or Standard Surface
// material with white inputs and no absorption builds, at the roughnesses 0, 0.1, 0.3, 0.6 and 1
// and incident angles from 0 to 85 degrees: each must reflect (and transmit) all the light it
// receives to within 1%, plus the estimate's own z standard errors (Sidak-corrected over this
// file's checks for a family-wide false-failure rate of 1%).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "render/bsdf_arena.h"
#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/dielectric_reflection.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/ggx_anisotropic_albedo.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/local_geometry.h"
#include "render/bsdfs/sheen_redistribution.h"
#include "render/bsdfs/thin_dielectric.h"
#include "render/bsdfs/thin_dielectric_albedo.h"
#include "render/material_bsdf.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

constexpr int kSamples = 40'000;
const std::vector<float> kRoughnesses = {0.0f, 0.1f, 0.3f, 0.6f, 1.0f};
const std::vector<float> kAngles = {0.0f, 30.0f, 60.0f, 80.0f, 85.0f};
// (roughness, anisotropy) pairs of the anisotropic table's check.
const std::vector<std::pair<float, float>> kAnisotropicWidths = {{0.3f, 1.0f}, {0.6f, 0.8f}, {1.0f, 0.5f}};
// Table checks: 3 f0 x 4 widths x 5 angles, 3 anisotropic widths x 5 angles x 5 azimuths, the
// thin sheet's 2 indices x 4 widths x 5 angles; furnace checks: 24 configurations x 5
// roughnesses x 5 angles, the 5 thin-walled ones seen from behind, and the subsurface boundary's
// inside under 4 stacks of layers; the share a coat's returned light sends through a sheet.
constexpr int kConfigurations = 24, kThinWalled = 5, kInsideStacks = 4;
constexpr int kChecks = 60 + 75 + 40 + (kConfigurations + kThinWalled + kInsideStacks) * 25 + 1;
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(kChecks));
// The stated energy target: a furnace reads 1 within 1%.
constexpr double kEnergyTolerance = 0.01;
// What the table may be off the true albedo: its quadrature and linear interpolation.
constexpr double kTableTolerance = 0.004;

TEST(BsdfEnergy, AlbedoTableMatchesMonteCarlo) {
    // The cost of first use: the two slices around F0 = 0.04 (index 1.5).
    const auto start = std::chrono::steady_clock::now();
    const float first = ggxReflectionAlbedo(0.5f, 0.1f, 0.04f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ measured ] GGX albedo slices for F0 0.04 built in %.3f s (E(0.5, 0.1, 0.04) = %.5f)\n", seconds,
                first);
    std::uint64_t seed = 1;
    for (float f0 : {0.04f, 0.2f, 1.0f})
        for (float alpha : {0.01f, 0.09f, 0.36f, 1.0f})
            for (float angle : kAngles) {
                const GgxDistribution ggx(alpha);
                const Vec3f wo = test::incidentDirection(angle);
                const RGB eta(etaFromF0(f0));
                const GgxConductorBsdf bare(RGB(1.0f), ggx);  // Schlick with F0 = 1: F = 1
                const DielectricReflectionBsdf dielectric(DielectricFresnel(eta), ggx);
                const Bsdf& lobe = f0 >= 1.0f ? static_cast<const Bsdf&>(bare) : dielectric;
                const test::MeanEstimate e = test::albedoEstimate(lobe, wo, kSamples, seed++);
                const float table = ggxReflectionAlbedo(wo.z, alpha, f0);
                EXPECT_NEAR(e.mean(), table, kTableTolerance + kZ * e.standardError())
                    << "f0 " << f0 << ", alpha " << alpha << ", angle " << angle;
            }
}

TEST(BsdfEnergy, AnisotropicAlbedoTableMatchesMonteCarlo) {
    // The bare albedo of a stretched GGX depends on the azimuth of wo (render/bsdfs/
    // ggx_anisotropic_albedo.h): the table against Monte Carlo at five azimuths, from the wide
    // axis to the narrow one, for Standard Surface's anisotropies 0.5, 0.8 and 1.
    const auto start = std::chrono::steady_clock::now();
    const float first = ggxAnisotropicAlbedo(Vec3f(0.6f, 0.0f, 0.8f), 0.5f, 0.1f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ measured ] anisotropic GGX albedo slices around (0.5, 0.1) built in %.3f s (E = %.5f)\n", seconds,
                first);
    std::uint64_t seed = 3000;
    for (const auto& [roughness, anisotropy] : kAnisotropicWidths) {
        const GgxDistribution ggx = GgxDistribution::fromRoughness(roughness, anisotropy);
        const GgxConductorBsdf bare(RGB(1.0f), ggx);
        for (float angle : kAngles)
            for (float phi : {0.0f, 20.0f, 45.0f, 70.0f, 90.0f}) {
                const float p = phi * kPi / 180.0f;
                const Vec3f wo = test::incidentDirection(angle, std::cos(p), std::sin(p));
                const test::MeanEstimate e = test::albedoEstimate(bare, wo, kSamples, seed++);
                EXPECT_NEAR(e.mean(), ggxBareAlbedo(wo, ggx), kTableTolerance + kZ * e.standardError())
                    << "roughness " << roughness << ", anisotropy " << anisotropy << ", angle " << angle << ", phi "
                    << phi;
            }
    }
}

struct Configuration {
    std::string name;
    MaterialParams material;
};

MaterialParams white() { return lambertianParams(RGB(1.0f)); }

MaterialParams withCoat(MaterialParams m, float coatRoughness) {
    m.coat = 1.0f;
    m.coatRoughness = coatRoughness;
    return m;
}

TEST(BsdfEnergy, ThinSheetAlbedoTableMatchesMonteCarlo) {
    // The single-scattering sheet's albedo, reflected and transmitted (render/bsdfs/
    // thin_dielectric_albedo.h), which its multiple-scattering lobe returns the complement of.
    const auto start = std::chrono::steady_clock::now();
    const float first = thinSheetAlbedo(0.5f, 0.1f, 1.5f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ measured ] thin sheet albedo slices for index 1.5 built in %.3f s (E(0.5, 0.1, 1.5) = %.5f)\n",
                seconds, first);
    std::uint64_t seed = 4000;
    for (float eta : {1.33f, 1.5f})
        for (float alpha : {0.01f, 0.09f, 0.36f, 1.0f})
            for (float angle : kAngles) {
                const ThinDielectricBsdf sheet(eta, GgxDistribution(alpha));
                const Vec3f wo = test::incidentDirection(angle);
                const test::MeanEstimate e = test::fluxAlbedoEstimate(sheet, wo, kSamples, seed++);
                EXPECT_NEAR(e.mean(), thinSheetAlbedo(wo.z, alpha, eta), kTableTolerance + kZ * e.standardError())
                    << "eta " << eta << ", alpha " << alpha << ", angle " << angle;
            }
}

TEST(BsdfEnergy, SheenSpreadSlicesAreBuiltOnFirstUse) {
    // The cost a coat over sheen pays once per sheen roughness node (render/bsdfs/
    // sheen_redistribution.h), and the spread's sum.
    const auto start = std::chrono::steady_clock::now();
    const ElevationWeights spread = sheenReflectionSpread(20, 0.45f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double sum = 0.0;
    for (float w : spread) sum += w;
    std::printf("[ measured ] sheen spread slices around roughness 0.45 built in %.3f s\n", seconds);
    EXPECT_NEAR(sum, 1.0, 1e-5);
}

// Every white, non-absorbing configuration of UsdPreviewSurface and Standard Surface at
// perceptual roughness r: r is the specular (or diffuse, sheen, coat) roughness of the lobe the
// configuration is about; a coat over a glossy base is taken both ways (coat r over a base of
// 0.3, and coat 0.1 over a base of r).
std::vector<Configuration> configurations(float r) {
    std::vector<Configuration> all;
    MaterialParams diffuse = white();
    all.push_back({"diffuse", diffuse});
    MaterialParams metal = white();
    metal.metallic = 1.0f;
    metal.roughness = r;
    all.push_back({"metal", metal});
    for (float anisotropy : {0.5f, 1.0f}) {
        MaterialParams brushed = metal;
        brushed.anisotropy = anisotropy;
        all.push_back({"metal anisotropy " + std::to_string(anisotropy), brushed});
    }
    MaterialParams plastic = white();
    plastic.specular = 1.0f;
    plastic.roughness = r;
    for (float ior : {1.3f, 1.5f, 2.0f}) {
        MaterialParams p = plastic;
        p.ior = ior;
        all.push_back({"plastic ior " + std::to_string(ior), p});
    }
    MaterialParams workflow = white();  // UsdPreviewSurface's specular workflow, F0 0.04
    workflow.specularWorkflow = true;
    workflow.specularColor = RGB(0.04f);
    workflow.roughness = r;
    all.push_back({"specular workflow F0 0.04", workflow});
    MaterialParams glass = plastic;
    glass.transmission = 1.0f;
    all.push_back({"glass", glass});
    MaterialParams sheet = glass;
    sheet.thinWalled = true;
    all.push_back({"thin-walled glass", sheet});
    MaterialParams cloth = white();
    cloth.sheen = 1.0f;
    cloth.sheenRoughness = r;
    all.push_back({"sheen over diffuse", cloth});
    MaterialParams skin = plastic;
    skin.subsurface = 1.0f;
    all.push_back({"subsurface boundary", skin});
    MaterialParams leaf = skin;
    leaf.thinWalled = true;
    all.push_back({"thin-walled subsurface", leaf});
    MaterialParams plastic03 = plastic, metal03 = metal, sheet03 = sheet;
    plastic03.roughness = metal03.roughness = sheet03.roughness = 0.3f;
    all.push_back({"coat over diffuse", withCoat(diffuse, r)});
    all.push_back({"coat over plastic 0.3", withCoat(plastic03, r)});
    all.push_back({"coat 0.1 over plastic", withCoat(plastic, 0.1f)});
    all.push_back({"coat over metal 0.3", withCoat(metal03, r)});
    all.push_back({"coat 0.1 over metal", withCoat(metal, 0.1f)});
    all.push_back({"coat over sheen", withCoat(cloth, r)});
    all.push_back({"coat over subsurface", withCoat(skin, r)});
    all.push_back({"coat over glass", withCoat(glass, r)});
    all.push_back({"coat over thin glass 0.3", withCoat(sheet03, r)});
    all.push_back({"coat 0.1 over thin glass", withCoat(sheet, 0.1f)});
    all.push_back({"coat over thin subsurface", withCoat(leaf, r)});
    return all;
}

// Reads the flux albedo of `c` lit from the directions `incident` gives for each angle, and
// checks that it is 1 within 1%: one line of readings per configuration.
void expectWhiteFurnaceOverAngles(const Configuration& c, float r, std::uint64_t& seed,
                                  const std::function<const Bsdf&(BsdfArena&)>& make,
                                  const std::function<Vec3f(float)>& incident) {
    BsdfArena arena;
    std::string readings;
    for (float angle : kAngles) {
        arena.reset();
        const test::MeanEstimate e = test::fluxAlbedoEstimate(make(arena), incident(angle), kSamples, seed++);
        // Float rounding lets a deterministic (smooth) estimate read 1 + 1e-7.
        const double slack = kZ * e.standardError() + 1e-5;
        EXPECT_NEAR(e.mean(), 1.0, kEnergyTolerance + slack) << c.name << ", roughness " << r << ", angle " << angle;
        char reading[16];
        std::snprintf(reading, sizeof reading, " %.4f", e.mean());
        readings += reading;
    }
    std::printf("[ measured ] %-26s roughness %.1f, 0/30/60/80/85 degrees:%s\n", c.name.c_str(), r, readings.c_str());
}

TEST(BsdfEnergy, WhiteMaterialsReflectAllTheLightAtEveryRoughness) {
    ASSERT_EQ(configurations(0.0f).size(), std::size_t(kConfigurations)) << "the family size of kZ";
    std::uint64_t seed = 1000;
    for (float r : kRoughnesses)
        for (const Configuration& c : configurations(r))
            expectWhiteFurnaceOverAngles(
                c, r, seed, [&](BsdfArena& arena) -> const Bsdf& { return materialBsdf(c.material, arena); },
                [](float angle) { return test::incidentDirection(angle); });
}

TEST(BsdfEnergy, ThinWallsReflectAllTheLightSeenFromBehind) {
    // A thin wall is seen from both sides; its layers lie on the side its normal faces (the
    // shading frame of a transmitting BSDF keeps the surface's orientation), so from behind the
    // light crosses the sheet first, and what the coat's underside sends back down must come out.
    std::uint64_t seed = 6000;
    int thinWalled = 0;
    for (float r : kRoughnesses)
        for (const Configuration& c : configurations(r)) {
            if (!c.material.thinWalled) continue;
            ++thinWalled;
            expectWhiteFurnaceOverAngles(
                {c.name + " from behind", c.material}, r, seed,
                [&](BsdfArena& arena) -> const Bsdf& { return materialBsdf(c.material, arena); },
                [](float angle) { return mirrorZ(test::incidentDirection(angle)); });
        }
    EXPECT_EQ(thinWalled, kThinWalled * int(kRoughnesses.size())) << "the family size of kZ";
}

TEST(BsdfEnergy, SubsurfaceBoundaryReturnsWhatItDoesNotLetOut) {
    // Seen from inside (a random walk reaching the surface), the boundary under its layers lets
    // out what they all let through and reflects the rest back in: under the specular lobe alone,
    // under it and a coat (both of roughness r, and a coat of 0.1 over a specular lobe of r), and
    // under a sheen, the specular lobe and a coat. Each layer must send back in only its share of
    // the light that the layers below it let through.
    std::uint64_t seed = 5000;
    for (float r : kRoughnesses) {
        MaterialParams skin = white();
        skin.subsurface = 1.0f;
        skin.specular = 1.0f;
        skin.roughness = r;
        MaterialParams velvet = withCoat(skin, 0.3f);
        velvet.sheen = 1.0f;
        velvet.sheenRoughness = r;
        const std::vector<Configuration> stacks = {{"specular", skin},
                                                   {"specular and coat", withCoat(skin, r)},
                                                   {"specular and coat 0.1", withCoat(skin, 0.1f)},
                                                   {"sheen, specular and coat 0.3", velvet}};
        ASSERT_EQ(stacks.size(), std::size_t(kInsideStacks)) << "the family size of kZ";
        for (const Configuration& c : stacks)
            expectWhiteFurnaceOverAngles(
                {"inside, " + c.name, c.material}, r, seed,
                [&](BsdfArena& arena) -> const Bsdf& { return subsurfaceExitBsdf(c.material, arena); },
                [](float angle) { return mirrorZ(test::incidentDirection(angle)); });
    }
}

TEST(BsdfEnergy, ACoatOverASmoothSheetSendsThroughItTheShareTheSeriesSays) {
    // A smooth coat over a smooth white sheet (render/bsdfs/coat_return.h, A THIN SHEET UNDER THE
    // COAT): at elevation mu the coat's underside sends loss(mu) = (1 - F) R F back down (F the
    // coat's Fresnel reflectance, R and T = 1 - R the slab's), and bouncing between sheet and
    // coat at that elevation, T / (1 - R F) of it leaves behind the sheet. Both layers smooth,
    // the stack has only delta lobes, so every non-delta sample that crosses is returned light:
    // lit by the cosine-weighted front hemisphere, their mean weight is X = 2 integral loss T /
    // (1 - R F) mu dmu. Tolerance: the estimate's z standard errors, plus what the model's 32 mu
    // nodes (piecewise-linear, render/bsdfs/albedo_table.h) make of the integral, computed here
    // against a 100,000-point midpoint rule. A cosine-weighted average of T in place of the
    // series reads 0.857 of the loss for 0.682.
    MaterialParams m = withCoat(white(), 0.0f);
    m.specular = 1.0f;
    m.roughness = 0.0f;
    m.transmission = 1.0f;
    m.thinWalled = true;
    const auto integrand = [&](double mu) {
        const double F = fresnelDielectric(float(mu), m.coatIor), R = slabReflectance(float(mu), m.ior);
        return (1.0 - F) * R * F * (1.0 - R) / (1.0 - R * F);
    };
    constexpr int kMidpoints = 100'000;
    double series = 0.0;
    for (int i = 0; i < kMidpoints; ++i) {
        const double mu = (i + 0.5) / kMidpoints;
        series += 2.0 * integrand(mu) * mu / kMidpoints;
    }
    const double nodes =
        albedo_table::cosineWeightedAverage([&](int i) { return integrand(albedo_table::cosineAt(i)); });
    BsdfArena arena;
    const Bsdf& bsdf = materialBsdf(m, arena);
    test::MeanEstimate crossed;
    for (int n = 0; n < 1'000'000; ++n) {
        SampleStream rng(7000, 0, static_cast<std::uint64_t>(n));
        const Vec3f wo = sampleCosineHemisphere(rng.next2D());
        const float uLobe = rng.next();
        const auto s = bsdf.sample(wo, uLobe, rng.next2D(), Transport::Importance);
        crossed.add(s && !s->specular && s->wi.z < 0.0f ? s->f.x * std::abs(s->wi.z) / s->pdf : 0.0);
    }
    std::printf("[ measured ] returned light crossing a smooth sheet: %.6f +- %.6f, series %.6f (32 nodes %.6f)\n",
                crossed.mean(), crossed.standardError(), series, nodes);
    EXPECT_NEAR(crossed.mean(), series, kZ * crossed.standardError() + std::abs(nodes - series));
}

}  // namespace
}  // namespace fluence::render
