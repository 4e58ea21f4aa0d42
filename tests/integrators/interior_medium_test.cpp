// Media inside closed surfaces (render::MaterialDesc::interior, integrators/medium_stack.h): which
// medium a path is in as it crosses surfaces; Beer-Lambert inside a glass cube against the closed
// form of its internal reflections; and a white furnace, where a glass sphere full of a chromatic,
// anisotropic, albedo-1 medium must neither lose nor gain light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrators/medium_stack.h"
#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::integrators {
namespace {

// 2 integrators x 3 channels (cube) + 3 channels (furnace) + 3 channels (light inside) checks,
// family-wide 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(12));

render::MaterialDesc glassWithInterior(const media::MediumProperties& interior) {
    render::MaterialDesc m;
    m.name = "/Glass";
    m.specular = 1.0f;
    m.transmission = 1.0f;
    m.roughness = 0.0f;
    m.ior = 1.5f;
    m.interior = interior;
    return m;
}

render::SceneDescription inAWhiteSky(render::MeshDesc mesh, render::MaterialDesc material) {
    render::SceneDescription s;
    s.materials.push_back(std::move(material));
    s.meshes.push_back(std::move(mesh));
    s.lights.push_back(test::domeLight("/Sky", RGB(1.0f)));
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(MediumStack, EntersAgainstTheNormalLeavesAlongItAndNests) {
    render::SceneDescription desc =
        inAWhiteSky(test::boxMesh(Vec3f(1.0f), 0), glassWithInterior({RGB(1.0f), RGB(0.0f)}));
    desc.materials.push_back(glassWithInterior({RGB(2.0f), RGB(0.0f)}));
    render::RenderScene scene(desc);
    ASSERT_TRUE(scene.hasMedia());
    render::SurfaceHit glass, liquid;
    glass.geometricNormal = liquid.geometricNormal = Vec3f(0.0f, 0.0f, 1.0f);
    glass.interior = 0;
    liquid.interior = 1;
    const Vec3f down(0.0f, 0.0f, -1.0f), up(0.0f, 0.0f, 1.0f);  // wo above, wi below: entering

    MediumStack outside(scene);
    EXPECT_EQ(outside.medium(), nullptr) << "no volumes: empty space outside";
    EXPECT_EQ(outside.after(glass, up, up).medium(), nullptr) << "a reflection stays outside";
    MediumStack inGlass = outside.after(glass, up, down);
    EXPECT_EQ(inGlass.medium(), scene.mediumInside(0));
    MediumStack inLiquid = inGlass.after(liquid, up, down);
    EXPECT_EQ(inLiquid.medium(), scene.mediumInside(1)) << "the innermost interior fills space";
    EXPECT_EQ(inLiquid.after(liquid, down, up).medium(), scene.mediumInside(0)) << "back into the glass";
    // Leaving the glass through a point where the liquid pokes out of it: still in the liquid.
    EXPECT_EQ(inLiquid.after(glass, down, up).medium(), scene.mediumInside(1));
    EXPECT_EQ(inLiquid.after(glass, down, up).after(liquid, down, up).medium(), nullptr);
    render::SurfaceHit opaque = glass;
    opaque.interior = -1;
    EXPECT_EQ(inGlass.after(opaque, up, down).depth(), 1) << "surfaces without interiors change nothing";
}

TEST(InteriorMedium, AbsorbingGlassCubeMatchesItsInternalReflections) {
    // Seen head-on, a glass cube of side L whose interior absorbs sigmaA: at normal incidence the
    // ray bounces between the front and back faces only, each reflecting F = ((n - 1) / (n + 1))^2,
    // and with a = exp(-sigmaA L) the sky of radiance 1 is seen with the geometric series of
    // test_support::glassSlabSeenHeadOn.
    // Chromatic sigmaA puts the three channels' distances on one hero's draws (spectral MIS).
    const RGB sigmaA(0.2f, 0.5f, 1.0f);
    const float side = 2.0f, F = 0.04f;
    render::RenderScene scene(
        inAWhiteSky(test::boxMesh(Vec3f(side / 2.0f), 0), glassWithInterior({sigmaA, RGB(0.0f)})));
    const render::Ray ray{{0.1f, -5.0f, 0.2f}, {0.0f, 1.0f, 0.0f}};
    const PathTracer path{IntegratorSettings{}};
    const NaivePathTracer naive{IntegratorSettings{}};
    for (const Integrator* tracer : {static_cast<const Integrator*>(&path), static_cast<const Integrator*>(&naive)}) {
        std::array<test::MeanEstimate, 3> e = test_support::radianceAlong(*tracer, scene, ray, 100000, 5);
        for (int c = 0; c < 3; ++c) {
            const double expected = test_support::glassSlabSeenHeadOn(F, std::exp(-sigmaA[c] * side));
            std::printf("[ measured ] channel %d: %.5f +- %.5f (expected %.5f)\n", c, e[c].mean(), e[c].standardError(),
                        expected);
            EXPECT_NEAR(e[c].mean(), expected, kZ * e[c].standardError() + 1e-5) << "channel " << c;
        }
    }
}

TEST(InteriorMedium, AlbedoOneInteriorFurnaceNeitherLosesNorGainsLight) {
    // A smooth glass sphere (round shading normals, as in material_furnace_test.cpp) filled with a
    // scattering, non-absorbing medium, chromatic and forward-scattering, in a sky of radiance 1:
    // every path leaves with its weight, so every channel reads 1.
    render::SceneDescription desc = test::furnaceScene(1.0f);
    desc.materials[0] = glassWithInterior({RGB(0.0f), RGB(3.0f, 1.0f, 0.3f), RGB(0.0f), 0.6f});
    test::addRoundNormals(desc.meshes[0]);
    test_support::Rendered r = test_support::renderWith(PathTracer(IntegratorSettings{}), desc, 48, 128);
    const int alpha = r.image.channelIndex("A");
    for (int c = 0; c < 3; ++c) {
        test::MeanEstimate reading =
            test_support::channelMean(r.image, c, [&](const float* p) { return p[alpha] == 1.0f; });
        std::printf("[ measured ] channel %d: %.5f +- %.5f over %d pixels\n", c, reading.mean(),
                    reading.standardError(), reading.count());
        ASSERT_GT(reading.count(), 100);
        EXPECT_NEAR(reading.mean(), 1.0, kZ * reading.standardError()) << "channel " << c;
    }
}

TEST(InteriorMedium, LightInsideAScatteringInteriorAgreesWithTheNaiveReference) {
    // A sphere light inside a glass ball full of a chromatic, absorbing, scattering medium: `path`
    // samples no light at scatterings inside (the ball's surface would block the shadow rays of
    // every light outside) and counts the light hit by phase sampling at full weight, while it
    // still samples the light from the glass surface. `naive` only ever hits it. Both estimate
    // the same radiance along a ray through the ball.
    render::SceneDescription desc =
        inAWhiteSky(test::roundSphereMesh(1.0f, 48, 24, 0),
                    glassWithInterior({RGB(0.1f, 0.2f, 0.4f), RGB(1.5f, 1.0f, 0.5f), RGB(0.0f), 0.3f}));
    desc.lights[0].radiance = RGB(0.0f);  // the sky stays dark; only the light inside shines
    desc.lights.push_back(test::sphereLight("/Bulb", 0.2f, RGB(10.0f)));
    render::RenderScene scene(desc);
    const render::Ray ray{{0.3f, -5.0f, 0.1f}, {0.0f, 1.0f, 0.0f}};
    std::array<test::MeanEstimate, 3> path =
        test_support::radianceAlong(PathTracer(IntegratorSettings{}), scene, ray, 40000, 5);
    std::array<test::MeanEstimate, 3> naive =
        test_support::radianceAlong(NaivePathTracer(IntegratorSettings{}), scene, ray, 40000, 5);
    for (int c = 0; c < 3; ++c) {
        const double difference = path[c].mean() - naive[c].mean();
        const double error = std::hypot(path[c].standardError(), naive[c].standardError());
        std::printf("[ measured ] channel %d: path %.5f +- %.5f, naive %.5f +- %.5f\n", c, path[c].mean(),
                    path[c].standardError(), naive[c].mean(), naive[c].standardError());
        EXPECT_GT(path[c].mean(), 0.0) << "the light inside shines through";
        EXPECT_NEAR(difference, 0.0, kZ * error) << "channel " << c;
    }
}

}  // namespace
}  // namespace fluence::integrators
