// A dome marked invisible to the camera (render::LightDesc::visibleToCamera = false, as the default
// dome of delegate/default_lights.h is): with every integrator, a camera ray that leaves the scene
// no longer sees it (alpha 0), while the dome still lights the surfaces it reaches.
#include <gtest/gtest.h>

#include "integrators/integrator.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using test_support::channelMean;

TEST(DomeCameraVisibility, EveryIntegratorShowsABlackBackgroundYetIsLitByTheDome) {
    render::SceneDescription seen = test::furnaceScene(0.5f);
    render::SceneDescription hidden = seen;
    hidden.lights[0].visibleToCamera = false;
    for (const IntegratorInfo& info : integratorRegistry()) {
        const std::unique_ptr<Integrator> integrator = info.create(IntegratorSettings{});
        const Image withSky = test_support::renderWith(*integrator, seen, 24, 4).image;
        const Image without = test_support::renderWith(*integrator, hidden, 24, 4).image;
        const int a = without.channelIndex("A");
        ASSERT_EQ(withSky.pixels.size(), without.pixels.size());
        int background = 0;
        for (std::size_t p = 0; p < without.pixels.size(); p += without.channels.size()) {
            if (without.pixels[p + std::size_t(a)] != 0.0f) continue;
            ++background;
            // What the camera saw of the dome (radiance 1) is all that changes there: bdpt's light
            // tracing splats light from the sphere into pixels its silhouette grazes, with or without.
            for (int c : {0, 1, 2})
                EXPECT_NEAR(withSky.pixels[p + std::size_t(c)] - without.pixels[p + std::size_t(c)], 1.0f, 1e-5f)
                    << info.name << " at pixel " << p / without.channels.size();
        }
        EXPECT_GT(background, 100) << info.name;
        // The sphere (alpha 1) is lit by the hidden dome as by the visible one.
        const double lit = channelMean(without, 1, [&](const float* px) { return px[a] == 1.0f; }).mean();
        const double reference = channelMean(withSky, 1, [&](const float* px) { return px[a] == 1.0f; }).mean();
        EXPECT_GT(lit, 0.2) << info.name;
        EXPECT_EQ(lit, reference) << info.name << ": the dome's light on the sphere changed";
    }
}

}  // namespace
}  // namespace fluence::integrators
