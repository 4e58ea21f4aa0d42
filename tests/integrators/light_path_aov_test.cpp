// Light path expression AOVs of the path tracer (integrators/light_path_tracker.h): layers of a
// disjoint cover of every path sum to the beauty, sample by sample; the diffuse first bounce is
// exactly what a one-bounce render adds to the emitters; the diffuse and glossy layers of a
// plastic floor match a plain reference estimator (light sampling of the BSDF's split); lights and
// subsurface scattering are told apart by their labels; the beauty does not change.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/sampling.h"
#include "integrators/path_tracer.h"
#include "media/subsurface_medium.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"
#include "tests/integrators/light_path_layers.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using namespace test_support;

TEST(LightPathAovs, LayersOfADisjointCoverSumToTheBeauty) {
    const Layers cover = byFirstEvent();
    expectLayersSumToBeauty(renderLayers<PathTracer>(everyKindOfEvent(), cover, 24, 16), cover);
}

TEST(LightPathAovs, LightLabelsSplitTheBeautyByLight) {
    const Layers lights = byLight();
    expectLayersSumToBeauty(renderLayers<PathTracer>(everyKindOfEvent(), lights, 24, 16), lights);
}

TEST(LightPathAovs, SubsurfaceEventsAreLabelled) {
    const Layers bySubsurface = bySubsurfaceOrNot();
    render::SceneDescription walk = everyKindOfEvent();
    expectLayersSumToBeauty(renderLayers<PathTracer>(walk, bySubsurface, 24, 16), bySubsurface);
    render::SceneDescription diffusion = walk;
    diffusion.materials[3].subsurfaceMethod = render::SubsurfaceMethod::Diffusion;
    expectLayersSumToBeauty(renderLayers<PathTracer>(diffusion, bySubsurface, 24, 16), bySubsurface);
    // Guided walks, three from each entry (PathTracer's subsurface-walks): the other walks' light counts.
    render::SceneDescription guided = walk;
    guided.materials[3].subsurfaceMethod = render::SubsurfaceMethod::RandomWalkGuided;
    IntegratorSettings split = withLayers(bySubsurface);
    split.parameters["subsurface-walks"] = 3;
    expectLayersSumToBeauty(renderLayersBy(PathTracer(split), guided, bySubsurface, 24, 16), bySubsurface);
}

// On Lambertian surfaces (one lobe kind), the light that arrives after one diffuse reflection is
// what a render with at most one bounce adds to the emitters seen, sample by sample (the same
// random numbers decide the first vertex in both).
TEST(LightPathAovs, DiffuseFirstBounceIsWhatOneBounceAdds) {
    render::SceneDescription s = everyKindOfEvent();
    for (render::MaterialDesc& m : s.materials) {
        const RGB emission = m.emission;
        m = test::diffuseMaterial(m.name, RGB(0.5f), emission);
    }
    const Layers layers = {{"seen", "C[LO]"}, {"bounce", "C<RD>[LO]"}};
    const Image full = renderLayers<PathTracer>(s, layers, 16, 8);
    const Image oneBounce = renderLayers<PathTracer>(s, {}, 16, 8, 1);
    for (int y = 0; y < full.height; ++y)
        for (int x = 0; x < full.width; ++x) {
            const RGB expected = beautyAt(oneBounce, x, y),
                      got = layerAt(full, "seen", x, y) + layerAt(full, "bounce", x, y);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(got[c], expected[c], 1e-5f * expected[c] + 1e-7f) << x << "," << y;
        }
}

// A plastic floor lit by a rect light: along one camera ray, the direct diffuse and direct glossy
// layers against a plain estimator of the same integrals, integral f_kind(wo, wi) L cos dwi, by
// sampling the light's area uniformly.
TEST(LightPathAovs, DiffuseAndGlossyLayersMatchAPlainLightSamplingEstimate) {
    render::SceneDescription s;
    s.materials.push_back(plastic("/plastic", RGB(0.5f, 0.4f, 0.3f), 0.35f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}}}, 0));
    const RGB Le(5.0f);
    const Vec3f lightCentre(0.3f, 0.5f, 1.0f);
    s.lights.push_back(test::rectLight("/key", 1.0f, 1.0f, Le, Matrix4::translate(Vec3d(lightCentre))));
    const render::RenderScene scene(s);

    // The camera ray: from (0, -2, 1.5) to the origin, which sees the light's glossy reflection nearby.
    const Vec3f eye(0.0f, -2.0f, 1.5f);
    const render::Ray ray{eye, normalize(-eye), 0.0f, 1e30f};
    const Layers layers = {{"diffuse", "C<RD>L"}, {"glossy", "C<RG>L"}};
    const PathTracer integrator(withLayers(layers));
    const render::Camera camera(render::CameraDesc{}, 8, 8);
    const std::unique_ptr<RenderState> state = integrator.prepare(scene, camera, 0, nullptr);
    constexpr int kSamples = 200'000;
    std::array<std::array<test::MeanEstimate, 3>, 2> tracer;
    RenderCounters counters;
    for (int i = 0; i < kSamples; ++i) {
        SampleStream rng(7, 0, std::uint64_t(i));
        const FilmSample fs = integrator.sample(*state, scene, camera, ray, rng, counters);
        for (int l = 0; l < 2; ++l)
            for (int c = 0; c < 3; ++c) tracer[l][c].add(fs.lightPath(std::size_t(l))[c]);
    }

    // The reference: the BSDF at the origin (shading frame = world, z up), the light's area sampled
    // uniformly (it faces down, local -Z), no occluders.
    render::BsdfArena arena;
    const render::Bsdf& bsdf = render::materialBsdf(s.materials[0], arena);
    const Vec3f wo = normalize(eye);
    std::array<std::array<test::MeanEstimate, 3>, 2> reference;
    for (int i = 0; i < kSamples; ++i) {
        SampleStream rng(8, 0, std::uint64_t(i));
        const Vec2f u = rng.next2D();
        const Vec3f p = lightCentre + Vec3f(u.x - 0.5f, u.y - 0.5f, 0.0f);
        const float d2 = dot(p, p);
        const Vec3f wi = p / std::sqrt(d2);
        const float geometry = wi.z * wi.z / d2;  // cos at the floor x cos at the light / d^2, area 1
        const render::LobeSplit split = bsdf.fByKind(wo, wi);
        for (int c = 0; c < 3; ++c) {
            reference[0][c].add(split.diffuse[c] * Le[c] * geometry);
            reference[1][c].add(split.glossy[c] * Le[c] * geometry);
        }
    }
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(6));
    for (int l = 0; l < 2; ++l)
        for (int c = 0; c < 3; ++c) {
            const double se = std::hypot(tracer[l][c].standardError(), reference[l][c].standardError());
            EXPECT_GT(reference[l][c].mean(), 10.0 * se)
                << layers[std::size_t(l)].first << ": too little light to test";
            EXPECT_NEAR(tracer[l][c].mean(), reference[l][c].mean(), z * se)
                << layers[std::size_t(l)].first << " channel " << c;
        }
}

TEST(LightPathAovs, BeautyIsTheSameWithAndWithoutLayers) {
    const render::SceneDescription s = everyKindOfEvent();
    const Image with = renderLayers<PathTracer>(s, {{"diffuse", "C<RD>.*L"}, {"all", "C.*"}}, 16, 4);
    const Image without = renderLayers<PathTracer>(s, {}, 16, 4);
    for (int y = 0; y < with.height; ++y)
        for (int x = 0; x < with.width; ++x) {
            const RGB a = beautyAt(with, x, y), b = beautyAt(without, x, y);
            for (int c = 0; c < 3; ++c) ASSERT_EQ(a[c], b[c]) << x << "," << y;
        }
}

}  // namespace
}  // namespace fluence::integrators
