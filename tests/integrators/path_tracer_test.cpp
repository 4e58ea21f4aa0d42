#include "integrators/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "integrators/renderer.h"
#include "media/subsurface_medium.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using test_support::channelMean;
using test_support::Rendered;

Rendered renderScene(const render::SceneDescription& desc, int size, int spp, int threads = 0, int maxDepth = 64,
                     std::uint64_t seed = 0, SamplerKind sampler = SamplerKind::Sobol) {
    const PathTracer tracer(IntegratorSettings{.maxDepth = maxDepth, .parameters = {}, .lightPathAovs = {}});
    return test_support::renderWith(tracer, desc, size, spp, threads, seed, sampler);
}

TEST(PathTracer, WhiteFurnaceSphereVanishes) {
    Rendered r = renderScene(test::furnaceScene(1.0f), 48, 16);
    int a = r.image.channelIndex("A");
    for (int c : {0, 1, 2}) {
        test::MeanEstimate sphere = channelMean(r.image, c, [&](const float* p) { return p[a] == 1.0f; });
        ASSERT_GT(sphere.count(), 500);
        // Unbiased: within 5 standard errors of exactly 1, and within 1% in any case.
        EXPECT_NEAR(sphere.mean(), 1.0, 5 * sphere.standardError() + 1e-6) << "channel " << c;
        EXPECT_NEAR(sphere.mean(), 1.0, 0.01);
        test::MeanEstimate background = channelMean(r.image, c, [&](const float* p) { return p[a] == 0.0f; });
        EXPECT_DOUBLE_EQ(background.mean(), 1.0) << "directly seen dome";
    }
}

TEST(PathTracer, FurnaceSphereOfAlbedoHalfReadsHalf) {
    // The sphere is convex, so each point sees only the dome: outgoing radiance = albedo.
    Rendered r = renderScene(test::furnaceScene(0.5f), 48, 16);
    int a = r.image.channelIndex("A");
    test::MeanEstimate sphere = channelMean(r.image, 1, [&](const float* p) { return p[a] == 1.0f; });
    EXPECT_NEAR(sphere.mean(), 0.5, 5 * sphere.standardError() + 1e-6);
    EXPECT_NEAR(sphere.mean(), 0.5, 0.005);
}

TEST(PathTracer, DiffusePlaneUnderADistantLightMatchesRhoEOverPi) {
    // A plane of albedo 0.6 facing a delta distant light of irradiance 2 at 60 degrees incidence:
    // L = rho * E * cos(60) / pi, exactly, with one sample (zero variance: one delta light, no
    // indirect light with maxDepth 1).
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/mat", RGB(0.6f), RGB(0.0f)));
    s.meshes.push_back(test::quadMesh("/plane", {{{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}}}, 0));
    render::LightDesc sun;
    sun.name = "/sun";
    sun.type = render::LightType::Distant;
    sun.angleDegrees = 0.0f;
    sun.radiance = RGB(2.0f);
    sun.transform = Matrix4::rotateX(60);  // its +Z axis is tilted 60 degrees from the plane normal
    s.lights.push_back(sun);
    s.camera = test::lookAtOriginCamera(1.0f);
    s.camera->transform = Matrix4::translate({0, 0, 3});  // looking straight down at the plane
    Rendered r = renderScene(s, 8, 1, 0, 1);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_NEAR(r.image.pixel(x, y)[0], 0.6 * 2.0 * 0.5 / M_PI, 1e-6);
}

TEST(PathTracer, ImagesAreBitIdenticalAcrossThreadCounts) {
    auto scene = test::furnaceScene(0.7f);
    for (SamplerKind sampler : test_support::kSamplers) {
        Rendered one = renderScene(scene, 40, 5, 1, 64, 1234, sampler);
        Rendered two = renderScene(scene, 40, 5, 2, 64, 1234, sampler);
        ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
        EXPECT_EQ(
            0, std::memcmp(one.image.pixels.data(), two.image.pixels.data(), one.image.pixels.size() * sizeof(float)));
        Rendered otherSeed = renderScene(scene, 40, 5, 2, 64, 99, sampler);
        EXPECT_NE(0, std::memcmp(one.image.pixels.data(), otherSeed.image.pixels.data(),
                                 one.image.pixels.size() * sizeof(float)));
    }
    // The samplers draw different numbers (the sphere's pixels differ; the dome's are exactly 1).
    const Rendered sobol = renderScene(scene, 40, 5, 2, 64, 1234, SamplerKind::Sobol);
    const Rendered independent = renderScene(scene, 40, 5, 2, 64, 1234, SamplerKind::Independent);
    ASSERT_EQ(sobol.image.pixels.size(), independent.image.pixels.size());
    EXPECT_NE(0, std::memcmp(sobol.image.pixels.data(), independent.image.pixels.data(),
                             sobol.image.pixels.size() * sizeof(float)));
}

// Four samples per pixel of a 32 x 32 camera: the tracer with media's in `withMedia` (with the
// equiangular strategy's `lights`) and the tracer without's in `without`, whose stream starts
// `offset` numbers on, give the same radiance, bit for bit, from the same number of rays.
void expectTheSameSamples(const render::RenderScene& withMedia, const EquiangularLights& lights,
                          const render::RenderScene& without, const render::Camera& camera, int offset) {
    const PathTracer tracer{IntegratorSettings{}};
    RenderCounters a, b;
    for (int i = 0; i < 32 * 32 * 4; ++i) {
        const render::Ray ray = camera.generateRay(float(i % 32) + 0.5f, float((i / 32) % 32) + 0.5f);
        SampleStream rngA(5, std::uint64_t(i), 0), rngB(5, std::uint64_t(i), 0);
        for (int k = 0; k < offset; ++k) rngB.next();
        const RGB with = tracer.trace<true>(LightEvents(), lights, withMedia, camera, ray, rngA, a).radiance;
        const RGB plain =
            tracer.trace<false>(LightEvents(), EquiangularLights(), without, camera, ray, rngB, b).radiance;
        ASSERT_EQ(0, std::memcmp(&with, &plain, sizeof(RGB))) << "sample " << i;
    }
    EXPECT_EQ(a.rays(), b.rays());
}

// A scene without media pays for none of their machinery: the tracer without it gives the same
// samples, bit for bit, as the one with it, through glass, metal and diffuse surfaces.
TEST(PathTracer, WithoutMediaTheSurfaceOnlyTracerGivesTheSameSamples) {
    render::SceneDescription s = test::furnaceScene(0.6f);
    s.materials.push_back(test::glassMaterial("/glass", 0.1f));
    s.materials.push_back(test::metalMaterial("/metal", RGB(0.9f, 0.6f, 0.3f), 0.3f));
    s.meshes.push_back(test::roundSphereMesh(0.5f, 32, 16, 1, Vec3f(1.2f, -0.5f, 0.0f)));
    s.meshes.push_back(test::roundSphereMesh(0.5f, 32, 16, 2, Vec3f(-1.2f, -0.5f, 0.0f)));
    s.lights.push_back(test::sphereLight("/bulb", 0.3f, RGB(20.0f), Vec3d(0.0, -1.5, 2.0)));
    const render::RenderScene scene(s);
    ASSERT_FALSE(scene.hasMedia());
    expectTheSameSamples(scene, EquiangularLights(), scene, render::Camera(*s.camera, 32, 32), 0);
}

// A scene whose only medium is a guided subsurface walk's (its steps do not depend on the path's
// hero channel, media/guided_walk.h) weighs the paths that meet no medium as a scene without
// media does, by the power heuristic: a glossy wall under a sphere light, with a guided
// subsurface ball hidden behind it, gives the same samples, bit for bit, as the wall alone (whose
// stream is one number on: the hero channel the tracer with media draws first).
TEST(PathTracer, PathsThatMeetNoHeroDependentMediumTakeThePowerHeuristic) {
    render::SceneDescription alone;
    alone.camera = test::lookAtOriginCamera(4.0f);
    alone.materials.push_back(test::metalMaterial("/metal", RGB(0.9f, 0.6f, 0.3f), 0.3f));
    alone.meshes.push_back(test::quadMesh("/wall",
                                          {Vec3f(-10.0f, 0.0f, -10.0f), Vec3f(10.0f, 0.0f, -10.0f),
                                           Vec3f(10.0f, 0.0f, 10.0f), Vec3f(-10.0f, 0.0f, 10.0f)},
                                          0));
    alone.lights.push_back(test::sphereLight("/bulb", 0.3f, RGB(20.0f), Vec3d(0.5, -1.5, 1.0)));
    render::SceneDescription withBall = alone;
    render::MaterialDesc skin;
    skin.name = "/skin";
    skin.subsurface = 1.0f;
    skin.subsurfaceMethod = render::SubsurfaceMethod::RandomWalkGuided;
    skin.interior = media::subsurfaceMedium(RGB(0.8f, 0.5f, 0.3f), RGB(0.2f), 0.0f);
    withBall.materials.push_back(skin);
    withBall.meshes.push_back(test::roundSphereMesh(0.5f, 32, 16, 1, Vec3f(0.0f, 3.0f, 0.0f)));
    const render::RenderScene sceneWithBall(withBall), sceneAlone(alone);
    ASSERT_TRUE(sceneWithBall.hasMedia());
    ASSERT_FALSE(sceneAlone.hasMedia());
    expectTheSameSamples(sceneWithBall, EquiangularLights(sceneWithBall), sceneAlone,
                         render::Camera(*alone.camera, 32, 32), 1);
}

TEST(PathTracer, CountsRaysAndSamples) {
    render::SceneDescription furnace = test::furnaceScene(0.5f);
    furnace.domeLightSampling = render::DomeLightSampling::Always;
    Rendered r = renderScene(furnace, 16, 3);
    EXPECT_EQ(r.stats.samplesPerPixel, 3);
    EXPECT_EQ(r.stats.counters.camera, 16u * 16u * 3u);
    EXPECT_GT(r.stats.counters.shadow, 0u);
    EXPECT_EQ(r.stats.passes, 2);  // passes of 1 then 2 samples
    // By default its constant dome is left to BSDF sampling (render/dome_light_sampling.h): no shadow rays.
    furnace.domeLightSampling = render::DomeLightSampling::Auto;
    EXPECT_EQ(renderScene(furnace, 16, 3).stats.counters.shadow, 0u);
}

TEST(Renderer, ThousandsOfSamplesAllArrive) {
    // Passes grow 1, 2, 4, ..., 32 (63 samples in 6 passes), then stay at 64: the remaining 4937
    // samples take 78 more passes.
    Rendered r = renderScene(test::furnaceScene(0.5f), 2, 5000);
    EXPECT_EQ(r.stats.samplesPerPixel, 5000);
    EXPECT_EQ(r.stats.passes, 84);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) EXPECT_EQ(r.image.pixel(x, y)[r.image.channelIndex("sampleCount")], 5000.0f);
}

// The render's CPU time is measured over the render: more than nothing, and at most what its two
// threads can spend in its wall time (the clock's tick of 1 microsecond aside).
TEST(Renderer, MeasuresTheRendersCpuTime) {
    Rendered r = renderScene(test::furnaceScene(0.5f), 32, 64, 2);
    EXPECT_GT(r.stats.cpuSeconds, 0.0);
    EXPECT_LE(r.stats.cpuSeconds, 2.0 * r.stats.seconds + 1e-6);
}

TEST(Renderer, DiscardsAndCountsNonFiniteSamples) {
    // An integrator that returns NaN for every third sample: the pixel keeps the finite samples'
    // sum (the NaN ones count as zero) and the render reports how many were discarded.
    class EveryThirdNaN final : public Integrator {
    public:
        FilmSample sample(const RenderState&, const render::RenderScene&, const render::Camera&, const render::Ray&,
                          SampleStream& rng, RenderCounters&) const override {
            FilmSample s;
            s.radiance = RGB(rng.next() < 0.0f ? 0.0f : 1.0f);
            if (++calls_ % 3 == 0) s.radiance.y = std::numeric_limits<float>::quiet_NaN();
            return s;
        }
        mutable std::atomic<int> calls_{0};
    } integrator;
    auto desc = test::furnaceScene(0.5f);
    render::RenderScene scene(desc);
    render::Camera camera(*desc.camera, 3, 1);
    Film film(3, 1, camera.farClip());
    RenderSettings settings;
    settings.samplesPerPixel = 4;
    settings.threads = 1;
    RenderStats stats = render(scene, camera, integrator, settings, film);
    EXPECT_EQ(stats.counters.nonFiniteSamples, 4u);  // 12 samples, every third
    Image image = film.resolve();
    for (int x = 0; x < 3; ++x)
        for (float v : {image.pixel(x, 0)[0], image.pixel(x, 0)[1], image.pixel(x, 0)[2]})
            EXPECT_TRUE(std::isfinite(v));
}

TEST(PathTracer, MaxDepthZeroSeesOnlyEmitters) {
    Rendered r = renderScene(test::furnaceScene(1.0f), 16, 2, 0, 0);
    int a = r.image.channelIndex("A");
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const float* p = r.image.pixel(x, y);
            EXPECT_FLOAT_EQ(p[0], p[a] == 1.0f ? 0.0f : (p[a] == 0.0f ? 1.0f : p[0]));
        }
}

}  // namespace
}  // namespace fluence::integrators
