// Light path expression AOVs of bdpt (integrators/bdpt_events.h): every strategy's MIS-weighted
// light goes to the layers its path matches, light tracing's (t = 1) through the splat film's
// layers, so the layers of a disjoint cover of every path sum to the beauty (a point light's
// caustic, which only t = 1 draws, included, and absent from a tile); a diffuse-only scene
// has nothing in a mirror layer; a layer's light agrees with `path`'s within noise; layers do not
// change the beauty and are bit-identical at any thread count, with splats and in tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/light_path_layers.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using namespace test_support;

TEST(BdptLightPathAovs, LayersOfADisjointCoverSumToTheBeauty) {
    const Layers cover = byFirstEvent();
    expectLayersSumToBeauty(renderLayers<Bdpt>(everyKindOfEvent(), cover, 24, 8), cover);
}

TEST(BdptLightPathAovs, LightLabelsSplitTheBeautyByLight) {
    const Layers lights = byLight();
    expectLayersSumToBeauty(renderLayers<Bdpt>(everyKindOfEvent(), lights, 24, 8), lights);
}

TEST(BdptLightPathAovs, SubsurfaceEventsAreLabelled) {
    const Layers bySubsurface = bySubsurfaceOrNot();
    expectLayersSumToBeauty(renderLayers<Bdpt>(everyKindOfEvent(), bySubsurface, 24, 8), bySubsurface);
}

// In diffuseOnly() no path has a singular event, so the mirror layer is black and the diffuse one
// is the whole beauty less the light seen.
TEST(BdptLightPathAovs, ADiffuseOnlySceneHasNothingSeenInMirrors) {
    const Layers layers = {{"mirror", "C<RS>.*L"}, {"diffuse", "C<RD>.*L"}, {"seen", "CL"}};
    const Image image = renderLayers<Bdpt>(diffuseOnly(), layers, 16, 8);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_EQ(layerAt(image, "mirror", x, y), RGB(0.0f)) << x << "," << y;
    expectLayersSumToBeauty(image, {{"diffuse", "C<RD>.*L"}, {"seen", "CL"}});
}

// The same layers from bdpt and from `path` on a scene with every kind of event: per layer and
// channel, their image means agree within their combined standard error (pixels are independent
// estimates; two-sided, Sidak over the layers and channels at the suite's level).
TEST(BdptLightPathAovs, AgreesWithPathWithinNoise) {
    const Layers layers = {
        {"diffuse", "C<RD>.*[LO]"}, {"glossy", "C<RG>.*[LO]"}, {"glass", "C<TS>.*[LO]"}, {"key", "C.*<L.'key'>"}};
    const Image bdpt = renderLayers<Bdpt>(everyKindOfEvent(), layers, 32, 256);
    const Image path = renderLayers<PathTracer>(everyKindOfEvent(), layers, 32, 256);
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(3.0 * double(layers.size()), test::kChi2Alpha));
    for (const auto& [name, expression] : layers)
        for (const char* c : {".R", ".G", ".B"}) {
            const auto all = [](const float*) { return true; };
            const test::MeanEstimate b = channelMean(bdpt, bdpt.channelIndex(name + c), all);
            const test::MeanEstimate p = channelMean(path, path.channelIndex(name + c), all);
            const double se = std::hypot(b.standardError(), p.standardError());
            EXPECT_GT(p.mean(), 4.0 * se) << name << c << ": too little light to test";
            EXPECT_NEAR(b.mean(), p.mean(), z * se) << name << c;
        }
}

// A point light inside a smooth glass ball over a diffuse floor: its caustic on the floor seen
// directly, C<RD>S+L, only light tracing (t = 1) can draw, so that layer holds light only when the
// render splats; with the rest of the paths it still sums to the beauty.
TEST(BdptLightPathAovs, LightTracingsCausticReachesItsLayer) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/floor", RGB(0.8f)));
    s.materials.push_back(test::glassMaterial("/glass", 0.0f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.4f, 32, 16, 1, Vec3f(0.0f)));
    s.lights.push_back(test::pointLight("/point", RGB(500.0f)));
    s.camera = test::lookAtOriginCamera(4.0f);
    // The rest: lit onward from the caustic. Paths seen through the glass (C[^D].*L) no strategy draws
    // from a point light (bdpt.h: LS+DS+E), so they hold nothing.
    const Layers cover = {{"caustic", "C<RD>S+L"}, {"indirect", "C<RD>.*[DG].*L"}};
    expectLayersSumToBeauty(renderLayers<Bdpt>(s, cover, 24, 8), cover);

    const render::RenderScene scene(s);  // a tile: no splat film, no t = 1, no caustic
    const render::Camera camera(*s.camera, 24, 24);
    Film tile(12, 24, camera.farClip(), namesOf(cover));
    RenderSettings settings;
    settings.samplesPerPixel = 8;
    settings.windowX = 12;
    settings.imageWidth = 24;
    render(scene, camera, Bdpt(withLayers(cover)), settings, tile);
    const Image image = tile.resolve();
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_EQ(layerAt(image, "caustic", x, y), RGB(0.0f)) << x << "," << y;
}

TEST(BdptLightPathAovs, BeautyIsTheSameWithAndWithoutLayers) {
    const render::SceneDescription s = everyKindOfEvent();
    const Image with = renderLayers<Bdpt>(s, {{"diffuse", "C<RD>.*L"}, {"all", "C.*"}}, 16, 4);
    const Image without = renderLayers<Bdpt>(s, {}, 16, 4);
    for (int y = 0; y < with.height; ++y)
        for (int x = 0; x < with.width; ++x) ASSERT_EQ(beautyAt(with, x, y), beautyAt(without, x, y)) << x << "," << y;
}

// Light tracing's splats included: one thread and four give the same image, layers and all.
TEST(BdptLightPathAovs, AreBitIdenticalAtAnyThreadCount) {
    const Layers cover = byFirstEvent();
    const Image one = renderLayers<Bdpt>(everyKindOfEvent(), cover, 16, 4, 64, 1);
    const Image four = renderLayers<Bdpt>(everyKindOfEvent(), cover, 16, 4, 64, 4);
    EXPECT_EQ(one.pixels, four.pixels);
}

// A tile (a window of the image: no splat film, so no t = 1) still splits its beauty exactly, and
// is bit-identical at any thread count.
TEST(BdptLightPathAovs, TilesSplitTheirBeautyAtAnyThreadCount) {
    const Layers cover = byFirstEvent();
    const render::SceneDescription desc = everyKindOfEvent();
    const auto tile = [&](int threads) {
        const render::RenderScene scene(desc);
        const render::Camera camera(*desc.camera, 24, 24);
        Film film(12, 24, camera.farClip(), namesOf(cover));
        const Bdpt bdpt(withLayers(cover));
        RenderSettings settings;
        settings.samplesPerPixel = 4;
        settings.threads = threads;
        settings.windowX = 12;
        settings.imageWidth = 24;
        render(scene, camera, bdpt, settings, film);
        EXPECT_EQ(film.splats(), nullptr);
        return film.resolve();
    };
    const Image one = tile(1);
    expectLayersSumToBeauty(one, cover);
    EXPECT_EQ(one.pixels, tile(4).pixels);
}

}  // namespace
}  // namespace fluence::integrators
