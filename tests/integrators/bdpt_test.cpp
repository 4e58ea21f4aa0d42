// `bdpt` (integrators/bdpt.h): its MIS weights sum to one over the strategies of a path; the
// emission samplers that start its light subpaths report the densities they draw with; it agrees
// with `path` within their combined noise (per channel over the image, and region by region) on
// a diffuse box lit by an area light, a glossy and metal scene, glass, a scene of delta lights, an
// emissive mesh and a cylinder light, and a white furnace, which it renders as 1; its images are
// the same at any thread count; it refuses media; and it finds the light of a point light's
// caustic, once that lights another surface, which `path` cannot.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrators/bdpt.h"
#include "integrators/bdpt_mis.h"
#include "integrators/path_tracer.h"
#include "render/area_lights.h"
#include "render/infinite_lights.h"
#include "render/sphere_light.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

// ---- MIS weights.

TEST(BdptMis, WeightsSumToOneOverTheStrategiesOfAPath) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> density(0.01f, 10.0f);
    std::bernoulli_distribution deltaVertex(0.2), hittable(0.8);
    for (int trial = 0; trial < 2000; ++trial) {
        const int vertices = 3 + trial % 8;  // x_0 ... x_k, k >= 2
        std::vector<VertexDensity> x(vertices);
        for (int i = 0; i < vertices; ++i) x[i] = {density(random), density(random), i > 0 && i < vertices - 1 && deltaVertex(random)};
        if (trial % 5 == 0) x[0].fromLight = 0.0f;  // a light without emission sampling
        StrategyPath path{x, density(random), hittable(random)};
        double sum = 0.0;
        int strategies = 0;
        for (int s = 0; s + 2 <= vertices; ++s)
            if (strategyExists(path, s) && (s < 2 || x[0].fromLight > 0.0f)) {  // (no light subpath from such a light)
                sum += misWeight(path, s);
                ++strategies;
            }
        if (strategies > 0) {
            EXPECT_NEAR(sum, 1.0, 1e-5) << "trial " << trial;
        }
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
}

// ---- Emission sampling (render/light_emission.cpp), which light subpaths start from.

// Each light's sampleEmission() reports the densities emissionDensity() gives for its point and
// direction, and only points and directions that carry light.
TEST(BdptEmission, SampledDensitiesMatchEmissionDensity) {
    auto desc = [](render::LightType type) {
        return test::lightDesc("/light", type, RGB(2.0f), Matrix4::translate({0.5, -0.2, 1.0}) * Matrix4::rotateX(30));
    };
    render::LightDesc spot = desc(render::LightType::Sphere);
    spot.treatAsPoint = true;
    spot.shaping = render::LightShapingDesc{40.0f, 0.5f};
    render::LightDesc sun = desc(render::LightType::Distant);
    sun.angleDegrees = 5.0f;
    std::vector<std::unique_ptr<render::Light>> lights;
    lights.push_back(std::make_unique<render::RectLight>(desc(render::LightType::Rect)));
    lights.push_back(std::make_unique<render::DiskLight>(desc(render::LightType::Disk)));
    lights.push_back(std::make_unique<render::TriangleLight>("/mesh", Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(0, 1, 0.5f), RGB(1.0f)));
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

// ---- Agreement with `path`.

constexpr int kSize = 32, kRegion = 8, kBatches = 16;
constexpr int kRegions = (kSize / kRegion) * (kSize / kRegion);

// Means with the variances of those means: per channel over the whole image, and per 8x8 region
// of the channels' average (regions hold disjoint pixels, so their estimates are independent;
// a region's three channels are not). From kBatches independent renders (seeds 1, 2, ...) of
// spp / kBatches samples each: pixels differ in expected value, so their spread is not noise,
// but each pixel's spread across the batches is, and gives the variance of its mean without bias.
struct Estimates {
    std::array<double, 3> imageMean{}, imageVariance{};
    std::array<double, kRegions> regionMean{}, regionVariance{};
};

Estimates estimates(const Integrator& integrator, const render::SceneDescription& desc, int spp) {
    std::vector<Image> batches;
    for (int b = 0; b < kBatches; ++b)
        batches.push_back(test_support::renderWith(integrator, desc, kSize, spp / kBatches, 0, b + 1).image);
    Estimates e;
    const double pixels = kSize * kSize, regionPixels = kRegion * kRegion;
    // The mean over the batches of f(pixel), and the variance of that mean.
    auto pixelEstimate = [&](int x, int y, auto&& f) {
        test::MeanEstimate m;
        for (const Image& image : batches) m.add(f(image.pixel(x, y)));
        // MeanEstimate's standard error divides by n; the unbiased variance of the mean by n - 1.
        return std::pair(m.mean(), m.standardError() * m.standardError() * kBatches / (kBatches - 1.0));
    };
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            for (int c = 0; c < 3; ++c) {
                auto [mean, variance] = pixelEstimate(x, y, [c](const float* p) { return double(p[c]); });
                e.imageMean[c] += mean / pixels;
                e.imageVariance[c] += variance / (pixels * pixels);
            }
            auto [mean, variance] = pixelEstimate(x, y, [](const float* p) { return (double(p[0]) + p[1] + p[2]) / 3.0; });
            const int region = (y / kRegion) * (kSize / kRegion) + x / kRegion;
            e.regionMean[region] += mean / regionPixels;
            e.regionVariance[region] += variance / (regionPixels * regionPixels);
        }
    return e;
}

// Per channel, the image means agree within their combined standard error (a two-sided test at
// the Sidak level of the suite's family); over the regions, the sum of z^2 of the noisy ones is
// chi-square distributed. Returns bdpt's estimates.
Estimates expectAgreement(const render::SceneDescription& scene, int bdptSpp, int pathSpp) {
    IntegratorSettings settings;
    const Estimates bdpt = estimates(Bdpt(settings), scene, bdptSpp);
    const Estimates path = estimates(PathTracer(settings), scene, pathSpp);
    const double zLimit = test::normalQuantile(0.5 * test::kChi2Alpha);
    for (int c = 0; c < 3; ++c) {
        const double sd = std::sqrt(bdpt.imageVariance[c] + path.imageVariance[c]);
        EXPECT_LE(std::abs(bdpt.imageMean[c] - path.imageMean[c]), zLimit * sd)
            << "channel " << c << ": bdpt " << bdpt.imageMean[c] << " path " << path.imageMean[c] << " sd " << sd;
    }
    double chi2 = 0.0;
    int noisy = 0;
    std::string worst;
    for (int r = 0; r < kRegions; ++r) {
        const double variance = bdpt.regionVariance[r] + path.regionVariance[r];
        if (variance == 0.0) {
            EXPECT_NEAR(bdpt.regionMean[r], path.regionMean[r], 1e-5 * std::abs(path.regionMean[r])) << "noiseless region " << r;
            continue;
        }
        const double z2 = std::pow(bdpt.regionMean[r] - path.regionMean[r], 2) / variance;
        chi2 += z2;
        ++noisy;
        if (z2 > 9.0)
            worst += " region " + std::to_string(r) + ": bdpt " + std::to_string(bdpt.regionMean[r]) + " path " +
                     std::to_string(path.regionMean[r]) + ";";
    }
    EXPECT_GT(noisy, 0);
    EXPECT_GT(test::upperIncompleteGammaQ(0.5 * noisy, 0.5 * chi2), test::kChi2Alpha)
        << "chi2 " << chi2 << " over " << noisy << " region means;" << worst;
    return bdpt;
}

// An open box (floor, ceiling, back and side walls; red and green sides) lit by a rect light
// under its ceiling, seen from the open side.
render::SceneDescription cornellBox() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.75f)));
    s.materials.push_back(test::diffuseMaterial("/red", RGB(0.7f, 0.1f, 0.1f)));
    s.materials.push_back(test::diffuseMaterial("/green", RGB(0.1f, 0.6f, 0.1f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}}, 0));
    s.meshes.push_back(test::quadMesh("/ceiling", {{{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}}}, 0));
    s.meshes.push_back(test::quadMesh("/back", {{{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}}}, 0));
    s.meshes.push_back(test::quadMesh("/left", {{{-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}}}, 1));
    s.meshes.push_back(test::quadMesh("/right", {{{1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}}}, 2));
    s.meshes.push_back(test::boxMesh({0.3f, 0.3f, 0.5f}, 0));
    // Emits along -Z, downwards.
    s.lights.push_back(test::rectLight("/light", 0.6f, 0.6f, RGB(12.0f), Matrix4::translate({0.0, 0.0, 0.98})));
    s.camera = test::lookAtOriginCamera(3.5f);
    return s;
}

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
    s.lights.push_back(
        test::diskLight("/disk", 0.5f, RGB(4.0f, 3.0f, 2.0f), Matrix4::translate({-1.5, 0.5, 2.0}) * Matrix4::rotateY(-20)));
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
    s.meshes.push_back(test::quadMesh("/sheet", {{{0.2f, 1.0f, -1}, {2.0f, 1.0f, -1}, {2.0f, 1.0f, 1.2f}, {0.2f, 1.0f, 1.2f}}}, 3));
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
    s.meshes.push_back(test::quadMesh("/panel", {{{-1.8f, 0.5f, -1}, {-1.2f, 1.2f, -1}, {-1.2f, 1.2f, 0.2f}, {-1.8f, 0.5f, 0.2f}}}, 1));
    render::LightDesc spot = test::pointLight("/spot", RGB(600.0f), {0.8, -0.5, 1.8});  // emits along -Z, downwards
    spot.radius = 0.1f;
    spot.shaping = render::LightShapingDesc{50.0f, 0.3f};
    s.lights.push_back(spot);
    s.lights.push_back(test::distantLight("/sun", 0.0f, RGB(1.2f, 1.1f, 0.9f), Matrix4::rotateX(40) * Matrix4::rotateY(-30)));
    render::LightDesc tube = test::lightDesc("/tube", render::LightType::Cylinder, RGB(8.0f), Matrix4::translate({1.2, 0.8, 0.8}));
    tube.radius = 0.05f;
    tube.length = 1.0f;
    s.lights.push_back(tube);
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(Bdpt, AgreesWithPathUnderDeltaLightsAnEmissiveMeshAndACylinderLight) { expectAgreement(deltaLightScene(), 256, 256); }

// A white sphere in a white dome reads 1 wherever it is seen (and the dome 1 around it).
TEST(Bdpt, RendersAWhiteFurnaceAsOne) {
    const Estimates bdpt = expectAgreement(test::furnaceScene(1.0f), 256, 256);
    const double zLimit = test::normalQuantile(0.5 * test::kChi2Alpha);
    for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(bdpt.imageMean[c] - 1.0), zLimit * std::sqrt(bdpt.imageVariance[c]) + 1e-5) << "channel " << c;
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

// Participating media are not supported: a scene with a material interior is refused.
TEST(Bdpt, RefusesScenesWithMedia) {
    render::SceneDescription desc = cornellBox();
    desc.materials[0].transmission = 1.0f;
    desc.materials[0].interior = media::MediumProperties{RGB(0.1f), RGB(0.5f)};
    const render::RenderScene scene(desc);
    const render::Camera camera(*desc.camera, 8, 8);
    EXPECT_THROW(Bdpt(IntegratorSettings{}).prepare(scene, camera, 0), std::invalid_argument);
}

// ---- A caustic from a point light.

// A point light inside a smooth glass sphere above a floor, beside a back wall: every light path
// leaves through the glass (LS+...), so no shadow ray reaches the light and `path` renders black.
// The caustic it throws on the floor and wall, seen directly (LS+DE), needs light tracing to the
// camera (t = 1), which bdpt leaves out; the light those lit surfaces send on to the others
// (LS+DD+E) is found by joining the light subpath's diffuse vertex to the camera's first hit
// (s >= 3, t = 2).
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

}  // namespace
}  // namespace fluence::integrators
