// `bdpt` (integrators/bdpt.h): its MIS weights sum to one over the strategies of a path; the
// emission samplers that start its light subpaths report the densities they draw with; it agrees
// with `path` within their combined noise (per channel over the image, and region by region) on
// a diffuse box lit by an area light, a glossy and metal scene, glass, a scene of delta lights, an
// emissive mesh and a cylinder light, and a white furnace, which it renders as 1; its images are
// the same at any thread count; and it finds the light of a point light's caustic, once that
// lights another surface, which `path` cannot. Light tracing (t = 1): its MIS weights take the
// power heuristic against the camera strategies; it finds a point light's caustic seen directly,
// as `path` does with a small sphere light in its place, which bdpt without t = 1 misses; its
// splats are bit-identical at any thread count (with adaptive sampling too); tiles and orthographic
// cameras leave it out and say so. With media: its spectral MIS weights sum to one over
// heroes and strategies; it agrees with `path` in a chromatic scattering volume (isotropic and
// forward-scattering) lit by an area light, around a light inside a scattering interior, and on a
// subsurface random-walk object; it matches Beer-Lambert's closed form through absorbing glass;
// a chromatic albedo-1 volume under a white sky reads 1; and it is bit-identical at any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrators/bdpt.h"
#include "integrators/bdpt_mis.h"
#include "integrators/bdpt_vertex.h"
#include "integrators/path_tracer.h"
#include "render/lights/disk_light.h"
#include "render/lights/distant_light.h"
#include "render/lights/dome_light.h"
#include "render/lights/point_light.h"
#include "render/lights/rect_light.h"
#include "render/lights/sphere_light.h"
#include "render/lights/triangle_light.h"
#include "tests/integrators/bdpt_agreement.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"
#include "tests/support/subsurface_material.h"
#include "tests/support/temp_dir.h"
#include "tests/volumes/vdb_test_files.h"

namespace fluence::integrators {
namespace {

using namespace bdpt_agreement;

// A cone of `angle` degrees and `softness`, unfocused, with no IES profile.
render::LightShapingDesc spotCone(float angle, float softness) {
    render::LightShapingDesc shaping;
    shaping.coneAngleDegrees = angle;
    shaping.coneSoftness = softness;
    return shaping;
}

// ---- MIS weights.

TEST(BdptMis, WeightsSumToOneOverTheStrategiesOfAPath) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> density(0.01f, 10.0f);
    std::bernoulli_distribution deltaVertex(0.2), hittable(0.8);
    for (int trial = 0; trial < 2000; ++trial) {
        const int vertices = 3 + trial % 8;  // x_0 ... x_k, k >= 2
        std::vector<VertexDensity> x(vertices);
        for (int i = 0; i < vertices; ++i)
            x[i] = {density(random), density(random), i > 0 && i < vertices - 1 && deltaVertex(random)};
        if (trial % 5 == 0) x[0].fromLight = 0.0f;  // a light without emission sampling
        // Half the paths with light tracing (t = 1, s = k) among their strategies.
        StrategyPath path{x, density(random), hittable(random), -1, trial % 2 == 1};
        double sum = 0.0;
        int strategies = 0;
        for (int s = 0; s + 1 <= vertices; ++s)
            if (strategyExists(path, s) && (s < 2 || x[0].fromLight > 0.0f)) {  // (no light subpath from such a light)
                sum += misWeight(path, s);
                ++strategies;
            }
        if (strategies > 0) {
            EXPECT_NEAR(sum, 1.0, 1e-5) << "trial " << trial;
        }
    }
}

// With media (bdpt_mis.h, SPECTRAL MIS), misWeight / 3 is the weight of the technique (hero h,
// strategy s): over the heroes that can draw the path and its strategies, they sum to one.
TEST(BdptMis, SpectralWeightsSumToOneOverHeroesAndStrategies) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> density(0.01f, 10.0f), depth(0.0f, 3.0f), sigma(0.1f, 4.0f);
    std::bernoulli_distribution deltaVertex(0.2), mediumVertex(0.4), walking(0.1), opaque(0.1);
    for (int trial = 0; trial < 2000; ++trial) {
        const int vertices = 3 + trial % 8;
        std::vector<VertexDensity> x(vertices);
        for (int i = 0; i < vertices; ++i) {
            const bool inner = i > 0 && i < vertices - 1;
            x[i] = {density(random), density(random), inner && deltaVertex(random), !(inner && walking(random))};
            if (inner && mediumVertex(random)) x[i].sigmaS = RGB(sigma(random), sigma(random), sigma(random));
            if (i > 0) x[i].edge.majorantDepth = RGB(depth(random), depth(random), depth(random));
        }
        // Channel 2 sometimes does not scatter at a medium vertex: hero 2 cannot draw the path.
        bool heroTwoBlind = false;
        if (trial % 3 == 0)
            for (int i = 1; i + 1 < vertices; ++i)
                if (x[i].sigmaS != RGB(1.0f)) {
                    x[i].sigmaS.z = 0.0f;
                    heroTwoBlind = true;
                    break;
                }
        // Ratio tracking in channel 1 sometimes cannot draw an edge's null points.
        if (trial % 4 == 1 && opaque(random)) x[1].edge.joinPossible.y = 0.0f;
        double sum = 0.0;
        const bool lightTracing = trial % 2 == 0;  // t = 1 among the strategies
        for (int hero = 0; hero < 3; ++hero) {
            if (hero == 2 && heroTwoBlind) continue;
            const StrategyPath path{x, 1.7f, true, hero, lightTracing};
            for (int s = 0; s + 1 <= vertices; ++s) {
                const bool drawable = !(hero == 1 && s == 1 && x[1].edge.joinPossible.y == 0.0f);
                if (strategyExists(path, s) && drawable) sum += misWeight(path, s) / 3.0;
            }
        }
        EXPECT_NEAR(sum, 1.0, 1e-4) << "trial " << trial;
    }
}

TEST(BdptMis, TwoStrategiesTakeThePowerHeuristic) {
    // x_0 on a light, x_1 a diffuse point, x_2 the camera: s = 0 (density x_0.fromCamera) against
    // s = 1 (next-event estimation, density neeOrigin).
    std::vector<VertexDensity> x = {{0.5f, 2.0f, false}, {3.0f, 4.0f, false}, {1.0f, 1.0f, false}};
    StrategyPath path{x, 1.5f, true};
    EXPECT_FLOAT_EQ(misWeight(path, 0), 4.0f / (4.0f + 2.25f));
    EXPECT_FLOAT_EQ(misWeight(path, 1), 2.25f / (4.0f + 2.25f));
    // A delta light cannot be hit: next-event estimation alone.
    path.lightHittable = false;
    EXPECT_FALSE(strategyExists(path, 0));
    EXPECT_FLOAT_EQ(misWeight(path, 1), 1.0f);
    // With light tracing, a light seen directly (k = 1) is still left to s = 0.
    std::vector<VertexDensity> seen = {{0.5f, 2.0f, false}, {1.0f, 1.0f, false}};
    EXPECT_FALSE(strategyExists(StrategyPath{seen, 0.0f, true, -1, true}, 1));
}

// Light tracing (t = 1, s = k) against the join at the camera's first vertex (t = 2, s = k - 1):
// x_{k-1} is drawn by the light subpath with density fromLight, by the camera with fromCamera.
TEST(BdptMis, LightTracingTakesThePowerHeuristicAgainstTheCameraStrategies) {
    // x_0 on a delta light (no s = 0), x_1 a diffuse point seen by the camera x_2: s = 1
    // (next-event estimation, neeOrigin) against s = 2 (light tracing, x_0.fromLight x_1.fromLight).
    std::vector<VertexDensity> x = {{0.5f, 0.0f, false}, {3.0f, 4.0f, false}, {1.0f, 1.0f, false}};
    StrategyPath path{x, 0.5f, false, -1, true};
    ASSERT_TRUE(strategyExists(path, 2));
    const double nee = 0.5 * 4.0, tracing = 0.5 * 3.0;  // the densities of x_0 x_1 under s = 1 and s = 2
    EXPECT_FLOAT_EQ(misWeight(path, 1), float(nee * nee / (nee * nee + tracing * tracing)));
    EXPECT_FLOAT_EQ(misWeight(path, 2), float(tracing * tracing / (nee * nee + tracing * tracing)));
    // A delta x_1 (a mirror before the camera) cannot be joined to the camera.
    x[1].delta = true;
    EXPECT_FALSE(strategyExists(path, 2));
}

// ---- Emission sampling (each light's sampleEmission, render/lights/), which light subpaths start from.

// Each light's sampleEmission() reports the densities emissionDensity() gives for its point and
// direction, and only points and directions that carry light.
TEST(BdptEmission, SampledDensitiesMatchEmissionDensity) {
    auto desc = [](render::LightType type) {
        return test::lightDesc("/light", type, RGB(2.0f), Matrix4::translate({0.5, -0.2, 1.0}) * Matrix4::rotateX(30));
    };
    render::LightDesc spot = desc(render::LightType::Sphere);
    spot.treatAsPoint = true;
    spot.shaping = spotCone(40.0f, 0.5f);
    render::LightDesc sun = desc(render::LightType::Distant);
    sun.angleDegrees = 5.0f;
    std::vector<std::unique_ptr<render::Light>> lights;
    lights.push_back(std::make_unique<render::RectLight>(desc(render::LightType::Rect)));
    lights.push_back(std::make_unique<render::DiskLight>(desc(render::LightType::Disk)));
    lights.push_back(
        std::make_unique<render::TriangleLight>("/mesh", Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0.5f), RGB(1.0f)));
    lights.push_back(std::make_unique<render::SphereLight>(desc(render::LightType::Sphere)));
    lights.push_back(std::make_unique<render::PointLight>(spot));
    lights.push_back(std::make_unique<render::DistantLight>(sun));
    lights.push_back(std::make_unique<render::DomeLight>(desc(render::LightType::Dome)));
    const render::SceneBounds bounds{Vec3f(0.0f, 0.0f, 0.5f), 3.0f};
    SampleStream rng(3, 0, 0);
    for (const auto& light : lights) {
        ASSERT_TRUE(light->hasEmissionSampling()) << light->name();
        for (int i = 0; i < 256; ++i) {
            const Vec2f uPosition = rng.next2D(), uDirection = rng.next2D();
            std::optional<render::EmissionSample> e = light->sampleEmission(uPosition, uDirection, bounds);
            ASSERT_TRUE(e.has_value()) << light->name();
            const render::EmissionDensity d = light->emissionDensity(e->point, e->direction, bounds);
            EXPECT_NEAR(d.position, e->density.position, 1e-4f * e->density.position) << light->name();
            EXPECT_NEAR(d.direction, e->density.direction, 1e-3f * e->density.direction) << light->name();
            EXPECT_NEAR(d.cosine, e->density.cosine, 1e-4f) << light->name();
            EXPECT_NEAR(length(e->direction), 1.0f, 1e-5f);
            EXPECT_TRUE(e->Le.x >= 0.0f && e->Le.y >= 0.0f && e->Le.z >= 0.0f && isFinite(e->Le));
        }
    }
}

// ---- Agreement with `path` (tests/integrators/bdpt_agreement.h).

TEST(Bdpt, AgreesWithPathOnADiffuseBoxLitByAnAreaLight) { expectAgreement(cornellBox(), 256, 256); }

// A rough metal sphere and a glossy plastic torus on a diffuse floor before a diffuse back wall,
// lit by a sphere light, a disk light and a dim dome.
render::SceneDescription glossyScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    s.materials.push_back(test::metalMaterial("/metal", RGB(0.9f, 0.7f, 0.4f), 0.3f));
    render::MaterialDesc plastic;
    plastic.name = "/plastic";
    plastic.diffuse = RGB(0.2f, 0.3f, 0.7f);
    plastic.roughness = 0.2f;
    s.materials.push_back(plastic);
    s.meshes.push_back(test::quadMesh("/ground", {{{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/wall", {{{-4, 1.5f, -1}, {4, 1.5f, -1}, {4, 1.5f, 3}, {-4, 1.5f, 3}}}, 0));
    render::MeshDesc sphere = test::sphereMesh(0.7f, 24, 12, 1);
    for (Vec3f& p : sphere.positions) p += Vec3f(-0.6f, 0.3f, -0.3f);
    s.meshes.push_back(sphere);
    render::MeshDesc torus = test::torusMesh(0.5f, 0.2f, 24, 12, 2);
    for (Vec3f& p : torus.positions) p += Vec3f(0.8f, -0.2f, -0.5f);
    s.meshes.push_back(torus);
    s.lights.push_back(test::sphereLight("/bulb", 0.3f, RGB(10.0f), {1.2, -1.0, 1.5}));
    s.lights.push_back(test::diskLight("/disk", 0.5f, RGB(4.0f, 3.0f, 2.0f),
                                       Matrix4::translate({-1.5, 0.5, 2.0}) * Matrix4::rotateY(-20)));
    s.lights.push_back(test::domeLight("/dome", RGB(0.1f, 0.15f, 0.3f)));
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(Bdpt, AgreesWithPathOnGlossyAndMetalSurfaces) { expectAgreement(glossyScene(), 256, 256); }

// Rough and smooth glass spheres (round shading normals, so the adjoint's shading-normal
// correction matters) and a rough thin sheet on a diffuse floor before a wall, lit by a rect light
// through the rough sphere and a sphere light behind the sheet: light subpaths refract (the
// adjoint carries eta^2 inside the glass) and transmissive surfaces are joined from both sides.
render::SceneDescription glassScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.6f)));
    s.materials.push_back(test::glassMaterial("/rough", 0.4f));
    s.materials.push_back(test::glassMaterial("/smooth", 0.0f));
    s.materials.push_back(test::thinSheetMaterial("/sheet", RGB(0.4f, 0.6f, 0.3f), 0.8f, 0.3f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/wall", {{{-3, 1.5f, -1}, {3, 1.5f, -1}, {3, 1.5f, 3}, {-3, 1.5f, 3}}}, 0));
    for (auto [material, centre] : {std::pair(1, Vec3f(-0.8f, 0.0f, -0.4f)), std::pair(2, Vec3f(0.8f, -0.2f, -0.4f))})
        s.meshes.push_back(test::roundSphereMesh(0.6f, 24, 12, material, centre));
    s.meshes.push_back(
        test::quadMesh("/sheet", {{{0.2f, 1.0f, -1}, {2.0f, 1.0f, -1}, {2.0f, 1.0f, 1.2f}, {0.2f, 1.0f, 1.2f}}}, 3));
    // Before the rough sphere, shining through it at the wall (emitting towards +Y): a rough
    // caustic in full view.
    s.lights.push_back(
        test::rectLight("/rect", 1.5f, 1.0f, RGB(8.0f), Matrix4::translate({-0.8, -1.2, -0.3}) * Matrix4::rotateX(90)));
    s.lights.push_back(test::sphereLight("/bulb", 0.2f, RGB(15.0f), {1.2, 1.3, 0.2}));  // behind the sheet
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(Bdpt, AgreesWithPathThroughGlassAndAThinSheet) { expectAgreement(glassScene(), 256, 256); }

// Delta lights, which only light sampling and light subpaths reach, and an emissive mesh: a
// spot light (a point light shaped to a soft cone, pointing down), the sun (a distant light of
// angle 0), a glowing panel (emissive triangles, emitting from both sides), and a cylinder light
// (no emission sampling: reached by the camera subpath alone), between a floor and a ceiling,
// before a back wall, with a box: much of the light is indirect.
render::SceneDescription deltaLightScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.6f)));
    s.materials.push_back(test::diffuseMaterial("/glow", RGB(0.3f), RGB(1.5f, 1.0f, 0.5f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/wall", {{{-3, 1.5f, -1}, {3, 1.5f, -1}, {3, 1.5f, 3}, {-3, 1.5f, 3}}}, 0));
    s.meshes.push_back(test::quadMesh("/ceiling", {{{-3, -3, 2.2f}, {-3, 3, 2.2f}, {3, 3, 2.2f}, {3, -3, 2.2f}}}, 0));
    s.meshes.push_back(test::boxMesh({0.4f, 0.4f, 0.6f}, 0));
    s.meshes.push_back(test::quadMesh(
        "/panel", {{{-1.8f, 0.5f, -1}, {-1.2f, 1.2f, -1}, {-1.2f, 1.2f, 0.2f}, {-1.8f, 0.5f, 0.2f}}}, 1));
    render::LightDesc spot = test::pointLight("/spot", RGB(600.0f), {0.8, -0.5, 1.8});  // emits along -Z, downwards
    spot.radius = 0.1f;
    spot.shaping = spotCone(50.0f, 0.3f);
    s.lights.push_back(spot);
    s.lights.push_back(
        test::distantLight("/sun", 0.0f, RGB(1.2f, 1.1f, 0.9f), Matrix4::rotateX(40) * Matrix4::rotateY(-30)));
    render::LightDesc tube =
        test::lightDesc("/tube", render::LightType::Cylinder, RGB(8.0f), Matrix4::translate({1.2, 0.8, 0.8}));
    tube.radius = 0.05f;
    tube.length = 1.0f;
    s.lights.push_back(tube);
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(Bdpt, AgreesWithPathUnderDeltaLightsAnEmissiveMeshAndACylinderLight) {
    expectAgreement(deltaLightScene(), 256, 256);
}

// A sphere light hanging before a wall over a floor under the sun: much of the light goes between
// floor and wall by paths whose joins would cross the sphere's shape, which every subpath ends at
// (bdpt's joins once passed it, as path's shadow rays did: light_shape_shadow_test.cpp).
render::SceneDescription lightShapeInTheWay() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.7f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/wall", {{{-3, 1.5f, -1}, {3, 1.5f, -1}, {3, 1.5f, 3}, {-3, 1.5f, 3}}}, 0));
    s.lights.push_back(test::sphereLight("/bulb", 0.6f, RGB(3.0f), {0.2f, 0.4f, 0.0f}));
    s.lights.push_back(test::distantLight("/sun", 0.0f, RGB(2.0f), Matrix4::rotateX(-60)));
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(Bdpt, AgreesWithPathWhereALightsShapeStandsInTheWay) { expectAgreement(lightShapeInTheWay(), 256, 256); }

// A white sphere in a white dome reads 1 wherever it is seen (and the dome 1 around it).
TEST(Bdpt, RendersAWhiteFurnaceAsOne) {
    const Estimates bdpt = expectAgreement(test::furnaceScene(1.0f), 256, 256);
    const double zLimit = test::normalQuantile(0.5 * test::kChi2Alpha);
    for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(bdpt.imageMean[c] - 1.0), zLimit * std::sqrt(bdpt.imageVariance[c]) + 1e-5)
            << "channel " << c;
}

// Every sample is a function of (seed, pixel, sample index) alone: the image is the same at any
// thread count.
TEST(Bdpt, IsBitIdenticalAtAnyThreadCount) {
    IntegratorSettings settings;
    const Bdpt bdpt(settings);
    const Image one = test_support::renderWith(bdpt, cornellBox(), 16, 4, 1).image;
    const Image four = test_support::renderWith(bdpt, cornellBox(), 16, 4, 4).image;
    EXPECT_EQ(one.pixels, four.pixels);
}

// ---- A caustic from a point light.

// A point light inside a smooth glass sphere above a floor, beside a back wall: every light path
// leaves through the glass (LS+...), so no shadow ray reaches the light and `path` renders black.
// The caustic it throws on the floor and wall, seen directly (LS+DE), is found by light tracing
// to the camera (t = 1); the light those lit surfaces send on to the others (LS+DD+E) by joining
// the light subpath's diffuse vertex to the camera's first hit (s >= 3, t = 2).
render::SceneDescription glassedPointLight() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.8f)));
    render::MaterialDesc glass;
    glass.name = "/glass";
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    s.materials.push_back(glass);
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/back", {{{-3, 1, -1}, {3, 1, -1}, {3, 1, 3}, {-3, 1, 3}}}, 0));
    render::MeshDesc ball = test::sphereMesh(0.4f, 32, 16, 1);
    for (Vec3f& p : ball.positions) p += Vec3f(0.0f, 0.0f, 0.0f);
    s.meshes.push_back(ball);
    s.lights.push_back(test::pointLight("/point", RGB(2000.0f)));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

TEST(Bdpt, FindsLightFromAPointLightCausticThatPathCannot) {
    const render::SceneDescription scene = glassedPointLight();
    IntegratorSettings settings;
    const Estimates path = estimates(PathTracer(settings), scene, 16);
    const Estimates bdpt = estimates(Bdpt(settings), scene, 16);
    const double zLimit = test::normalQuantile(test::kChi2Alpha);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(path.imageMean[c], 0.0) << "channel " << c;
        EXPECT_GT(bdpt.imageMean[c], zLimit * std::sqrt(bdpt.imageVariance[c])) << "channel " << c;
    }
}

// ---- Light tracing (t = 1).

// A smooth glass ball beside a point light throws its caustic on a floor, which the camera looks
// straight down at (neither the ball nor the light in view): every pixel sees the floor, lit
// directly (LDE) and by the caustic (LS+DE, only light tracing draws it from a point light). With
// `radius` > 0 the point light is a sphere light of that radius and the same power, which `path`
// finds through the glass by hitting it.
render::SceneDescription causticOnAFloor(float radius) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.5f)));
    s.materials.push_back(test::glassMaterial("/glass", 0.0f));
    s.meshes.push_back(test::quadMesh("/floor", {{{-6, -6, -1}, {6, -6, -1}, {6, 6, -1}, {-6, 6, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.4f, 48, 24, 1, Vec3f(0.0f, 0.0f, -0.5f)));
    const Vec3d at(-1.5, 0.0, 0.0);
    const RGB radiance(15000.0f, 12000.0f, 9000.0f);  // test::pointLight's: a sphere of radius 0.05
    s.lights.push_back(radius > 0.0f
                           ? test::sphereLight("/bulb", radius, radiance * (0.05f * 0.05f / (radius * radius)), at)
                           : test::pointLight("/point", radiance, at));
    render::CameraDesc camera;  // looking down -Z from above the caustic, 30 degrees across
    camera.focalLength = 50.0f;
    camera.horizontalAperture = camera.verticalAperture = 26.8f;
    camera.nearClip = 0.01f;
    camera.transform = Matrix4::translate({1.8, 0.0, 2.5});
    s.camera = camera;
    return s;
}

// bdpt as it was before light tracing: the render loop hands it no splat film, so t = 1 is out.
class WithoutLightTracing final : public Integrator {
public:
    explicit WithoutLightTracing(const Integrator& bdpt) : bdpt_(bdpt) {}
    std::unique_ptr<RenderState> prepare(const render::RenderScene& scene, const render::Camera& camera,
                                         std::uint64_t seed, SplatFilm*) const override {
        return bdpt_.prepare(scene, camera, seed, nullptr);
    }
    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override {
        return bdpt_.sample(state, scene, camera, ray, rng, counters);
    }

private:
    const Integrator& bdpt_;
};

// bdpt with the point light agrees with `path` with a small sphere light of the same power in its
// place (radius 0.1: its finite size blurs the caustic by a few pixels, which moves little light
// across the 8x8 regions' borders and none across the image's), over the image and region by
// region; without t = 1 it reads significantly less, the caustic missed.
TEST(BdptLightTracing, FindsAPointLightsCausticSeenDirectly) {
    IntegratorSettings settings;
    const Bdpt bdpt(settings), withoutT1(settings);
    const Estimates traced = estimates(bdpt, causticOnAFloor(0.0f), 128);
    const Estimates path = estimates(PathTracer(settings), causticOnAFloor(0.1f), 4096);
    expectAgreement(traced, path);
    const Estimates missed = estimates(WithoutLightTracing(withoutT1), causticOnAFloor(0.0f), 64);
    const double zLimit = test::normalQuantile(test::kChi2Alpha);
    for (int c = 0; c < 3; ++c) {
        const double sd = std::sqrt(missed.imageVariance[c] + path.imageVariance[c]);
        std::printf("[ measured ] channel %d: without t = 1 %.5f (path %.5f, sd %.5f)\n", c, missed.imageMean[c],
                    path.imageMean[c], sd);
        EXPECT_GT(path.imageMean[c] - missed.imageMean[c], zLimit * sd) << "channel " << c;
    }
}

// The splats add in fixed point: the image is the same at any thread count, with adaptive
// sampling too (which divides the splats by the image's mean samples per pixel).
TEST(BdptLightTracing, IsBitIdenticalAtAnyThreadCount) {
    const Bdpt bdpt{IntegratorSettings{}};
    for (double targetError : {0.0, 0.2}) {
        RenderSettings settings;
        settings.samplesPerPixel = 8;
        settings.targetError = targetError;
        settings.minSamples = 2;
        settings.threads = 1;
        const test_support::RenderedFilm one = test_support::renderFilm(bdpt, causticOnAFloor(0.0f), 16, settings);
        settings.threads = 2;
        const test_support::RenderedFilm two = test_support::renderFilm(bdpt, causticOnAFloor(0.0f), 16, settings);
        ASSERT_NE(one.film.splats(), nullptr);
        std::vector<std::int64_t> sums = one.film.splats()->fixedSums();
        EXPECT_GT(*std::max_element(sums.begin(), sums.end()), 0) << "nothing was splatted";
        EXPECT_EQ(sums, two.film.splats()->fixedSums());
        EXPECT_EQ(one.film.resolve().pixels, two.film.resolve().pixels) << "target error " << targetError;
    }
}

// A tile (a film that is a window of the image) gets no splat film, and an orthographic camera
// cannot be joined: bdpt leaves t = 1 out and says why in its summary.
TEST(BdptLightTracing, TilesAndOrthographicCamerasLeaveItOutAndSaySo) {
    const render::SceneDescription desc = causticOnAFloor(0.0f);
    const render::RenderScene scene(desc);
    const Bdpt bdpt{IntegratorSettings{}};
    RenderSettings settings;
    settings.samplesPerPixel = 1;
    const render::Camera camera(*desc.camera, 16, 16);
    Film whole(16, 16, camera.farClip());
    EXPECT_EQ(render(scene, camera, bdpt, settings, whole).methodSummary, "");
    EXPECT_NE(whole.splats(), nullptr);
    Film tile(8, 16, camera.farClip());
    settings.windowX = 8;
    settings.imageWidth = 16;
    const std::string tileSummary = render(scene, camera, bdpt, settings, tile).methodSummary;
    EXPECT_EQ(tile.splats(), nullptr);
    EXPECT_NE(tileSummary.find("tile"), std::string::npos) << tileSummary;
    render::CameraDesc orthographic = *desc.camera;
    orthographic.projection = render::Projection::Orthographic;
    const render::Camera flat(orthographic, 16, 16);
    Film film(16, 16, flat.farClip());
    settings.windowX = settings.imageWidth = 0;
    const std::string flatSummary = render(scene, flat, bdpt, settings, film).methodSummary;
    EXPECT_NE(flatSummary.find("orthographic"), std::string::npos) << flatSummary;
}

// ---- Media.

// Per channel, bdpt's and `path`'s means along a ray agree within their combined standard error
// (two-sided, Sidak over the three channels at the suite's level).
void expectAgreementAlong(const render::SceneDescription& desc, const render::Ray& ray, int n) {
    const render::RenderScene scene(desc);
    const std::array<test::MeanEstimate, 3> bdpt =
        test_support::radianceAlong(Bdpt{IntegratorSettings{}}, scene, ray, n, 3);
    const std::array<test::MeanEstimate, 3> path =
        test_support::radianceAlong(PathTracer(IntegratorSettings{}), scene, ray, n, 3);
    const double zLimit = test::normalQuantile(0.5 * test::sidakAlpha(3));
    for (int c = 0; c < 3; ++c) {
        const double error = std::hypot(bdpt[c].standardError(), path[c].standardError());
        std::printf("[ measured ] channel %d: bdpt %.5f +- %.5f, path %.5f +- %.5f\n", c, bdpt[c].mean(),
                    bdpt[c].standardError(), path[c].mean(), path[c].standardError());
        EXPECT_GT(path[c].mean(), 0.0) << "channel " << c;
        EXPECT_NEAR(bdpt[c].mean(), path[c].mean(), zLimit * error) << "channel " << c;
    }
}

// A cube of constant density 1 (40 voxels of 0.05 a side; the trilinear density ramps to 0 over
// the outermost voxel) centred at `centre`, as a volume with `params`.
render::VolumeDesc fogCube(const test::TempDir& dir, const volumes::GridMediumParams& params, const Vec3d& centre) {
    constexpr int kVoxels = 40;
    constexpr double kVoxel = 0.05;
    openvdb::FloatGrid::Ptr grid = test::makeGrid<openvdb::FloatGrid>("density", kVoxel, openvdb::Vec3d(0.0));
    grid->fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(kVoxels - 1)), 1.0f, true);
    const std::string file = dir.file("fog.vdb");
    test::writeGrids(file, {grid});
    render::VolumeDesc v;
    v.name = "/Fog";
    v.transform = Matrix4::translate(centre - Vec3d(0.5 * kVoxel * (kVoxels - 1)));
    v.density = render::VolumeFieldDesc{file, "density", -1};
    v.params = params;
    return v;
}

// A chromatic fog cube of side 2 (sigmaT (1.5, 1.35, 0.6) per unit, albedo (0.75, 0.56, 0.63):
// optical depth 3 to 1.2 across) over a diffuse floor before a wall, lit by a rect light above it.
render::SceneDescription fogOverAFloor(const test::TempDir& dir, float g) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.6f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/wall", {{{-3, 1.5f, -1}, {3, 1.5f, -1}, {3, 1.5f, 3}, {-3, 1.5f, 3}}}, 0));
    volumes::GridMediumParams fog;
    fog.densityScale = 1.5f;
    fog.albedo = RGB(0.75f, 0.5f, 0.25f);
    fog.absorptionColor = RGB(0.0f, 0.2f, 0.8f);
    fog.anisotropy = g;
    s.volumes.push_back(fogCube(dir, fog, {0.0, 0.0, 0.0}));
    s.lights.push_back(test::rectLight("/light", 1.0f, 1.0f, RGB(6.0f), Matrix4::translate({0.3, -0.2, 1.5})));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

TEST(BdptMedia, AgreesWithPathInAnIsotropicChromaticVolume) {
    const test::TempDir dir;
    expectAgreement(fogOverAFloor(dir, 0.0f), 384, 384);
}

TEST(BdptMedia, AgreesWithPathInAForwardScatteringChromaticVolume) {
    const test::TempDir dir;
    expectAgreement(fogOverAFloor(dir, 0.6f), 384, 384);
}

// A glass ball of a chromatic, absorbing, anisotropic scattering interior with a sphere light
// inside (as in interior_medium_test.cpp): light subpaths start inside the ball's medium (found by
// bdpt::mediaAt), and the walks inside join nowhere.
TEST(BdptMedia, AgreesWithPathAroundALightInsideAScatteringInterior) {
    render::SceneDescription desc;
    render::MaterialDesc glass = test::glassMaterial("/Glass", 0.0f);
    glass.interior = media::MediumProperties{RGB(0.1f, 0.2f, 0.4f), RGB(1.5f, 1.0f, 0.5f), RGB(0.0f), 0.3f};
    desc.materials.push_back(glass);
    desc.meshes.push_back(test::roundSphereMesh(1.0f, 48, 24, 0));
    desc.lights.push_back(test::sphereLight("/Bulb", 0.2f, RGB(10.0f)));
    desc.camera = test::lookAtOriginCamera(5.0f);
    expectAgreementAlong(desc, render::Ray{{0.3f, -5.0f, 0.1f}, {0.0f, 1.0f, 0.0f}}, 400000);
}

// A light subpath starts in the interiors that hold its light: inside a ball and inside a
// ball nested in it, not outside them or in empty space.
TEST(BdptMedia, LightSubpathsStartInTheInteriorsHoldingTheirLight) {
    render::SceneDescription s;
    render::MaterialDesc glass = test::glassMaterial("/Glass", 0.0f);
    glass.interior = media::MediumProperties{RGB(1.0f), RGB(0.0f)};
    s.materials.push_back(glass);
    glass.interior = media::MediumProperties{RGB(2.0f), RGB(0.0f)};
    s.materials.push_back(glass);
    s.meshes.push_back(test::roundSphereMesh(1.0f, 32, 16, 0, Vec3f(0.0f)));
    s.meshes.push_back(test::roundSphereMesh(0.3f, 32, 16, 1, Vec3f(0.5f, 0.0f, 0.0f)));
    s.lights.push_back(test::domeLight("/Sky", RGB(1.0f)));
    s.camera = test::lookAtOriginCamera(4.0f);
    const render::RenderScene scene(s);
    RenderCounters counters;
    const Vec3f up(0.0f, 0.0f, 1.0f);
    EXPECT_EQ(bdpt::mediaAt(scene, Vec3f(-0.5f, 0.0f, 0.0f), up, counters).medium(), scene.mediumInside(0));
    EXPECT_EQ(bdpt::mediaAt(scene, Vec3f(0.5f, 0.0f, 0.0f), up, counters).medium(), scene.mediumInside(1));
    EXPECT_EQ(bdpt::mediaAt(scene, Vec3f(0.5f, 0.0f, 0.0f), up, counters).depth(), 2);
    EXPECT_EQ(bdpt::mediaAt(scene, Vec3f(0.45f, 0.05f, -2.0f), up, counters).medium(), nullptr)
        << "below both, crossing both";
}

// A sphere light inside a rough glass ball whose interior absorbs, over a floor: light subpaths
// start inside the interior, are attenuated on their way to the rough glass, and are joined from
// there to the floor. (Their joins carry little of the light here: the test checks agreement, not
// mediaAt, which the test above checks.)
TEST(BdptMedia, AgreesWithPathAroundALightInsideAnAbsorbingRoughGlassBall) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.6f)));
    render::MaterialDesc glass = test::glassMaterial("/Glass", 0.3f);
    glass.interior = media::MediumProperties{RGB(3.0f, 1.5f, 0.5f), RGB(0.0f)};
    s.materials.push_back(glass);
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.6f, 32, 16, 1, Vec3f(0.0f)));
    s.lights.push_back(test::sphereLight("/Bulb", 0.1f, RGB(80.0f)));
    s.camera = test::lookAtOriginCamera(4.0f);
    expectAgreement(s, 128, 128);
}

// A subsurface random-walk ball (Standard Surface subsurface = 1, its interior from
// media::subsurfaceMedium) on a floor, lit by a rect light: light subpaths walk through it too.
TEST(BdptMedia, AgreesWithPathOnASubsurfaceRandomWalk) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.6f)));
    s.materials.push_back(test::subsurfaceMaterial("/Skin", RGB(0.8f, 0.5f, 0.3f), RGB(0.2f, 0.1f, 0.05f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-3, -3, -1}, {3, -3, -1}, {3, 3, -1}, {-3, 3, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.7f, 32, 16, 1, Vec3f(0.0f, 0.0f, -0.3f)));
    s.lights.push_back(test::rectLight("/light", 1.0f, 1.0f, RGB(6.0f), Matrix4::translate({0.8, -0.5, 1.5})));
    s.camera = test::lookAtOriginCamera(4.0f);
    expectAgreement(s, 512, 512);
}

// Seen head-on, a glass cube whose interior absorbs sigmaA shows the sky through the geometric
// series of its internal reflections (test_support::glassSlabSeenHeadOn, as in
// interior_medium_test.cpp): bdpt matches it within 4.5 standard errors per channel.
TEST(BdptMedia, MatchesBeerLambertThroughAbsorbingGlass) {
    const RGB sigmaA(0.2f, 0.5f, 1.0f);
    const float side = 2.0f, F = 0.04f;
    render::SceneDescription desc = test::furnaceScene(1.0f);
    desc.materials[0] = test::glassMaterial("/Glass", 0.0f);
    desc.materials[0].interior = media::MediumProperties{sigmaA, RGB(0.0f)};
    desc.meshes[0] = test::boxMesh(Vec3f(side / 2.0f), 0);
    const render::RenderScene scene(desc);
    const std::array<test::MeanEstimate, 3> e = test_support::radianceAlong(
        Bdpt{IntegratorSettings{}}, scene, render::Ray{{0.1f, -5.0f, 0.2f}, {0.0f, 1.0f, 0.0f}}, 400000, 5);
    for (int c = 0; c < 3; ++c) {
        const double expected = test_support::glassSlabSeenHeadOn(F, std::exp(-sigmaA[c] * side));
        std::printf("[ measured ] channel %d: %.5f +- %.5f (expected %.5f)\n", c, e[c].mean(), e[c].standardError(),
                    expected);
        EXPECT_NEAR(e[c].mean(), expected, 4.5 * e[c].standardError() + 1e-5) << "channel " << c;
    }
}

// A fog cube that scatters every channel without absorbing (albedo-1, chromatic: sigmaS (1.5,
// 0.75, 0.3), forward-scattering) under a white sky: every path leaves with its weight, so the
// radiance through it reads 1 in every channel.
TEST(BdptMedia, RendersAChromaticAlbedoOneVolumeUnderAWhiteSkyAsOne) {
    const test::TempDir dir;
    render::SceneDescription desc;
    volumes::GridMediumParams fog;
    fog.densityScale = 1.5f;
    fog.albedo = RGB(1.0f, 0.5f, 0.2f);
    fog.absorptionColor = RGB(1.0f);
    fog.anisotropy = 0.5f;
    desc.volumes.push_back(fogCube(dir, fog, Vec3d(0.0)));
    desc.lights.push_back(test::domeLight("/Sky", RGB(1.0f)));
    desc.camera = test::lookAtOriginCamera(4.0f);
    const render::RenderScene scene(desc);
    const std::array<test::MeanEstimate, 3> e = test_support::radianceAlong(
        Bdpt{IntegratorSettings{}}, scene, render::Ray{{0.05f, -4.0f, 0.1f}, {0.0f, 1.0f, 0.0f}}, 200000, 9);
    for (int c = 0; c < 3; ++c) {
        std::printf("[ measured ] channel %d: %.5f +- %.5f\n", c, e[c].mean(), e[c].standardError());
        EXPECT_NEAR(e[c].mean(), 1.0, 4.5 * e[c].standardError() + 1e-5) << "channel " << c;
    }
}

TEST(BdptMedia, IsBitIdenticalAtAnyThreadCount) {
    const test::TempDir dir;
    const Bdpt bdpt(IntegratorSettings{});
    const render::SceneDescription scene = fogOverAFloor(dir, 0.6f);
    const Image one = test_support::renderWith(bdpt, scene, 16, 4, 1).image;
    const Image four = test_support::renderWith(bdpt, scene, 16, 4, 4).image;
    EXPECT_EQ(one.pixels, four.pixels);
}

}  // namespace
}  // namespace fluence::integrators
