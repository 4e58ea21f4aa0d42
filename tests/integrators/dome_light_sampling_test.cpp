// Every integrator that weighs BSDF-sampled light against next-event estimation stays unbiased
// when next-event estimation leaves a constant dome to scattering (render/dome_light_sampling.h,
// `auto`): a diffuse sphere under a constant dome reads its albedo exactly (it would read about
// 0.82 of it if the rays that escape kept the MIS weight of a light strategy that no longer
// samples the dome), and `auto` and `always` give the same image, on surfaces (a dome and a sun
// over a sphere on a floor) and in chromatic smoke (phase-sampled escapes, spectral MIS).
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "integrators/bdpt.h"
#include "integrators/direct_lighting.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/integrators/smoke_cube.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"
#include "tests/support/temp_dir.h"

namespace fluence::integrators {
namespace {

using render::DomeLightSampling;
using test_support::meanDifference;

// The statistical checks below, for a family-wide false-failure rate of 1%, two-sided: the furnace
// (3 methods x 3 channels), auto against always on surfaces (3 x 3), under a shadowless dome (3
// channels) and in smoke (3 levels x 3 channels).
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(30));

struct Method {
    const char* name;
    std::function<std::unique_ptr<Integrator>()> make;
};

const std::vector<Method> kMethods = {
    {"path", [] { return std::make_unique<PathTracer>(IntegratorSettings{}); }},
    {"direct", [] { return std::make_unique<DirectLighting>(IntegratorSettings{}); }},
    {"bdpt", [] { return std::make_unique<Bdpt>(IntegratorSettings{}); }},
};

// The sphere's pixels are each an estimate of the same value, the albedo times the dome's
// radiance (a convex sphere sees only the dome), so their mean's standard error comes from their
// own spread.
TEST(DomeLightSampling, ADiffuseSphereUnderAConstantDomeReadsItsAlbedoWhenScatteringAloneFindsTheDome) {
    render::SceneDescription desc = test::furnaceScene(0.5f);
    desc.domeLightSampling = DomeLightSampling::Auto;
    for (const Method& method : kMethods) {
        const test_support::Rendered r = test_support::renderWith(*method.make(), desc, 48, 16);
        const int a = r.image.channelIndex("A");
        for (int c = 0; c < 3; ++c) {
            const test::MeanEstimate sphere =
                test_support::channelMean(r.image, c, [&](const float* p) { return p[a] == 1.0f; });
            std::printf("[ measured ] %s, channel %d: %.5f +- %.5f (expected 0.5)\n", method.name, c, sphere.mean(),
                        sphere.standardError());
            ASSERT_GT(sphere.count(), 500);
            EXPECT_NEAR(sphere.mean(), 0.5, kZ * sphere.standardError() + 1e-6) << method.name << ", channel " << c;
        }
    }
}

// A sphere (albedo 0.5) on a floor (albedo 0.7, 0.6, 0.5) under a constant dome and a delta sun.
render::SceneDescription sphereOnAFloor(DomeLightSampling policy) {
    render::SceneDescription s;
    s.materials = {test::diffuseMaterial("/sphere", RGB(0.5f)), test::diffuseMaterial("/floor", RGB(0.7f, 0.6f, 0.5f))};
    s.meshes = {test::sphereMesh(1.0f, 32, 16, 0),
                test::quadMesh("/floor", {{{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}}}, 1)};
    s.lights = {test::domeLight("/sky", RGB(0.6f, 0.7f, 0.9f)),
                test::distantLight("/sun", 0.0f, RGB(3.0f), Matrix4::rotateY(30) * Matrix4::rotateX(-20))};
    s.camera = test::lookAtOriginCamera(5.0f);
    s.domeLightSampling = policy;
    return s;
}

// Both policies render the same pixels' expected values: the per-pixel differences of the two
// images (same seed) each have mean 0, so their mean over the image is 0 within the standard error
// their own spread gives (pixels are independent of each other).
TEST(DomeLightSampling, AutoAndAlwaysRenderTheSameImageOfASphereOnAFloorUnderASkyAndASun) {
    for (const Method& method : kMethods) {
        const std::unique_ptr<Integrator> integrator = method.make();
        const Image automatic =
            test_support::renderWith(*integrator, sphereOnAFloor(DomeLightSampling::Auto), 32, 64).image;
        const Image always =
            test_support::renderWith(*integrator, sphereOnAFloor(DomeLightSampling::Always), 32, 64).image;
        for (int c = 0; c < 3; ++c) {
            const test::MeanEstimate d = meanDifference(automatic, always, c, [](int, int) { return true; });
            std::printf("[ measured ] %s, channel %d: auto - always %+.6f +- %.6f\n", method.name, c, d.mean(),
                        d.standardError());
            EXPECT_GT(d.standardError(), 0.0) << "the two images differ in their noise";
            EXPECT_NEAR(d.mean(), 0.0, kZ * d.standardError()) << method.name << ", channel " << c;
        }
    }
}

// A constant dome that casts no shadows lights the floor under the sphere through it, light only
// next-event estimation finds (a BSDF-sampled ray stops at the sphere: render/shadow_rays.cpp), so
// `auto` must keep sampling it: left out of the light tree, the floor under the sphere loses the
// dome's light and the two images differ by far more than their noise.
TEST(DomeLightSampling, AShadowlessConstantDomeIsStillSampledUnderAuto) {
    auto scene = [](DomeLightSampling policy) {
        render::SceneDescription s = sphereOnAFloor(policy);
        s.lights[0].castsShadows = false;
        return s;
    };
    const PathTracer path{IntegratorSettings{}};
    const Image automatic = test_support::renderWith(path, scene(DomeLightSampling::Auto), 32, 64).image;
    const Image always = test_support::renderWith(path, scene(DomeLightSampling::Always), 32, 64).image;
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate d = meanDifference(automatic, always, c, [](int, int) { return true; });
        std::printf("[ measured ] shadowless dome, channel %d: auto - always %+.6f +- %.6f\n", c, d.mean(),
                    d.standardError());
        EXPECT_NEAR(d.mean(), 0.0, kZ * d.standardError()) << "channel " << c;
    }
}

// Chromatic smoke (sigmaS 2 (0.9, 0.6, 0.3) per unit, absorption colour (0, 0.5, 0.8)) under the
// white sky and a delta sun, along one ray, at exact-flights levels 1, 2 and 3, channel by channel
// (spectral MIS could bias one channel against another): the differences of the pairs of paths
// drawn from the same streams under either policy are independent of each other, so their mean's
// standard error comes from their spread.
TEST(DomeLightSampling, AutoAndAlwaysAgreeInChromaticSmokeUnderASkyAndASun) {
    test::TempDir dir{"fluence_dome_sampling"};
    render::SceneDescription desc = test::smokeUnderAWhiteSky(test::writeSmokeCube(dir), 2.0f, RGB(0.9f, 0.6f, 0.3f));
    desc.volumes[0].params.absorptionColor = RGB(0.0f, 0.5f, 0.8f);
    desc.lights.push_back(
        test::distantLight("/Sun", 0.0f, RGB(3.0f, 2.0f, 1.0f), Matrix4::rotateY(35.0) * Matrix4::rotateX(-25.0)));
    desc.domeLightSampling = DomeLightSampling::Auto;
    const render::RenderScene automatic(desc);
    desc.domeLightSampling = DomeLightSampling::Always;
    const render::RenderScene always(desc);
    const Vec3f d = normalize(Vec3f(1.0f, 0.3f, 0.2f));
    const render::Ray ray{Vec3f(1.0f) - d * 5.0f, d};
    render::Camera camera(render::CameraDesc{}, 8, 8);
    for (int level : {1, 2, 3}) {
        IntegratorSettings settings;
        settings.parameters["exact-flights"] = level;
        const PathTracer tracer(settings);
        const auto stateAuto = tracer.prepare(automatic, camera, 11, nullptr);
        const auto stateAlways = tracer.prepare(always, camera, 11, nullptr);
        RenderCounters counters;
        test::MeanEstimate difference[3], alwaysMean[3];
        for (int i = 0; i < 20000; ++i) {
            SampleStream a(11, 0, std::uint64_t(i)), b(11, 0, std::uint64_t(i));
            const RGB la = tracer.sample(*stateAuto, automatic, camera, ray, a, counters).radiance;
            const RGB lb = tracer.sample(*stateAlways, always, camera, ray, b, counters).radiance;
            for (int c = 0; c < 3; ++c) {
                difference[c].add(double(la[c]) - double(lb[c]));
                alwaysMean[c].add(lb[c]);
            }
        }
        for (int c = 0; c < 3; ++c) {
            std::printf("[ measured ] level %d, channel %d: always %.5f, auto - always %+.6f +- %.6f\n", level, c,
                        alwaysMean[c].mean(), difference[c].mean(), difference[c].standardError());
            EXPECT_GT(alwaysMean[c].mean(), 0.01);
            EXPECT_GT(difference[c].standardError(), 0.0);
            EXPECT_NEAR(difference[c].mean(), 0.0, kZ * difference[c].standardError())
                << "level " << level << ", channel " << c;
        }
    }
}

}  // namespace
}  // namespace fluence::integrators
