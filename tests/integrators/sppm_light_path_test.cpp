// Light path expression AOVs of sppm (integrators/photon_light_paths.h): the eye path's events
// run the automaton forward, each photon carries the states from which its own events accept, so
// every gathered photon's term goes to exactly the layers its joined path matches: the layers of a
// disjoint cover of every path sum to the beauty; light labels split it by light; a diffuse-only
// scene has nothing in a mirror layer; a layer agrees with `path`'s within noise; layers do not
// change the beauty and are bit-identical at any thread count and in tiles; an expression photons
// cannot carry is refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/random.h"
#include "integrators/path_tracer.h"
#include "integrators/photon_light_paths.h"
#include "integrators/sppm.h"
#include "tests/integrators/light_path_layers.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using namespace test_support;

const SppmSettings kFewPhotons{5000};

Image sppmLayers(const render::SceneDescription& desc, const Layers& layers, int size, int spp, int threads = 0,
                 std::uint64_t seed = 0, const SppmSettings& sppm = kFewPhotons) {
    return renderLayers<Sppm>(desc, layers, size, spp, 64, threads, seed, sppm);
}

// A photon's state set is exactly the states from which its events, read back to its light, are
// accepted: checked against running the automaton forward from every state, over event strings
// drawn at random (a fixed seed) from the events Fluence produces.
TEST(SppmLightPathAovs, PhotonStateSetsAreTheStatesThatAcceptTheReversedEvents) {
    const Layers layers = {{"a", "C<RD>.*[LO]"},
                           {"b", "C.*<L.'key'>"},
                           {"c", "C(D|G){2}<TS>?L"},
                           {"d", "C[^S]*<V>.*L"},
                           {"e", "C<R.>.*G.*[LO]"}};
    const IntegratorSettings settings = withLayers(layers);
    const std::vector<PathEvent> events = {
        {EventType::Reflection, Scattering::Diffuse},   {EventType::Reflection, Scattering::Glossy},
        {EventType::Reflection, Scattering::Singular},  {EventType::Transmission, Scattering::Singular},
        {EventType::Transmission, Scattering::Diffuse}, {EventType::Volume, Scattering::Diffuse}};
    const std::vector<PathEvent> lights = {{EventType::Light, Scattering::None, "key"},
                                           {EventType::Light, Scattering::None, "fill"},
                                           {EventType::Object, Scattering::None, ""}};
    SampleStream rng(7, 0, 0);
    for (int trial = 0; trial < 300; ++trial) {
        const PathEvent& light = lights[std::size_t(rng.next() * float(lights.size())) % lights.size()];
        PhotonLightPaths photon(*settings.lightPathAovs, light);
        std::vector<PathEvent> drawn;  // light first
        const int n = int(rng.next() * 5.0f);
        for (int i = 0; i < n; ++i) {
            drawn.push_back(events[std::size_t(rng.next() * float(events.size())) % events.size()]);
            photon.scatter(VertexEvents(drawn.back()));
        }
        for (int aov = 0; aov < int(layers.size()); ++aov) {
            const LightPathExpression& e = (*settings.lightPathAovs)[std::size_t(aov)].expression;
            std::uint64_t states = 0;
            for (const PhotonHistory& h : photon.histories())
                if (h.aov == aov) states |= h.states;
            for (int q = 0; q < e.stateCount(); ++q) {
                int state = q;
                for (auto it = drawn.rbegin(); it != drawn.rend(); ++it) state = e.next(state, *it);
                ASSERT_EQ(e.accepts(e.next(state, light)), ((states >> q) & 1u) != 0)
                    << layers[std::size_t(aov)].second << " trial " << trial << " state " << q;
            }
        }
    }
}

TEST(SppmLightPathAovs, LayersOfADisjointCoverSumToTheBeauty) {
    const Layers cover = byFirstEvent();
    expectLayersSumToBeauty(sppmLayers(everyKindOfEvent(), cover, 24, 4), cover);
}

TEST(SppmLightPathAovs, LightLabelsSplitTheBeautyByLight) {
    const Layers lights = byLight();
    expectLayersSumToBeauty(sppmLayers(everyKindOfEvent(), lights, 24, 4), lights);
}

TEST(SppmLightPathAovs, SubsurfaceEventsAreLabelled) {
    const Layers bySubsurface = bySubsurfaceOrNot();
    expectLayersSumToBeauty(sppmLayers(everyKindOfEvent(), bySubsurface, 24, 4), bySubsurface);
}

// The photon's own scatterings decide: light that reached the floor through the metal ball (a
// glossy scattering on the photon's side) against light that reached it otherwise.
TEST(SppmLightPathAovs, PhotonEventsSplitTheBeauty) {
    const Layers cover = {{"viaGlossy", "C<R.>.*G.*[LO]"}, {"other", "C[LO]|C<R.>[^G]*[LO]|C<T.>.*[LO]"}};
    expectLayersSumToBeauty(sppmLayers(everyKindOfEvent(), cover, 24, 4), cover);
}

TEST(SppmLightPathAovs, ADiffuseOnlySceneHasNothingSeenInMirrors) {
    const Layers layers = {{"mirror", "C<RS>.*L"}, {"diffuse", "C<RD>.*L"}, {"seen", "CL"}};
    const Image image = sppmLayers(diffuseOnly(), layers, 16, 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) ASSERT_EQ(layerAt(image, "mirror", x, y), RGB(0.0f)) << x << "," << y;
    expectLayersSumToBeauty(image, {{"diffuse", "C<RD>.*L"}, {"seen", "CL"}});
}

// A plastic floor (diffuse and glossy lobes) far wider than the view, a rough metal ball and two
// lights: radiance there is smooth, so sppm's kernel bias is far below the noise.
render::SceneDescription plasticFloorAndBall() {
    render::SceneDescription s;
    s.materials.push_back(plastic("/plastic", RGB(0.6f, 0.5f, 0.4f), 0.4f));
    s.materials.push_back(test::metalMaterial("/metal", RGB(0.9f, 0.7f, 0.5f), 0.3f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-20, -20, -1}, {20, -20, -1}, {20, 20, -1}, {-20, 20, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.4f, 32, 16, 1, Vec3f(0.0f, 0.0f, -0.5f)));
    s.lights.push_back(test::rectLight("/lights/key", 1.0f, 1.0f, RGB(8.0f), Matrix4::translate({0.0, 0.0, 2.0})));
    s.lights.push_back(test::sphereLight("/lights/fill", 0.2f, RGB(10.0f, 10.0f, 12.0f), Vec3d(-2.0, -1.0, 1.0)));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// The same layers from sppm and from `path` (the direct and indirect light of the floor's diffuse
// lobe, the key light's): per layer and channel, their image means agree within
// their combined standard error, two-sided, Sidak over the layers and channels at the suite's level.
// sppm's pixels share each sample index's photon map, so they are not independent: its standard
// error comes from kSeeds renders with different seeds, whose image means are independent; the
// quantile is widened for the kSeeds - 1 degrees of freedom of that estimate (Student's t by its
// Cornish-Fisher expansion, t ~ z + (z^3 + z) / (4 nu)). The kernel's bias, O(r^2) times the
// radiance's curvature, is left out of the tolerance: on this scene it is far below the noise.
TEST(SppmLightPathAovs, AgreesWithPathWithinNoise) {
    const Layers layers = {{"diffuse", "C<RD>.*[LO]"}, {"indirect", "C<RD>.+[LO]"}, {"key", "C.*<L.'key'>"}};
    const render::SceneDescription desc = plasticFloorAndBall();
    constexpr int kSeeds = 24;
    std::vector<Image> sppm;
    for (int seed = 0; seed < kSeeds; ++seed)
        sppm.push_back(sppmLayers(desc, layers, 16, 4, 0, std::uint64_t(seed) + 1, SppmSettings{20000}));
    const Image path = renderLayers<PathTracer>(desc, layers, 32, 256);
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(3.0 * double(layers.size()), test::kChi2Alpha));
    const double t = z + (z * z * z + z) / (4.0 * (kSeeds - 1));
    const auto all = [](const float*) { return true; };
    for (const auto& [name, expression] : layers)
        for (const char* c : {".R", ".G", ".B"}) {
            test::MeanEstimate s;
            for (const Image& image : sppm) s.add(channelMean(image, image.channelIndex(name + c), all).mean());
            const test::MeanEstimate p = channelMean(path, path.channelIndex(name + c), all);
            const double se = std::hypot(s.standardError() * std::sqrt(kSeeds / (kSeeds - 1.0)), p.standardError());
            EXPECT_GT(p.mean(), 4.0 * se) << name << c << ": too little light to test";
            EXPECT_NEAR(s.mean(), p.mean(), t * se) << name << c;
        }
}

TEST(SppmLightPathAovs, BeautyIsTheSameWithAndWithoutLayers) {
    const render::SceneDescription s = everyKindOfEvent();
    const Image with = sppmLayers(s, {{"diffuse", "C<RD>.*L"}, {"all", "C.*"}}, 16, 2);
    const Image without = sppmLayers(s, {}, 16, 2);
    for (int y = 0; y < with.height; ++y)
        for (int x = 0; x < with.width; ++x) ASSERT_EQ(beautyAt(with, x, y), beautyAt(without, x, y)) << x << "," << y;
}

TEST(SppmLightPathAovs, AreBitIdenticalAtAnyThreadCountAndInTiles) {
    const Layers cover = byFirstEvent();
    const render::SceneDescription desc = everyKindOfEvent();
    const Image one = sppmLayers(desc, cover, 16, 2, 1);
    EXPECT_EQ(one.pixels, sppmLayers(desc, cover, 16, 2, 4).pixels);
    const auto tile = [&](int threads) {  // the right half of the image
        const render::RenderScene scene(desc);
        const render::Camera camera(*desc.camera, 16, 16);
        Film film(8, 16, camera.farClip(), namesOf(cover));
        RenderSettings settings;
        settings.samplesPerPixel = 2;
        settings.threads = threads;
        settings.windowX = 8;
        settings.imageWidth = 16;
        render(scene, camera, Sppm(withLayers(cover), kFewPhotons), settings, film);
        return film.resolve();
    };
    const Image right = tile(1);
    EXPECT_EQ(right.pixels, tile(3).pixels);
    for (int y = 0; y < right.height; ++y)
        for (int x = 0; x < right.width; ++x)
            for (std::size_t c = 0; c < right.channels.size(); ++c)
                ASSERT_EQ(right.pixel(x, y)[c], one.pixel(x + 8, y)[c]) << x << "," << y << " channel " << c;
}

// C.{70}L's automaton counts 70 events: more states than a photon's 64-bit set holds.
TEST(SppmLightPathAovs, RefusesAnExpressionPhotonsCannotCarryByName) {
    try {
        Sppm sppm(withLayers({{"long", "C.{70}L"}, {"short", "C.*L"}}));
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("long"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("C.{70}L"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(Sppm(withLayers({{"short", "C.*L"}})));
}

}  // namespace
}  // namespace fluence::integrators
