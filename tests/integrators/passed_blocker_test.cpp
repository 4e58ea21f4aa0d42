// Lights that pass surfaces (render/shadow_rays.cpp): UsdLux ShadowAPI shadow:enable = false
// (LightDesc::castsShadows) and a blocker that the light's shadow link excludes (render/light_links.h).
// Such a light lights a floor through a blocker as if the blocker were not there, in every
// integrator, and `path` and `bdpt` agree where the blocker also reflects light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "integrators/bdpt.h"
#include "integrators/direct_lighting.h"
#include "integrators/path_tracer.h"
#include "integrators/radiosity.h"
#include "integrators/sppm.h"
#include "integrators/whitted.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using test_support::renderWith;

constexpr float kHeight = 2.0f, kRadius = 0.5f, kRadiance = 10.0f, kFloorAlbedo = 0.5f;
constexpr int kSize = 16;

// How the blocker stands between the light and the floor.
enum class Blocker {
    Shadows,          // it casts the light's shadow
    LightShadowless,  // the light's shadows are off
    ShadowUnlinked,   // the light's shadow link excludes it
};

// A disk light (radius kRadius, radiance kRadiance) at height kHeight shining down on a grey floor
// at z = 0, a square blocker of albedo `blockerAlbedo` at z = 1 between them (it hides the whole
// disk from the floor under it), and a narrow camera at z = 0.6, under the blocker, looking down at
// the floor about the origin.
render::SceneDescription blockedFloor(Blocker blocker, float blockerAlbedo) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/floorGrey", RGB(kFloorAlbedo)));
    s.materials.push_back(test::diffuseMaterial("/blocker", RGB(blockerAlbedo)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}}}, 0));
    s.meshes.push_back(test::quadMesh("/blocker", {{{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}}, 1));
    render::LightDesc disk =
        test::diskLight("/disk", kRadius, RGB(kRadiance), Matrix4::translate({0.0, 0.0, double(kHeight)}));
    disk.castsShadows = blocker != Blocker::LightShadowless;
    s.lights.push_back(disk);
    if (blocker == Blocker::ShadowUnlinked) {
        s.lightLinkGroups.push_back({{}, {0}});
        s.meshes[1].linkGroup = 1;
    }
    render::CameraDesc camera;
    camera.transform = Matrix4::translate({0.0, 0.0, 0.6});      // looks down local -Z
    camera.horizontalAperture = camera.verticalAperture = 2.0f;  // 1.1 degrees: a floor patch of radius 0.012
    camera.nearClip = 0.01f;
    s.camera = camera;
    return s;
}

// The radiance of the floor at the origin lit by the whole disk: irradiance pi L R^2 / (h^2 + R^2),
// times albedo / pi. (Across the camera's patch it varies by under 1e-5 of itself.)
double unblockedRadiance() {
    return kFloorAlbedo * kRadiance * kRadius * kRadius / (kHeight * kHeight + kRadius * kRadius);
}

test::MeanEstimate redMean(const Image& image) {
    return test_support::channelMean(image, 0, [](const float*) { return true; });
}

// Checks below, per blocker: 4 integrators against the closed form, path against bdpt; family-wide 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(5));

TEST(ShadowEnable, ShadowedFloorIsDark) {
    // The check below must be able to fail: with shadows on, the black blocker hides the light
    // and nothing else lights the floor under it.
    const Image image =
        renderWith(PathTracer(IntegratorSettings{}), blockedFloor(Blocker::Shadows, 0.0f), kSize, 16).image;
    EXPECT_EQ(redMean(image).mean(), 0.0);
}

class PassedBlocker : public ::testing::TestWithParam<Blocker> {};

TEST_P(PassedBlocker, LightReachesTheFloorThroughTheBlockerInEveryIntegrator) {
    const render::SceneDescription desc = blockedFloor(GetParam(), 0.0f);
    const double expected = unblockedRadiance();
    const IntegratorSettings settings;
    struct Method {
        std::string name;
        test::MeanEstimate estimate;
    };
    const Method methods[] = {
        {"path", redMean(renderWith(PathTracer(settings), desc, kSize, 64).image)},
        {"direct", redMean(renderWith(DirectLighting(settings), desc, kSize, 64).image)},
        {"whitted", redMean(renderWith(Whitted(settings), desc, kSize, 64).image)},
        {"bdpt", redMean(renderWith(Bdpt(settings), desc, kSize, 64).image)},
    };
    for (const Method& m : methods) {
        std::printf("%s: %.5f +- %.5f (expected %.5f)\n", m.name.c_str(), m.estimate.mean(), m.estimate.standardError(),
                    expected);
        EXPECT_NEAR(m.estimate.mean(), expected, kZ * m.estimate.standardError() + 1e-6) << m.name;
    }
}

TEST_P(PassedBlocker, SppmDepositsTheLightsPhotonsThroughTheBlocker) {
    const render::SceneDescription desc = blockedFloor(GetParam(), 0.0f);
    const double expected = unblockedRadiance();
    // Photons within r_j of the origin in map j (r_j shrinks as Sppm::radius says): the patch's
    // flux pi r_j^2 E over the disk's power pi L pi R^2, times the paths. Every pixel shares a
    // map's photons, so the noise is that of their count over all maps: relative 1 / sqrt(count).
    constexpr int kPaths = 20000, kMaps = 64;
    constexpr float kGather = 0.1f;
    const double irradiance = kPi * expected / kFloorAlbedo;
    const double power = kPi * kRadiance * kPi * kRadius * kRadius;
    double photons = 0.0;
    for (int j = 0; j < kMaps; ++j) {
        const double r = Sppm::radius(kGather, std::uint64_t(j), 2);
        photons += kPaths * irradiance * kPi * r * r / power;
    }
    const Image image = renderWith(Sppm(IntegratorSettings{}, SppmSettings{kPaths, kGather}), desc, kSize, kMaps).image;
    const double mean = redMean(image).mean();
    std::printf("sppm: %.5f (expected %.5f, %.0f photons gathered)\n", mean, expected, photons);
    EXPECT_NEAR(mean, expected, 4.0 * expected / std::sqrt(photons));
}

TEST_P(PassedBlocker, RadiosityCountsTheLightInFull) {
    const render::SceneDescription desc = blockedFloor(GetParam(), 0.0f);
    const double expected = unblockedRadiance();
    RadiositySettings settings;
    settings.patchEdge = 0.125f;
    settings.formFactorRays = 16;  // the flat floor and the black blocker exchange no light
    const double mean = redMean(renderWith(Radiosity(settings), desc, kSize, 4).image).mean();
    std::printf("radiosity: %.5f (expected %.5f)\n", mean, expected);
    // The camera's patch shows the irradiance averaged over the elements about the origin (within
    // 0.2 of it: under 0.5% below the centre's) from 64 light samples each (a few % noise apiece).
    EXPECT_NEAR(mean, expected, 0.03 * expected);
}

// With a grey blocker, light also bounces between floor and blocker: `path` and `bdpt` (light
// subpaths and camera connections included) take the same paths through the blocker.
TEST_P(PassedBlocker, PathAndBdptAgreeWithInterreflection) {
    const render::SceneDescription desc = blockedFloor(GetParam(), 0.8f);
    const test::MeanEstimate path = redMean(renderWith(PathTracer(IntegratorSettings{}), desc, kSize, 128).image);
    const test::MeanEstimate bdpt = redMean(renderWith(Bdpt(IntegratorSettings{}), desc, kSize, 128).image);
    std::printf("path %.5f +- %.5f, bdpt %.5f +- %.5f, direct alone %.5f\n", path.mean(), path.standardError(),
                bdpt.mean(), bdpt.standardError(), unblockedRadiance());
    EXPECT_GT(path.mean(), unblockedRadiance() * 1.05);  // the interreflection shows
    EXPECT_NEAR(path.mean(), bdpt.mean(), kZ * std::hypot(path.standardError(), bdpt.standardError()));
}

INSTANTIATE_TEST_SUITE_P(ShadowEnable, PassedBlocker,
                         ::testing::Values(Blocker::LightShadowless, Blocker::ShadowUnlinked),
                         [](const ::testing::TestParamInfo<Blocker>& info) {
                             return info.param == Blocker::LightShadowless ? std::string("ShadowOff")
                                                                           : std::string("ShadowLink");
                         });

}  // namespace
}  // namespace fluence::integrators
