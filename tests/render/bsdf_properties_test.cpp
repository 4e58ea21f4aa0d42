// The properties every BSDF must have, checked for every model at several parameters and
// incident directions (render/bsdf.h states the conventions):
//   - sample() draws directions with the density pdf() (chi-square over the whole sphere);
//   - the f and pdf sample() returns are f(wo, wi) and pdf(wo, wi); delta samples only from
//     BSDFs that have a delta lobe, transmitted ones only from transmissive BSDFs;
//   - fAndPdf(wo, wi) is {f(wo, wi), pdf(wo, wi)} bit for bit (the layered models compute it
//     with one lookup of the top's reflectance at wo);
//   - pdf integrates to the fraction of samples that are not delta (so to at most 1);
//   - reciprocity (generalised with n^2 across a refracting interface);
//   - the importance transport mode is the adjoint: f(wi, wo), and the same samples as radiance's
//     with the adjoint's f;
//   - the albedo (flux) is at most 1 for the models that conserve energy, and mirrored
//     directions give the same values on a two-sided reflector (and on a thin sheet, which
//     transmits straight through as a delta but has two alike sides).
// Tolerances are statistical (Sidak-corrected over each family of tests) or, where a quantity is
// recomputed in float, a stated rounding bound.
#include <gtest/gtest.h>

#include <functional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "render/bsdf_arena.h"
#include "render/bsdfs/blinn_phong.h"
#include "render/bsdfs/coated.h"
#include "render/bsdfs/cook_torrance.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/ggx_dielectric.h"
#include "render/bsdfs/ggx_dielectric_multiple_scattering.h"
#include "render/bsdfs/ggx_multiple_scattering.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/lambertian_transmission.h"
#include "render/bsdfs/oren_nayar.h"
#include "render/bsdfs/layered.h"
#include "render/bsdfs/mix.h"
#include "render/bsdfs/modified_phong.h"
#include "render/bsdfs/phong.h"
#include "render/bsdfs/sheen.h"
#include "render/bsdfs/thin_dielectric.h"
#include "render/bsdfs/thin_dielectric_multiple_scattering.h"
#include "render/material_bsdf.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::render {
namespace {

struct BsdfCase {
    std::string name;
    std::function<const Bsdf&(BsdfArena&)> make;
    bool conservesEnergy = true;
    bool sidesAlike = false;   // transmits, yet both sides are alike (a thin sheet: straight through, eta 1)
    bool crossesIndex = true;  // its transmission refracts (eta != 1); false for diffuse transmission
};

void PrintTo(const BsdfCase& c, std::ostream* os) { *os << c.name; }

std::vector<BsdfCase> allCases() {
    const RGB colour(0.8f, 0.5f, 0.2f);
    std::vector<BsdfCase> cases = {
        {"Lambertian", [=](BsdfArena& a) -> const Bsdf& { return a.make<LambertianBsdf>(colour); }},
        {"OrenNayar_s30", [=](BsdfArena& a) -> const Bsdf& { return a.make<OrenNayarBsdf>(colour, 0.3f); }},
        {"OrenNayar_s100", [=](BsdfArena& a) -> const Bsdf& { return a.make<OrenNayarBsdf>(colour, 1.0f); }},
        {"PhongOriginal_n1", [](BsdfArena& a) -> const Bsdf& { return a.make<PhongBsdf>(RGB(0.1f), RGB(0.5f), 1.0f); },
         false},
        {"PhongOriginal_n20",
         [](BsdfArena& a) -> const Bsdf& { return a.make<PhongBsdf>(RGB(0.0f), RGB(1.0f), 20.0f); }, false},
    };
    for (float n : {1.0f, 30.0f, 300.0f}) {
        cases.push_back({"ModifiedPhong_n" + std::to_string(int(n)), [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<PhongBsdf>(modifiedPhong(RGB(0.3f), RGB(0.7f), n));
                         }});
        cases.push_back({"BlinnPhong_n" + std::to_string(int(n)), [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<BlinnPhongBsdf>(modifiedBlinnPhong(RGB(0.3f), RGB(0.7f), n));
                         }});
    }
    for (float m : {0.1f, 0.3f, 0.7f})
        cases.push_back({"CookTorrance_m" + std::to_string(int(m * 100)),
                         [=](BsdfArena& a) -> const Bsdf& { return a.make<CookTorranceBsdf>(RGB(1.0f), 1.5f, m); }});
    for (float alpha : {0.0f, 0.05f, 0.2f, 0.6f})
        cases.push_back({"GgxConductor_a" + std::to_string(int(alpha * 100)), [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<GgxConductorBsdf>(colour, GgxDistribution(alpha));
                         }});
    for (float alpha : {0.05f, 0.3f, 1.0f})
        cases.push_back(
            {"CompensatedGgxConductor_a" + std::to_string(int(alpha * 100)), [=](BsdfArena& a) -> const Bsdf& {
                 return energyCompensatedConductor(colour, GgxDistribution(alpha), a);
             }});
    cases.push_back({"GgxConductorAnisotropic", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<GgxConductorBsdf>(colour, GgxDistribution(0.4f, 0.05f));
                     }});
    cases.push_back({"CompensatedGgxConductorAnisotropic", [=](BsdfArena& a) -> const Bsdf& {
                         return energyCompensatedConductor(colour, GgxDistribution(0.8f, 0.1f), a);
                     }});
    for (float alpha : {0.0f, 0.05f, 0.2f, 0.5f})
        cases.push_back({"GgxDielectric_a" + std::to_string(int(alpha * 100)), [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<GgxDielectricBsdf>(1.5f, GgxDistribution(alpha));
                         }});
    cases.push_back({"GgxDielectricInverted_a30", [](BsdfArena& a) -> const Bsdf& {
                         return a.make<GgxDielectricBsdf>(1.0f / 1.33f, GgxDistribution(0.3f));
                     }});
    const DielectricTints tints{RGB(1.0f, 0.5f, 0.2f), RGB(0.9f, 0.6f, 0.3f)};
    for (float alpha : {0.2f, 0.5f})
        cases.push_back(
            {"CompensatedGgxDielectric_a" + std::to_string(int(alpha * 100)), [=](BsdfArena& a) -> const Bsdf& {
                 return a.make<CompensatedGgxDielectricBsdf>(1.5f, GgxDistribution(alpha));
             }});
    cases.push_back({"CompensatedGgxDielectricInverted_a30", [](BsdfArena& a) -> const Bsdf& {
                         return a.make<CompensatedGgxDielectricBsdf>(1.0f / 1.33f, GgxDistribution(0.3f));
                     }});
    cases.push_back({"CompensatedGgxDielectricTintedAnisotropic", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<CompensatedGgxDielectricBsdf>(1.5f, GgxDistribution(0.4f, 0.1f), tints);
                     }});
    cases.push_back({"GgxDielectricTintedSmooth", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<GgxDielectricBsdf>(1.5f, GgxDistribution(0.0f), tints);
                     }});
    cases.push_back({"GgxDielectricTintedAnisotropic", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<GgxDielectricBsdf>(1.5f, GgxDistribution(0.4f, 0.1f), tints);
                     }});
    cases.push_back(
        {"ThinDielectricSmooth",
         [](BsdfArena& a) -> const Bsdf& { return a.make<ThinDielectricBsdf>(1.5f, GgxDistribution(0.0f)); }, true,
         true});
    cases.push_back(
        {"ThinDielectricTinted_a30",
         [=](BsdfArena& a) -> const Bsdf& { return a.make<ThinDielectricBsdf>(1.5f, GgxDistribution(0.3f), tints); },
         true, true});
    for (float alpha : {0.3f, 1.0f})
        cases.push_back({"CompensatedThinDielectric_a" + std::to_string(int(alpha * 100)),
                         [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<CompensatedThinDielectricBsdf>(1.5f, GgxDistribution(alpha));
                         },
                         true, true});
    cases.push_back({"CompensatedThinDielectricTintedAnisotropic",
                     [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<CompensatedThinDielectricBsdf>(1.5f, GgxDistribution(0.6f, 0.2f), tints);
                     },
                     true, true});
    for (float r : {0.1f, 0.5f, 1.0f})
        cases.push_back({"CharlieSheen_r" + std::to_string(int(r * 100)),
                         [=](BsdfArena& a) -> const Bsdf& { return a.make<CharlieSheenBsdf>(colour, r); }});
    cases.push_back({"SheenOverLambertian", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<LayeredBsdf<CharlieSheenBsdf>>(CharlieSheenBsdf(RGB(1.0f, 0.7f, 0.4f), 0.4f),
                                                                      a.make<LambertianBsdf>(colour));
                     }});
    for (float alpha : {0.0f, 0.1f, 0.4f})
        cases.push_back({"CoatedLambertian_a" + std::to_string(int(alpha * 100)), [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<CoatedBsdf>(a.make<LambertianBsdf>(colour), 1.5f, alpha);
                         }});
    for (float alpha : {0.0f, 0.3f})
        cases.push_back({"CoatedDiffuseBase_a" + std::to_string(int(alpha * 100)), [=](BsdfArena& a) -> const Bsdf& {
                             return a.make<CoatedBsdf>(a.make<LambertianBsdf>(colour), RGB(1.5f),
                                                       GgxDistribution(alpha), RGB(1.0f), RGB(1.0f), DiffuseBase{});
                         }});
    cases.push_back({"SheenOverDiffuseBase", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<LayeredBsdf<CharlieSheenBsdf>>(CharlieSheenBsdf(RGB(1.0f, 0.7f, 0.4f), 0.4f),
                                                                      a.make<LambertianBsdf>(colour), RGB(1.0f),
                                                                      DiffuseBase{});
                     }});
    cases.push_back({"CoatedConductor_a20", [=](BsdfArena& a) -> const Bsdf& {
                         return a.make<CoatedBsdf>(a.make<GgxConductorBsdf>(colour, GgxDistribution(0.3f)), 1.5f, 0.2f);
                     }});
    cases.push_back({"CoatedTintedFilteredAnisotropic", [=](BsdfArena& a) -> const Bsdf& {
                         // A coloured F0 (one index per channel), a tint and a filter.
                         return a.make<CoatedBsdf>(a.make<LambertianBsdf>(colour), RGB(1.3f, 1.5f, 1.8f),
                                                   GgxDistribution(0.3f, 0.08f), RGB(1.0f, 0.6f, 0.3f),
                                                   RGB(0.8f, 0.6f, 0.4f));
                     }});
    for (float metallic : {0.0f, 0.4f, 1.0f})  // a coat returning what its underside sends back (coat_return.h)
        cases.push_back(
            {"CoatReturnedOverGlossy_metallic" + std::to_string(int(metallic * 100)), [=](BsdfArena& a) -> const Bsdf& {
                 MaterialParams m = lambertianParams(colour);
                 m.specular = 1.0f;
                 m.roughness = 0.4f;
                 m.metallic = metallic;
                 m.coat = 1.0f;
                 m.coatRoughness = 0.3f;
                 m.coatColor = RGB(0.9f, 0.8f, 0.7f);
                 return materialBsdf(m, a);
             }});
    // A coat returning its underside's light over a sheen, a subsurface base and solid glass.
    const auto coatedMaterial = [=](MaterialParams m) {
        m.coat = 1.0f;
        m.coatRoughness = 0.3f;
        m.coatColor = RGB(0.9f, 0.8f, 0.7f);
        return m;
    };
    MaterialParams cloth = lambertianParams(colour);
    cloth.sheen = 1.0f;
    cloth.sheenColor = RGB(0.9f, 0.7f, 0.5f);
    cloth.sheenRoughness = 0.4f;
    cases.push_back(
        {"CoatReturnedOverSheen", [=](BsdfArena& a) -> const Bsdf& { return materialBsdf(coatedMaterial(cloth), a); }});
    MaterialParams skin = lambertianParams(colour);
    skin.specular = 1.0f;
    skin.roughness = 0.3f;
    skin.subsurface = 0.6f;
    cases.push_back({"CoatReturnedOverSubsurface",
                     [=](BsdfArena& a) -> const Bsdf& { return materialBsdf(coatedMaterial(skin), a); }, true, false,
                     false});
    MaterialParams glass = lambertianParams(colour);
    glass.specular = 1.0f;
    glass.roughness = 0.4f;
    glass.transmission = 1.0f;
    glass.transmissionColor = RGB(0.9f, 0.8f, 0.6f);
    cases.push_back(
        {"CoatReturnedOverGlass", [=](BsdfArena& a) -> const Bsdf& { return materialBsdf(coatedMaterial(glass), a); }});
    // Over a thin-walled sheet, rough and smooth, and a thin wall of subsurface: the light the coat
    // returns leaves on either side of the sheet (the same medium on both: no index crossed).
    for (float roughness : {0.0f, 0.4f}) {
        MaterialParams sheet = glass;
        sheet.thinWalled = true;
        sheet.roughness = roughness;
        cases.push_back({"CoatReturnedOverThinSheet_r" + std::to_string(int(roughness * 100)),
                         [=](BsdfArena& a) -> const Bsdf& { return materialBsdf(coatedMaterial(sheet), a); }, true,
                         false, false});
    }
    MaterialParams leaf = skin;
    leaf.thinWalled = true;
    leaf.subsurfaceColor = RGB(0.7f, 0.9f, 0.5f);
    cases.push_back({"CoatReturnedOverThinSubsurface",
                     [=](BsdfArena& a) -> const Bsdf& { return materialBsdf(coatedMaterial(leaf), a); }, true, false,
                     false});
    cases.push_back({"CoatedGlass", [](BsdfArena& a) -> const Bsdf& {
                         return a.make<CoatedBsdf>(a.make<GgxDielectricBsdf>(1.5f, GgxDistribution(0.3f)), 1.5f, 0.2f);
                     }});
    cases.push_back({"LambertianTransmission",
                     [=](BsdfArena& a) -> const Bsdf& { return a.make<LambertianTransmissionBsdf>(colour); }, true,
                     true});
    cases.push_back({"CoatedSubsurfaceBoundary",
                     [=](BsdfArena& a) -> const Bsdf& {  // Standard Surface subsurface = 0.6
                         const Bsdf& base = a.make<MixBsdf>(a.make<LambertianBsdf>(colour),
                                                            a.make<LambertianTransmissionBsdf>(RGB(1.0f)), 0.6f);
                         return a.make<CoatedBsdf>(base, 1.4f, 0.35f * 0.35f);
                     },
                     true, false, false});
    cases.push_back({"CoatedSubsurfaceDiffuseBase",
                     [=](BsdfArena& a) -> const Bsdf& {  // subsurface 0.6, and the light the coat returns inside
                         const Bsdf& base = a.make<MixBsdf>(a.make<LambertianBsdf>(colour),
                                                            a.make<LambertianTransmissionBsdf>(RGB(1.0f)), 0.6f);
                         return a.make<CoatedBsdf>(base, RGB(1.4f), GgxDistribution(0.35f * 0.35f), RGB(1.0f),
                                                   RGB(1.0f), DiffuseBase{RGB(0.6f)});
                     },
                     true, false, false});
    return cases;
}

// Incident directions: near normal, oblique, grazing, and below the surface (the mirrored side
// of a reflector, the inside of a dielectric).
std::vector<Vec3f> incidentDirections() {
    std::vector<Vec3f> dirs;
    for (float degrees : {5.0f, 45.0f, 80.0f, 130.0f}) {
        float t = degrees * kPi / 180.0f, phi = 0.7f;
        dirs.push_back(Vec3f(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)));
    }
    return dirs;
}

// The size of each family of statistical tests: one per case and incident direction.
double familySize() { return double(allCases().size() * incidentDirections().size()); }

// Relative float rounding bound for a value recomputed from (wo, wi) instead of the sampled
// half vector, or evaluated with wo and wi exchanged: a few hundred ulps of the exponents and
// Fresnel factors involved (float epsilon is 1.2e-7).
constexpr double kRecomputeTolerance = 1e-4;

std::string describe(const Vec3f& w) {
    std::ostringstream os;
    os << "(" << w.x << ", " << w.y << ", " << w.z << ")";
    return os.str();
}

bool isTransmitted(const Vec3f& wo, const Vec3f& wi) { return wo.z * wi.z < 0.0f; }

class BsdfProperties : public testing::TestWithParam<BsdfCase> {
protected:
    const Bsdf& bsdf() { return GetParam().make(arena_); }

private:
    BsdfArena arena_;
};

TEST_P(BsdfProperties, SamplingMatchesPdfChiSquare) {
    const Bsdf& b = bsdf();
    if (!(b.flags() & (kBsdfDiffuse | kBsdfGlossy))) GTEST_SKIP() << "only delta lobes: nothing to histogram";
    for (const Vec3f& wo : incidentDirections()) {
        auto r = test::chi2SphereTest(
            [&](SampleStream& rng) -> std::optional<Vec3f> {
                float uLobe = rng.next();
                auto s = b.sample(wo, uLobe, rng.next2D());
                return s && !s->specular ? std::optional(s->wi) : std::nullopt;
            },
            [&](const Vec3f& wi) { return double(b.pdf(wo, wi)); }, test::Chi2Options{400'000});
        EXPECT_GT(r.pValue, test::sidakAlpha(familySize())) << "wo " << describe(wo) << ": " << r.report;
    }
}

TEST_P(BsdfProperties, SampleAgreesWithEvalAndPdf) {
    const Bsdf& b = bsdf();
    const unsigned flags = b.flags();
    for (const Vec3f& wo : incidentDirections())
        for (int n = 0; n < 2000; ++n) {
            SampleStream rng(1, 0, n);
            float uLobe = rng.next();
            auto s = b.sample(wo, uLobe, rng.next2D());
            if (!s) continue;
            SCOPED_TRACE("wo " + describe(wo) + " wi " + describe(s->wi));
            ASSERT_NEAR(length(s->wi), 1.0f, 1e-5f);
            ASSERT_GT(s->pdf, 0.0f);
            ASSERT_TRUE(isFinite(s->f));
            ASSERT_GE(std::min({s->f.x, s->f.y, s->f.z}), 0.0f);
            if (isTransmitted(wo, s->wi)) {
                EXPECT_TRUE(flags & kBsdfTransmission);
                if (GetParam().sidesAlike || !GetParam().crossesIndex)
                    EXPECT_EQ(s->eta, 1.0f) << "no index crossed: the same medium on both sides";
                else
                    EXPECT_NE(s->eta, 1.0f);
            } else {
                EXPECT_TRUE(flags & kBsdfReflection);
                EXPECT_EQ(s->eta, 1.0f);
            }
            if (s->specular) {
                EXPECT_TRUE(flags & kBsdfSpecular);
                EXPECT_LE(s->pdf, 1.0f) << "a delta sample's pdf is a lobe probability";
                continue;
            }
            EXPECT_TRUE(flags & (kBsdfDiffuse | kBsdfGlossy));
            EXPECT_NEAR(s->pdf, b.pdf(wo, s->wi), kRecomputeTolerance * s->pdf);
            RGB f = b.f(wo, s->wi);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->f[c], f[c], kRecomputeTolerance * s->f[c]) << "channel " << c;
        }
}

// The lobe split (render/bsdf.h, THE LOBE SPLIT) sums to f, has no negative part, and gives a
// model nothing of a kind it has no lobe of.
TEST_P(BsdfProperties, LobeSplitSumsToF) {
    const Bsdf& b = bsdf();
    const unsigned flags = b.flags();
    for (const Vec3f& wo : incidentDirections())
        for (int n = 0; n < 2000; ++n) {
            SampleStream rng(3, 0, n);
            const Vec3f wi = sampleUniformSphere(rng.next2D());
            const LobeSplit split = b.fByKind(wo, wi);
            const RGB f = b.f(wo, wi);
            SCOPED_TRACE("wo " + describe(wo) + " wi " + describe(wi));
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(split.diffuse[c], 0.0f);
                EXPECT_GE(split.glossy[c], 0.0f);
                EXPECT_NEAR(split.diffuse[c] + split.glossy[c], f[c], kRecomputeTolerance * f[c]) << "channel " << c;
            }
            // Braced: gtest's EXPECT_* expands to an if/else (GCC's -Wdangling-else).
            if (!(flags & kBsdfDiffuse)) {
                EXPECT_TRUE(isBlack(split.diffuse));
            }
            if (!(flags & kBsdfGlossy)) {
                EXPECT_TRUE(isBlack(split.glossy));
            }
        }
}

// Next-event estimation asks fAndPdf() for both values at once; they must be f's and pdf's exactly,
// so that images do not depend on which a method asks for.
TEST_P(BsdfProperties, FAndPdfAreFAndPdfBitForBit) {
    const Bsdf& b = bsdf();
    for (const Vec3f& wo : incidentDirections())
        for (int n = 0; n < 500; ++n) {
            SampleStream rng(5, 0, n);
            const Vec3f wi = sampleUniformSphere(rng.next2D());
            const auto [f, pdf] = b.fAndPdf(wo, wi);
            const RGB fAlone = b.f(wo, wi);
            SCOPED_TRACE("wo " + describe(wo) + " wi " + describe(wi));
            for (int c = 0; c < 3; ++c) EXPECT_EQ(f[c], fAlone[c]) << "channel " << c;
            EXPECT_EQ(pdf, b.pdf(wo, wi));
        }
}

TEST_P(BsdfProperties, PdfIntegratesToTheFractionOfNonDeltaSamples) {
    const Bsdf& b = bsdf();
    constexpr int kSamples = 200'000;
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(familySize()));
    for (const Vec3f& wo : incidentDirections()) {
        // Quadrature to a relative 3e-4 per cell, well below the binomial standard error (1e-3).
        test::SphereIntegral integral =
            test::integrateOverSphere([&](const Vec3f& wi) { return double(b.pdf(wo, wi)); }, 3e-4);
        int accepted = 0;
        for (int n = 0; n < kSamples; ++n) {
            SampleStream rng(2, 0, n);
            float uLobe = rng.next();
            auto s = b.sample(wo, uLobe, rng.next2D());
            accepted += s && !s->specular;
        }
        double p = double(accepted) / kSamples, se = std::sqrt(p * (1.0 - p) / kSamples);
        const double numerical = integral.error + test::kFloatDensityRounding * integral.value;
        EXPECT_LE(integral.value, 1.0 + numerical) << "wo " << describe(wo);
        EXPECT_NEAR(integral.value, p, z * se + numerical)
            << "wo " << describe(wo) << ": integral " << integral.value << " +- " << integral.error << ", " << accepted
            << " of " << kSamples << " samples non-delta";
    }
}

TEST_P(BsdfProperties, IsReciprocal) {
    // f(wo, wi) / n(wo)^2 == f(wi, wo) / n(wi)^2; n is 1 outside (and for reflectors) and the
    // relative eta of a transmitted sample inside. Up to 500 non-delta samples per incident
    // direction (drawn among at most 20000: some models sample their non-delta lobe rarely).
    const Bsdf& b = bsdf();
    int checked = 0;
    for (const Vec3f& wo : incidentDirections())
        for (int n = 0, found = 0; n < 20'000 && found < 500; ++n) {
            SampleStream rng(3, 0, n);
            float uLobe = rng.next();
            auto s = b.sample(wo, uLobe, rng.next2D());
            if (!s || s->specular) continue;
            RGB forward = b.f(wo, s->wi) * (s->eta * s->eta), backward = b.f(s->wi, wo);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(forward[c], backward[c], kRecomputeTolerance * forward[c])
                    << "wo " << describe(wo) << " wi " << describe(s->wi) << " channel " << c;
            ++checked;
            ++found;
        }
    if (b.flags() & (kBsdfDiffuse | kBsdfGlossy)) {
        EXPECT_GT(checked, 1000);
    }
}

TEST_P(BsdfProperties, ImportanceModeIsTheAdjoint) {
    // Transport::Importance (render/bsdf.h, TRANSPORT MODE) evaluates f(wi, wo); its sample() draws
    // what the radiance sample() draws from the same numbers, with f(wi, wo) for a non-delta sample
    // and, for a delta one, the coefficient times eta^2 (generalised reciprocity).
    const Bsdf& b = bsdf();
    for (const Vec3f& wo : incidentDirections())
        for (int n = 0; n < 2000; ++n) {
            SampleStream rng(5, 0, n);
            const float uLobe = rng.next();
            const Vec2f u = rng.next2D();
            const auto radiance = b.sample(wo, uLobe, u, Transport::Radiance),
                       importance = b.sample(wo, uLobe, u, Transport::Importance);
            ASSERT_EQ(radiance.has_value(), importance.has_value());
            if (!radiance) continue;
            EXPECT_EQ(radiance->f, b.sample(wo, uLobe, u)->f) << "radiance is the models' own f";
            EXPECT_EQ(importance->wi, radiance->wi);
            EXPECT_EQ(importance->pdf, radiance->pdf);
            EXPECT_EQ(importance->specular, radiance->specular);
            EXPECT_EQ(importance->eta, radiance->eta);
            const RGB expected =
                radiance->specular ? radiance->f * (radiance->eta * radiance->eta) : b.f(radiance->wi, wo);
            EXPECT_EQ(importance->f, expected) << "wo " << describe(wo) << " wi " << describe(radiance->wi);
            if (!radiance->specular) {
                EXPECT_EQ(b.f(wo, radiance->wi, Transport::Importance), b.f(radiance->wi, wo));
                EXPECT_EQ(b.f(wo, radiance->wi, Transport::Radiance), b.f(wo, radiance->wi));
            }
        }
}

TEST_P(BsdfProperties, ReflectorsAreTwoSidedTransmittersAreNot) {
    const Bsdf& b = bsdf();
    const bool transmits = b.flags() & kBsdfTransmission;
    Vec3f wo = normalize(Vec3f(0.3f, -0.2f, 0.8f)), wi = normalize(Vec3f(-0.4f, 0.1f, 0.6f));
    RGB above = b.f(wo, wi), below = b.f(mirrorZ(wo), mirrorZ(wi));
    if (b.flags() & kBsdfSpecular && !(b.flags() & (kBsdfDiffuse | kBsdfGlossy))) {
        EXPECT_EQ(above, RGB(0.0f)) << "f() has no delta";
        EXPECT_EQ(b.pdf(wo, wi), 0.0f);
    } else if (transmits && !GetParam().sidesAlike) {
        EXPECT_NE(above, below) << "the inside of a dielectric is not the outside";
    } else {
        EXPECT_EQ(above, below);
        EXPECT_EQ(b.pdf(wo, wi), b.pdf(mirrorZ(wo), mirrorZ(wi)));
        if (transmits) {
            EXPECT_EQ(b.f(wo, mirrorZ(wi)), b.f(mirrorZ(wo), wi)) << "both sides transmit alike";
            EXPECT_EQ(b.pdf(wo, mirrorZ(wi)), b.pdf(mirrorZ(wo), wi));
        } else {
            EXPECT_EQ(b.f(wo, mirrorZ(wi)), RGB(0.0f)) << "a reflector does not transmit";
            EXPECT_EQ(b.pdf(wo, mirrorZ(wi)), 0.0f);
        }
    }
    EXPECT_FALSE(b.sample(Vec3f(1, 0, 0), 0.5f, Vec2f{0.5f, 0.5f})) << "grazing wo scatters nothing";
    EXPECT_EQ(b.f(Vec3f(1, 0, 0), wi), RGB(0.0f));
}

TEST_P(BsdfProperties, ReflectsAtMostAllTheLight) {
    // The flux albedo: the mean weight f |cos| / pdf of the importance mode's samples (the adjoint,
    // which carries flux: render/bsdf.h, TRANSPORT MODE), over every sample including delta ones
    // and failures (which count 0). It must not exceed 1 by more than z standard errors in any
    // channel. (Radiance's weights do, by 1 / eta^2, for light leaving a denser medium.)
    if (!GetParam().conservesEnergy) GTEST_SKIP() << "does not conserve energy (see bsdf_phong_test.cpp)";
    const Bsdf& b = bsdf();
    constexpr int kSamples = 200'000;
    const double z = test::normalQuantile(test::sidakAlpha(familySize()));
    for (const Vec3f& wo : incidentDirections()) {
        test::MeanEstimate albedo[3];
        for (int n = 0; n < kSamples; ++n) {
            SampleStream rng(4, 0, n);
            float uLobe = rng.next();
            auto s = b.sample(wo, uLobe, rng.next2D(), Transport::Importance);
            RGB w = s ? s->f * (std::abs(s->wi.z) / s->pdf) : RGB(0.0f);
            for (int c = 0; c < 3; ++c) albedo[c].add(w[c]);
        }
        for (int c = 0; c < 3; ++c)
            EXPECT_LE(albedo[c].mean(), 1.0 + z * albedo[c].standardError() + kRecomputeTolerance)
                << "wo " << describe(wo) << " channel " << c << ": albedo " << albedo[c].mean() << " +- "
                << albedo[c].standardError();
    }
}

INSTANTIATE_TEST_SUITE_P(Models, BsdfProperties, testing::ValuesIn(allCases()),
                         [](const testing::TestParamInfo<BsdfCase>& info) { return info.param.name; });

}  // namespace
}  // namespace fluence::render
