// `path` (NEE + MIS) against `naive` (BSDF sampling only) on a scene with every kind of light
// that BSDF sampling can reach: if an MIS weight or a light pdf were wrong, the two estimates
// of the image would disagree, block by block, by more than their noise.
#include <gtest/gtest.h>

#include <cmath>

#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

render::SceneDescription everyLightScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f), RGB(0.0f)));
    s.materials.push_back(test::diffuseMaterial("/orange", RGB(0.8f, 0.4f, 0.1f), RGB(0.0f)));
    s.materials.push_back(test::diffuseMaterial("/glow", RGB(0.2f), RGB(0.5f, 2.0f, 1.0f)));
    s.meshes.push_back(test::quadMesh("/ground", {{{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}}}, 0));
    s.meshes.push_back(test::sphereMesh(0.8f, 24, 12, 1));
    // An emissive quad standing behind the sphere.
    s.meshes.push_back(test::quadMesh("/panel", {{{-1.5f, 2, -1}, {1.5f, 2, -1}, {1.5f, 2.5f, 1.5f}, {-1.5f, 2.5f, 1.5f}}}, 2));

    render::LightDesc rect;
    rect.name = "/rect";
    rect.type = render::LightType::Rect;
    rect.width = 1.5f;
    rect.height = 1.0f;
    rect.radiance = RGB(6.0f, 5.0f, 4.0f);
    rect.transform = Matrix4::translate({1.5, -0.5, 2.5}) * Matrix4::rotateY(30);  // emits downwards-ish
    s.lights.push_back(rect);
    render::LightDesc sphere;
    sphere.name = "/bulb";
    sphere.type = render::LightType::Sphere;
    sphere.radius = 0.3f;
    sphere.radiance = RGB(8.0f);
    sphere.transform = Matrix4::translate({-1.8, -0.8, 0.5});
    s.lights.push_back(sphere);
    render::LightDesc sun;
    sun.name = "/sun";
    sun.type = render::LightType::Distant;
    sun.angleDegrees = 20.0f;
    sun.radiance = RGB(1.5f);
    sun.normalize = true;
    sun.transform = Matrix4::rotateX(35) * Matrix4::rotateY(-20);
    s.lights.push_back(sun);
    render::LightDesc dome;
    dome.name = "/dome";
    dome.type = render::LightType::Dome;
    dome.radiance = RGB(0.1f, 0.15f, 0.3f);
    s.lights.push_back(dome);

    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

// Means of 8x8-pixel blocks of the image, per channel, with the variance of each mean.
struct BlockEstimates {
    std::vector<double> mean, variance;  // index: (block * 3 + channel)
};
constexpr int kBlock = 8;

Image renderImage(const Integrator& integrator, const render::SceneDescription& desc, int size, int spp,
                  std::uint64_t seed) {
    render::RenderScene scene(desc);
    render::Camera camera(*desc.camera, size, size);
    Film film(size, size, camera.farClip());
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.seed = seed;
    render(scene, camera, integrator, settings, film);
    return film.resolve();
}

// Two independent renders (seeds 1 and 2) of spp/2 samples each. Pixels differ in expected value,
// so their spread is not noise; the difference of the two renders is: each pixel's noise
// variance is estimated without bias by (a - b)^2 / 2.
BlockEstimates blockMeans(const Integrator& integrator, const render::SceneDescription& desc, int size, int spp) {
    Image a = renderImage(integrator, desc, size, spp / 2, 1), b = renderImage(integrator, desc, size, spp / 2, 2);
    const int blocks = (size / kBlock) * (size / kBlock);
    BlockEstimates e{std::vector<double>(blocks * 3, 0.0), std::vector<double>(blocks * 3, 0.0)};
    const double n = kBlock * kBlock;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            int block = (y / kBlock) * (size / kBlock) + x / kBlock;
            for (int c = 0; c < 3; ++c) {
                double va = a.pixel(x, y)[c], vb = b.pixel(x, y)[c];
                e.mean[block * 3 + c] += 0.5 * (va + vb) / n;
                // Var of the pixel's two-half average: ((a - b)^2 / 2) / 2; of the block mean: / n^2.
                e.variance[block * 3 + c] += 0.25 * (va - vb) * (va - vb) / (n * n);
            }
        }
    return e;
}

TEST(ReferenceAgreement, PathTracerMatchesNaivePathTracerOnEveryLightType) {
    // Every 8x8 block and channel gives z = (path - naive) / sd; under agreement the sum of z^2
    // is chi-square with (blocks x 3) degrees of freedom.
    auto scene = everyLightScene();
    IntegratorSettings settings;
    BlockEstimates path = blockMeans(PathTracer(settings), scene, 32, 128);
    BlockEstimates naive = blockMeans(NaivePathTracer(settings), scene, 32, 1024);
    double chi2 = 0.0, pathTotal = 0.0;
    std::string worst;
    for (std::size_t i = 0; i < path.mean.size(); ++i) {
        double z2 = std::pow(path.mean[i] - naive.mean[i], 2) / (path.variance[i] + naive.variance[i]);
        chi2 += z2;
        pathTotal += path.mean[i];
        if (z2 > 9.0)
            worst += " block " + std::to_string(i / 3) + " channel " + std::to_string(i % 3) + ": path " +
                     std::to_string(path.mean[i]) + " naive " + std::to_string(naive.mean[i]) + ";";
    }
    double p = test::upperIncompleteGammaQ(0.5 * double(path.mean.size()), 0.5 * chi2);
    EXPECT_GT(p, test::kChi2Alpha) << "chi2 " << chi2 << " over " << path.mean.size() << " block means;" << worst;
    EXPECT_GT(pathTotal / double(path.mean.size()), 0.05) << "the scene is lit";
}

TEST(ReferenceAgreement, NaiveMissesDeltaLightsAsItsPathClassSays) {
    // A delta distant light is invisible to BSDF sampling: `naive` renders it black, `path` not.
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f), RGB(0.0f)));
    s.meshes.push_back(test::sphereMesh(1.0f, 16, 8, 0));
    render::LightDesc sun;
    sun.type = render::LightType::Distant;
    sun.angleDegrees = 0.0f;
    sun.radiance = RGB(1.0f);
    sun.transform = Matrix4::rotateX(90);
    s.lights.push_back(sun);
    s.camera = test::lookAtOriginCamera(4.0f);
    IntegratorSettings settings;
    Image naive = renderImage(NaivePathTracer(settings), s, 8, 4, 1), path = renderImage(PathTracer(settings), s, 8, 4, 1);
    float naiveMax = 0.0f, pathMax = 0.0f;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            naiveMax = std::max(naiveMax, naive.pixel(x, y)[0]);
            pathMax = std::max(pathMax, path.pixel(x, y)[0]);
        }
    EXPECT_EQ(naiveMax, 0.0f);
    EXPECT_GT(pathMax, 0.01f);
}

}  // namespace
}  // namespace fluence::integrators
