// Shared by the light path expression AOV tests of every integrator that writes them: layers
// given as (name, expression), a render that resolves them, a scene with every kind of event, and
// the check that the layers of a disjoint cover of every path sum to the beauty.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "integrators/integrator.h"
#include "integrators/light_path_tracker.h"
#include "integrators/renderer.h"
#include "media/subsurface_medium.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace fluence::integrators::test_support {

using Layers = std::vector<std::pair<std::string, std::string>>;  // name, expression

inline IntegratorSettings withLayers(const Layers& layers, int maxDepth = 64) {
    auto aovs = std::make_shared<std::vector<LightPathAov>>();
    for (const auto& [name, expression] : layers) aovs->push_back({name, LightPathExpression(expression)});
    IntegratorSettings s;
    s.maxDepth = maxDepth;
    s.lightPathAovs = std::move(aovs);
    return s;
}

inline std::vector<std::string> namesOf(const Layers& layers) {
    std::vector<std::string> names;
    for (const auto& layer : layers) names.push_back(layer.first);
    return names;
}

// A size x size render of `desc` by `integrator` (made with withLayers(layers)) with the layers,
// resolved; `threads` and `seed` as RenderSettings's.
inline Image renderLayersBy(const Integrator& integrator, const render::SceneDescription& desc, const Layers& layers,
                            int size, int spp, int threads = 0, std::uint64_t seed = 0) {
    render::RenderScene scene(desc);
    render::Camera camera(*desc.camera, size, size);
    Film film(size, size, camera.farClip(), namesOf(layers));
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.threads = threads;
    settings.seed = seed;
    render(scene, camera, integrator, settings, film);
    return film.resolve();
}

// The same by Method, constructed from withLayers(layers, maxDepth) and `extra`.
template <class Method, class... Extra>
Image renderLayers(const render::SceneDescription& desc, const Layers& layers, int size, int spp, int maxDepth = 64,
                   int threads = 0, std::uint64_t seed = 0, const Extra&... extra) {
    return renderLayersBy(Method(withLayers(layers, maxDepth), extra...), desc, layers, size, spp, threads, seed);
}

inline render::MaterialDesc plastic(std::string name, const RGB& colour, float roughness) {
    render::MaterialDesc m = test::diffuseMaterial(std::move(name), colour);
    m.specular = 1.0f;
    m.roughness = roughness;
    return m;
}

// Every kind of event Fluence labels: a plastic floor (D and G lobes), a rough metal ball (G), a
// smooth glass ball with a scattering interior (T S, V), a subsurface ball, an emissive panel (O),
// a rect light, a sphere light and a dome (L).
inline render::SceneDescription everyKindOfEvent() {
    render::SceneDescription s;
    s.materials.push_back(plastic("/plastic", RGB(0.6f, 0.5f, 0.4f), 0.4f));
    s.materials.push_back(test::metalMaterial("/metal", RGB(0.9f, 0.7f, 0.5f), 0.3f));
    render::MaterialDesc murky = test::glassMaterial("/murky", 0.0f);
    murky.interior = media::MediumProperties{RGB(0.2f), RGB(1.5f, 1.0f, 0.5f), RGB(0.0f), 0.3f};
    s.materials.push_back(murky);
    render::MaterialDesc skin;
    skin.name = "/skin";
    skin.subsurface = 1.0f;
    skin.subsurfaceColor = RGB(0.9f, 0.5f, 0.3f);
    skin.specular = 0.0f;
    skin.interior = media::subsurfaceMedium(skin.subsurfaceColor, RGB(0.1f), 0.0f);
    s.materials.push_back(skin);
    s.materials.push_back(test::diffuseMaterial("/panel", RGB(0.0f), RGB(3.0f, 2.0f, 1.0f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.4f, 32, 16, 1, Vec3f(-0.6f, 0.0f, -0.55f)));
    s.meshes.push_back(test::roundSphereMesh(0.4f, 32, 16, 2, Vec3f(0.6f, 0.0f, -0.55f)));
    s.meshes.push_back(test::roundSphereMesh(0.35f, 32, 16, 3, Vec3f(0.0f, 0.9f, -0.6f)));
    s.meshes.push_back(test::quadMesh("/panel", {{{-1, 2, -1}, {1, 2, -1}, {1, 2, 0}, {-1, 2, 0}}}, 4));
    s.lights.push_back(test::rectLight("/lights/key", 1.0f, 1.0f, RGB(8.0f), Matrix4::translate({0.0, 0.0, 2.0})));
    s.lights.push_back(test::sphereLight("/lights/fill", 0.2f, RGB(10.0f, 10.0f, 12.0f), Vec3d(-2.0, -1.0, 1.0)));
    s.lights.push_back(test::domeLight("/lights/sky", RGB(0.1f)));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// A diffuse floor and back wall lit by a rect light and a point light: no path has a singular event.
inline render::SceneDescription diffuseOnly() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.7f, 0.6f, 0.5f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/back", {{{-3, 1, -1}, {3, 1, -1}, {3, 1, 3}, {-3, 1, 3}}}, 0));
    s.lights.push_back(test::rectLight("/key", 1.0f, 1.0f, RGB(8.0f), Matrix4::translate({0.0, 0.0, 1.5})));
    s.lights.push_back(test::pointLight("/point", RGB(20.0f), Vec3d(1.0, -0.5, 0.5)));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// Disjoint covers of every path: paths through a medium, then the others by their first event;
// by the light they end on (everyKindOfEvent's); and by whether they scatter below a subsurface
// material's surface.
inline Layers byFirstEvent() {
    return {{"emission", "C[LO]"},
            {"volume", "C.*V.*[LO]"},
            {"diffuse", "C<RD>[^V]*[LO]"},
            {"glossy", "C<R[GS]>[^V]*[LO]"},
            {"transmission", "C<T.>[^V]*[LO]"}};
}
inline Layers byLight() {
    return {{"key", "C.*<L.'key'>"}, {"fill", "C.*<L.'fill'>"}, {"sky", "C.*<L.'sky'>"}, {"panel", "C.*O"}};
}
inline Layers bySubsurfaceOrNot() {
    return {{"subsurface", "C.*'subsurface'.*[LO]"}, {"other", "C[^'subsurface']*[LO]"}};
}

inline RGB layerAt(const Image& image, const std::string& layer, int x, int y) {
    const float* p = image.pixel(x, y);
    return RGB(p[image.channelIndex(layer + ".R")], p[image.channelIndex(layer + ".G")],
               p[image.channelIndex(layer + ".B")]);
}
inline RGB beautyAt(const Image& image, int x, int y) {
    const float* p = image.pixel(x, y);
    return RGB(p[image.channelIndex("R")], p[image.channelIndex("G")], p[image.channelIndex("B")]);
}

// Per pixel and channel, the layers sum to the beauty up to float rounding (each sample's layers
// are its beauty's terms, split), and every layer holds some light.
inline void expectLayersSumToBeauty(const Image& image, const Layers& layers) {
    std::vector<double> layerTotal(layers.size(), 0.0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const RGB beauty = beautyAt(image, x, y);
            RGB sum(0.0f);
            for (std::size_t l = 0; l < layers.size(); ++l) {
                const RGB v = layerAt(image, layers[l].first, x, y);
                sum += v;
                layerTotal[l] += luminance(v);
            }
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(sum[c], beauty[c], 1e-5f * beauty[c] + 1e-7f)
                    << "pixel " << x << "," << y << " channel " << c;
        }
    for (std::size_t l = 0; l < layers.size(); ++l) EXPECT_GT(layerTotal[l], 0.0) << layers[l].first << " is empty";
}

}  // namespace fluence::integrators::test_support
