// Energy preservation of rough glass (render/bsdfs/ggx_dielectric_multiple_scattering.h): the
// dielectric albedo table (render/bsdfs/ggx_dielectric_albedo.h) against independent Monte Carlo
// estimates of the single-scattering BSDF, and the white furnace of the compensated interface,
// from outside and from inside, at several indices, roughnesses and incident angles, alone and
// as the material a white UsdPreviewSurface / Standard Surface glass builds: each keeps all the
// light it receives to within 1% plus the estimate's z standard errors (Sidak-corrected over
// this file's checks for a family-wide false-failure rate of 1%).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "render/bsdf_arena.h"
#include "render/bsdfs/ggx_dielectric.h"
#include "render/bsdfs/ggx_dielectric_albedo.h"
#include "render/bsdfs/ggx_dielectric_multiple_scattering.h"
#include "render/bsdfs/local_geometry.h"
#include "render/material_bsdf.h"
#include "tests/support/bsdf_estimates.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

constexpr int kSamples = 40'000;
const std::vector<float> kAngles = {0.0f, 30.0f, 60.0f, 80.0f};
const std::vector<float> kIndices = {1.33f, 1.5f, 2.0f};
const std::vector<float> kRoughnesses = {0.1f, 0.3f, 0.5f, 0.7f, 1.0f};
// Table: 2 indices x 2 sides x 3 widths x 4 angles; furnaces: 3 indices x 2 sides x 5
// roughnesses x 4 angles; materials: 5 roughnesses x 2 sides x 4 angles.
constexpr int kChecks = 48 + 120 + 40;
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(kChecks));
constexpr double kEnergyTolerance = 0.01;
// What the table may be off the true albedo: its quadrature and linear interpolation.
constexpr double kTableTolerance = 0.004;

test::MeanEstimate fluxAlbedo(const Bsdf& bsdf, const Vec3f& wo, std::uint64_t seed) {
    return test::fluxAlbedoEstimate(bsdf, wo, kSamples, seed);
}

// wo at `angle` degrees from the normal, on the outside or (mirrored) the inside.
Vec3f incident(float angle, bool inside) {
    const Vec3f wo = test::incidentDirection(angle);
    return inside ? mirrorZ(wo) : wo;
}

TEST(GlassEnergy, AlbedoTableMatchesMonteCarlo) {
    std::uint64_t seed = 1;
    for (float eta : {1.5f, 2.0f})
        for (bool inside : {false, true})
            for (float alpha : {0.09f, 0.36f, 1.0f})
                for (float angle : kAngles) {
                    const GgxDielectricBsdf single(eta, GgxDistribution(alpha));
                    const Vec3f wo = incident(angle, inside);
                    const test::MeanEstimate e = fluxAlbedo(single, wo, seed++);
                    const float table = ggxDielectricAlbedo(std::abs(wo.z), alpha, inside ? 1.0f / eta : eta);
                    EXPECT_NEAR(e.mean(), table, kTableTolerance + kZ * e.standardError())
                        << "eta " << eta << (inside ? " inside" : " outside") << ", alpha " << alpha << ", angle "
                        << angle;
                }
}

TEST(GlassEnergy, CompensatedInterfaceKeepsAllTheLightFromBothSides) {
    std::uint64_t seed = 1000;
    BsdfArena arena;
    for (float eta : kIndices)
        for (bool inside : {false, true})
            for (float r : kRoughnesses)
                for (float angle : kAngles) {
                    arena.reset();
                    const GgxDistribution ggx = GgxDistribution::fromRoughness(r);
                    const Bsdf& glass = energyCompensatedDielectric(eta, ggx, {}, arena);
                    const Vec3f wo = incident(angle, inside);
                    const test::MeanEstimate e = fluxAlbedo(glass, wo, seed++);
                    const std::string what = "eta " + std::to_string(eta) + (inside ? " inside" : " outside") +
                                             ", roughness " + std::to_string(r) + ", angle " + std::to_string(angle);
                    if (angle == 0.0f)
                        std::printf("[ measured ] %s: %.4f (single scattering %.4f)\n", what.c_str(), e.mean(),
                                    fluxAlbedo(GgxDielectricBsdf(eta, ggx), wo, seed + 100000).mean());
                    EXPECT_NEAR(e.mean(), 1.0, kEnergyTolerance + kZ * e.standardError()) << what;
                }
}

TEST(GlassEnergy, WhiteGlassMaterialKeepsAllTheLightAtEveryRoughness) {
    std::uint64_t seed = 5000;
    BsdfArena arena;
    for (float r : kRoughnesses) {
        MaterialParams glass = lambertianParams(RGB(1.0f));
        glass.specular = 1.0f;  // Standard Surface's default: the interface reflects
        glass.transmission = 1.0f;
        glass.roughness = r;
        for (bool inside : {false, true})
            for (float angle : kAngles) {
                arena.reset();
                const test::MeanEstimate e = fluxAlbedo(materialBsdf(glass, arena), incident(angle, inside), seed++);
                EXPECT_NEAR(e.mean(), 1.0, kEnergyTolerance + kZ * e.standardError())
                    << "roughness " << r << (inside ? " inside" : " outside") << ", angle " << angle;
            }
    }
}

}  // namespace
}  // namespace fluence::render
