// Stability where methods fail (issue #10): every registered integrator renders scenes built to
// break estimators — degenerate, coincident and inside-out geometry, a tiny and very bright light,
// glossy-to-glossy chains, a point light's caustic through glass, a dense albedo-0.99 interior —
// and no sample may be NaN or infinite (RenderCounters::nonFiniteSamples counts the ones the
// renderer had to discard) and every pixel must be finite.
// The suite's USD scenes (bench/stability/, which the benchmark renders in full) are rendered by
// tests/apps/stability_scenes_test.cpp, which can read them through the delegate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "integrators/integrator.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

struct StressScene {
    std::string name;
    render::SceneDescription scene;
};

// A floor with degenerate triangles (zero area, collinear corners), two coincident quads, and a
// box turned inside out (its winding reversed and its shading normals pointing in), lit by a rect
// light and a dome.
render::SceneDescription brokenGeometry() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.6f)));
    s.materials.push_back(test::metalMaterial("/metal", RGB(0.9f), 0.2f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/twin", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 1));
    render::MeshDesc degenerate;
    degenerate.name = "/degenerate";
    degenerate.positions = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 0.5f}, {0.5f, 0, 0.5f}, {1, 0, 0.5f}};
    degenerate.indices = {0, 1, 2, 3, 4, 5};  // a zero-area triangle and a collinear one
    s.meshes.push_back(degenerate);
    render::MeshDesc insideOut = test::boxMesh(Vec3f(0.4f), 0);
    for (std::size_t t = 0; t + 2 < insideOut.indices.size(); t += 3)
        std::swap(insideOut.indices[t + 1], insideOut.indices[t + 2]);
    for (std::uint32_t i : insideOut.indices) insideOut.cornerNormals.push_back(-normalize(insideOut.positions[i]));
    s.meshes.push_back(insideOut);
    s.lights.push_back(test::rectLight("/light", 1.0f, 1.0f, RGB(10.0f), Matrix4::translate({0.0, 0.0, 2.0})));
    s.lights.push_back(test::domeLight("/sky", RGB(0.2f)));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// Two facing rough mirrors and a smooth one between them, lit by a tiny, very bright sphere light
// (radius 1e-3, radiance 1e7: fireflies) and a point light.
render::SceneDescription glossyChainsAndATinyLight() {
    render::SceneDescription s;
    s.materials.push_back(test::metalMaterial("/rough", RGB(0.95f), 0.05f));
    s.materials.push_back(test::metalMaterial("/smooth", RGB(0.95f), 0.0f));
    s.meshes.push_back(test::quadMesh("/left", {{{-1, -2, -1}, {-1, -2, 1}, {-1, 2, 1}, {-1, 2, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/right", {{{1, -2, -1}, {1, 2, -1}, {1, 2, 1}, {1, -2, 1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.3f, 24, 12, 1));
    s.lights.push_back(test::sphereLight("/spark", 1e-3f, RGB(1e7f), {0.5, 0.5, 0.5}));
    s.lights.push_back(test::pointLight("/point", RGB(20.0f), {-0.5, -0.5, 0.8}));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// A smooth glass ball on a diffuse floor under a point light: the caustic only photons find.
render::SceneDescription pointLightCaustic() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/floor", RGB(0.7f)));
    s.materials.push_back(test::glassMaterial("/glass", 0.0f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.5f, 32, 16, 1));
    s.lights.push_back(test::pointLight("/point", RGB(30.0f), {0.3, 0.2, 2.0}));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// A glass ball filled with a dense, albedo-0.99 medium (hundreds of scatterings per path).
render::SceneDescription denseHighAlbedoInterior() {
    render::SceneDescription s = test::furnaceScene(1.0f);
    render::MaterialDesc glass = test::glassMaterial("/milk", 0.0f);
    glass.interior = media::MediumProperties{RGB(0.2f), RGB(19.8f), RGB(0.0f), 0.3f};
    s.materials[0] = glass;
    return s;
}

TEST(Stability, NoMethodMakesANaNOrInfinityWhereMethodsFail) {
    const StressScene scenes[] = {{"broken geometry", brokenGeometry()},
                                  {"glossy chains and a tiny light", glossyChainsAndATinyLight()},
                                  {"point-light caustic", pointLightCaustic()},
                                  {"dense albedo-0.99 interior", denseHighAlbedoInterior()}};
    for (const IntegratorInfo& info : integratorRegistry())
        for (const StressScene& stress : scenes) {
            const std::unique_ptr<Integrator> integrator = info.create(IntegratorSettings{});
            test_support::Rendered r = test_support::renderWith(*integrator, stress.scene, 16, 16);
            std::uint64_t nonFinitePixels = 0;
            for (float v : r.image.pixels) nonFinitePixels += !std::isfinite(v);
            std::printf("[ measured ] %-9s %-32s %llu non-finite samples\n", info.name.c_str(), stress.name.c_str(),
                        static_cast<unsigned long long>(r.stats.counters.nonFiniteSamples));
            EXPECT_EQ(r.stats.counters.nonFiniteSamples, 0u) << info.name << " on " << stress.name;
            EXPECT_EQ(nonFinitePixels, 0u) << info.name << " on " << stress.name;
        }
}

}  // namespace
}  // namespace fluence::integrators
