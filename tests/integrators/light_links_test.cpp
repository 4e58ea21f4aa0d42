// Light linking (render/light_links.h): a light linked away from a plane does not light it, in
// every integrator, and the plane then looks as it does with that light deleted (the light tree
// still picks the unlinked light; its samples count nothing, so the estimate stays unbiased);
// camera rays still see the light; a render is the same at any thread count; `radiosity` refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
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

constexpr int kSize = 16;

// A grey floor at z = 0 under a red disk light (light 0) and a green one (light 1), both at
// height 2 and off to either side, seen from above by a camera at z = 3 that sees only floor.
// `redLinked`: whether the red light lights the floor (else the floor is in a group it does not).
render::SceneDescription twoLightsOverAFloor(bool redLinked, bool withRed = true) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}}}, 0));
    if (withRed)
        s.lights.push_back(test::diskLight("/red", 0.5f, RGB(8.0f, 0.0f, 0.0f), Matrix4::translate({-1, 0, 2})));
    s.lights.push_back(test::diskLight("/green", 0.5f, RGB(0.0f, 8.0f, 0.0f), Matrix4::translate({1, 0, 2})));
    if (!redLinked) {
        s.lightLinkGroups.push_back({{0}, {}});
        s.meshes[0].linkGroup = 1;
    }
    render::CameraDesc camera;
    camera.transform = Matrix4::translate({0.0, 0.0, 3.0});
    camera.horizontalAperture = camera.verticalAperture = 20.0f;  // sees x, y in [-0.6, 0.6]
    s.camera = camera;
    return s;
}

test::MeanEstimate channel(const Image& image, int c) {
    return test_support::channelMean(image, c, [](const float*) { return true; });
}

// Checks: per integrator (5), the red channel is zero and the green agrees with the scene without
// the red light; family-wide 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(5));

struct Method {
    std::string name;
    std::unique_ptr<Integrator> integrator;
    int spp;
};

std::vector<Method> everyMethod() {
    const IntegratorSettings settings;
    std::vector<Method> m;
    m.push_back({"path", std::make_unique<PathTracer>(settings), 64});
    m.push_back({"direct", std::make_unique<DirectLighting>(settings), 64});
    m.push_back({"whitted", std::make_unique<Whitted>(settings), 64});
    m.push_back({"bdpt", std::make_unique<Bdpt>(settings), 64});
    m.push_back({"sppm", std::make_unique<Sppm>(settings, SppmSettings{20000, 0.1f}), 64});
    return m;
}

TEST(LightLinks, UnlinkedLightDoesNotLightThePlane) {
    const render::SceneDescription linked = twoLightsOverAFloor(true), unlinked = twoLightsOverAFloor(false);
    for (const Method& m : everyMethod()) {
        // The check must be able to fail: linked, the red light shows on the floor.
        EXPECT_GT(channel(renderWith(*m.integrator, linked, kSize, 4).image, 0).mean(), 0.01) << m.name;
        EXPECT_EQ(channel(renderWith(*m.integrator, unlinked, kSize, 16).image, 0).mean(), 0.0) << m.name;
    }
}

TEST(LightLinks, PlaneLooksAsWithTheUnlinkedLightDeleted) {
    const render::SceneDescription unlinked = twoLightsOverAFloor(false), deleted = twoLightsOverAFloor(true, false);
    for (const Method& m : everyMethod()) {
        const Image a = renderWith(*m.integrator, unlinked, kSize, m.spp, 0, 1).image;
        const Image b = renderWith(*m.integrator, deleted, kSize, m.spp, 0, 2).image;
        const test::MeanEstimate ga = channel(a, 1), gb = channel(b, 1);
        std::printf("%s: green %.5f +- %.5f unlinked, %.5f +- %.5f deleted\n", m.name.c_str(), ga.mean(),
                    ga.standardError(), gb.mean(), gb.standardError());
        if (m.name == "sppm") {
            // Pixels share each map's photons: compare against the photon noise (about 1% here).
            EXPECT_NEAR(ga.mean(), gb.mean(), 0.05 * gb.mean()) << m.name;
        } else {
            EXPECT_NEAR(ga.mean(), gb.mean(), kZ * std::hypot(ga.standardError(), gb.standardError())) << m.name;
        }
    }
}

TEST(LightLinks, CameraRaysSeeALightLinkedAwayFromEverything) {
    render::SceneDescription s = twoLightsOverAFloor(false);
    s.lights[0] =
        test::rectLight("/red", 4.0f, 4.0f, RGB(1.0f, 0.0f, 0.0f),
                        Matrix4::translate({0, 0, 1.5}) * Matrix4::rotateX(180));  // faces up, 1.5 from the camera
    const Image image = renderWith(PathTracer(IntegratorSettings{}), s, kSize, 4).image;
    EXPECT_NEAR(channel(image, 0).mean(), 1.0, 1e-5);  // the radiance of its front
}

TEST(LightLinks, SameImageAtAnyThreadCount) {
    const render::SceneDescription desc = twoLightsOverAFloor(false);
    for (const Method& m : everyMethod()) {
        const Image one = renderWith(*m.integrator, desc, kSize, 8, 1, 7).image;
        const Image many = renderWith(*m.integrator, desc, kSize, 8, 4, 7).image;
        EXPECT_TRUE(one.pixels == many.pixels) << m.name;
    }
}

TEST(LightLinks, RadiosityRefusesLinksThatExcludeGeometry) {
    const render::SceneDescription desc = twoLightsOverAFloor(false);
    EXPECT_THROW(renderWith(Radiosity(), desc, kSize, 1), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::integrators
