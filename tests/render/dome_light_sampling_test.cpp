// The dome light sampling policy (render/dome_light_sampling.h) in the scene's light selection:
// under auto, next-event estimation never chooses a dome of constant radiance and gives it
// probability 0, while a textured dome and the other lights are chosen as before; under always,
// every light is chosen. The power-based selection (sppm's photons, `haveLights`) keeps every light.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/random.h"
#include "render/render_scene.h"
#include "tests/render/light_test_support.h"
#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

constexpr int kConstantDome = 0, kTexturedDome = 1, kDisk = 2;

LightDesc texturedDome() {
    LightDesc d = test::domeLight("/texturedDome", RGB(0.5f));
    d.texture = test::image(16, 8, [](int x, int y) { return RGB(0.2f + 0.1f * float(x % 4), 0.3f, 0.1f * float(y)); });
    return d;
}

// A constant dome, a textured dome and a disk light above the origin, with the given policy.
SceneDescription threeLights(DomeLightSampling policy) {
    SceneDescription s;
    s.lights = {test::domeLight("/constantDome", RGB(1.0f)), texturedDome(),
                test::diskLight("/disk", 0.5f, RGB(20.0f), Matrix4::translate({0, 2, 0}) * Matrix4::rotateX(-90))};
    s.domeLightSampling = policy;
    return s;
}

// Points and normals around the lights (a zero normal: a point in a medium).
const std::vector<std::pair<Vec3f, Vec3f>> kPoints = {
    {Vec3f(0.0f), Vec3f(0, 1, 0)}, {Vec3f(1, 0.5f, -2), Vec3f(0.0f)}, {Vec3f(-3, 4, 1), Vec3f(0, -1, 0)}};

// How often each light is chosen over `n` stratified numbers at each point; checks that every
// choice's probability is lightProbability's and that the probabilities sum to 1 where any light is chosen.
std::vector<int> choices(const RenderScene& scene, int n = 256) {
    std::vector<int> count(scene.lightCount(), 0);
    for (const auto& [p, normal] : kPoints) {
        double sum = 0.0;
        for (std::size_t i = 0; i < scene.lightCount(); ++i) sum += scene.lightProbability(p, normal, int(i));
        EXPECT_NEAR(sum, 1.0, 1e-5);
        for (int k = 0; k < n; ++k) {
            const LightChoice c = scene.chooseLight(p, normal, (float(k) + 0.5f) / float(n));
            EXPECT_GE(c.light, 0);
            if (c.light < 0) continue;
            EXPECT_NEAR(c.probability, scene.lightProbability(p, normal, c.light), 1e-6f);
            ++count[std::size_t(c.light)];
        }
    }
    return count;
}

TEST(DomeLightSampling, AutoNeverChoosesAConstantDomeButATexturedOne) {
    const RenderScene scene(threeLights(DomeLightSampling::Auto));
    const std::vector<int> count = choices(scene);
    EXPECT_EQ(count[kConstantDome], 0);
    EXPECT_GT(count[kTexturedDome], 0);
    EXPECT_GT(count[kDisk], 0);
    for (const auto& [p, n] : kPoints) EXPECT_EQ(scene.lightProbability(p, n, kConstantDome), 0.0f);
    EXPECT_GT(scene.lightSelection().pmf(kConstantDome), 0.0f) << "its power still starts photons";
}

TEST(DomeLightSampling, AlwaysChoosesEveryLight) {
    const RenderScene scene(threeLights(DomeLightSampling::Always));
    const std::vector<int> count = choices(scene);
    for (int light : {kConstantDome, kTexturedDome, kDisk}) EXPECT_GT(count[std::size_t(light)], 0) << light;
    for (const auto& [p, n] : kPoints) EXPECT_GT(scene.lightProbability(p, n, kConstantDome), 0.0f);
}

TEST(DomeLightSampling, AutoBesideOneLightGivesTheDomeProbabilityZero) {
    // One light left in the tree and none at infinity: the tree's one-leaf shortcut must not
    // answer for the dome it left out.
    SceneDescription s = threeLights(DomeLightSampling::Auto);
    s.lights.erase(s.lights.begin() + kTexturedDome);
    const RenderScene scene(s);
    const Vec3f p(0.0f), n(0, 1, 0);
    EXPECT_EQ(scene.lightProbability(p, n, 0), 0.0f);
    EXPECT_EQ(scene.lightProbability(p, n, 1), 1.0f);
    for (float u : {0.0f, 0.5f, 0.99f}) EXPECT_EQ(scene.chooseLight(p, n, u).light, 1);
}

TEST(DomeLightSampling, AConstantDomeAloneIsLeftToScatteringButStillLightsTheScene) {
    SceneDescription s;
    s.lights = {test::domeLight("/dome", RGB(1.0f))};
    const RenderScene scene(s);
    for (const auto& [p, n] : kPoints) {
        EXPECT_LT(scene.chooseLight(p, n, 0.5f).light, 0);
        EXPECT_EQ(scene.lightProbability(p, n, 0), 0.0f);
    }
    EXPECT_FALSE(scene.lightSelection().empty()) << "integrators' haveLights checks keep the dome's light";
    EXPECT_EQ(scene.lightsAtInfinity(false), std::vector<int>{0}) << "rays that leave the scene meet it";
}

}  // namespace
}  // namespace fluence::render
