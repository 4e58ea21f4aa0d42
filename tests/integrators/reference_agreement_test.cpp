// `path` (NEE + MIS) against `naive` (BSDF sampling only) on a scene with every kind of light
// that BSDF sampling can reach, and on one of transmissive materials lit from both sides: if an
// MIS weight or a light pdf were wrong (or next-event estimation missed the side a transmitted
// path leaves by), the two estimates of the image would disagree, block by block, by more than
// their noise.
#include <gtest/gtest.h>

#include <cmath>

#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

// A constant dark-blue sky.
render::LightDesc blueSkyDome() { return test::domeLight("/dome", RGB(0.1f, 0.15f, 0.3f)); }

render::SceneDescription everyLightScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f), RGB(0.0f)));
    s.materials.push_back(test::diffuseMaterial("/orange", RGB(0.8f, 0.4f, 0.1f), RGB(0.0f)));
    s.materials.push_back(test::diffuseMaterial("/glow", RGB(0.2f), RGB(0.5f, 2.0f, 1.0f)));
    s.meshes.push_back(test::quadMesh("/ground", {{{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}}}, 0));
    s.meshes.push_back(test::sphereMesh(0.8f, 24, 12, 1));
    // An emissive quad standing behind the sphere.
    s.meshes.push_back(
        test::quadMesh("/panel", {{{-1.5f, 2, -1}, {1.5f, 2, -1}, {1.5f, 2.5f, 1.5f}, {-1.5f, 2.5f, 1.5f}}}, 2));

    // The rect light emits downwards-ish.
    s.lights.push_back(test::rectLight("/rect", 1.5f, 1.0f, RGB(6.0f, 5.0f, 4.0f),
                                       Matrix4::translate({1.5, -0.5, 2.5}) * Matrix4::rotateY(30)));
    s.lights.push_back(test::sphereLight("/bulb", 0.3f, RGB(8.0f), {-1.8, -0.8, 0.5}));
    render::LightDesc sun = test::distantLight("/sun", 20.0f, RGB(1.5f), Matrix4::rotateX(35) * Matrix4::rotateY(-20));
    sun.normalize = true;
    s.lights.push_back(sun);
    s.lights.push_back(blueSkyDome());

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
    return test_support::renderWith(integrator, desc, size, spp, 0, seed).image;
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

// Every 8x8 block and channel gives z = (path - naive) / sd; under agreement the sum of z^2 is
// chi-square with as many degrees of freedom as there are noisy block means. A block without
// noise in either render (one that sees only the dome) must agree to float rounding instead.
void expectAgreement(const render::SceneDescription& scene, int pathSpp, int naiveSpp) {
    IntegratorSettings settings;
    BlockEstimates path = blockMeans(PathTracer(settings), scene, 32, pathSpp);
    BlockEstimates naive = blockMeans(NaivePathTracer(settings), scene, 32, naiveSpp);
    double chi2 = 0.0, pathTotal = 0.0;
    int noisy = 0;
    std::string worst;
    for (std::size_t i = 0; i < path.mean.size(); ++i) {
        pathTotal += path.mean[i];
        const double variance = path.variance[i] + naive.variance[i];
        if (variance == 0.0) {
            EXPECT_NEAR(path.mean[i], naive.mean[i], 1e-6 * naive.mean[i]) << "noiseless block " << i / 3;
            continue;
        }
        double z2 = std::pow(path.mean[i] - naive.mean[i], 2) / variance;
        chi2 += z2;
        ++noisy;
        if (z2 > 9.0)
            worst += " block " + std::to_string(i / 3) + " channel " + std::to_string(i % 3) + ": path " +
                     std::to_string(path.mean[i]) + " naive " + std::to_string(naive.mean[i]) + ";";
    }
    ASSERT_GT(noisy, 0);
    double p = test::upperIncompleteGammaQ(0.5 * noisy, 0.5 * chi2);
    EXPECT_GT(p, test::kChi2Alpha) << "chi2 " << chi2 << " over " << noisy << " block means;" << worst;
    EXPECT_GT(pathTotal / double(path.mean.size()), 0.05) << "the scene is lit";
}

TEST(ReferenceAgreement, PathTracerMatchesNaivePathTracerOnEveryLightType) {
    expectAgreement(everyLightScene(), 128, 1024);
}

// Rough glass, a layered material with every lobe (glass, metal, sheen, coat, anisotropy), and a
// rough thin-walled sheet, on a diffuse ground; a rect light behind the sheet shines through it at
// the camera, a sphere light behind the glass sphere lights it through its far side, another
// lights the scene from the front, a dim dome all round. Transmissive surfaces gather light from
// both sides by next-event estimation.
render::SceneDescription transmissiveScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f), RGB(0.0f)));
    render::MaterialDesc glass;
    glass.name = "/glass";
    glass.transmission = 1.0f;
    glass.roughness = 0.4f;
    glass.anisotropy = 0.3f;
    glass.transmissionColor = RGB(0.9f, 1.0f, 0.8f);
    s.materials.push_back(glass);
    render::MaterialDesc layered;
    layered.name = "/layered";
    layered.diffuse = RGB(0.7f, 0.4f, 0.2f);
    layered.roughness = 0.4f;
    layered.anisotropy = 0.6f;
    layered.metallic = 0.3f;
    layered.transmission = 0.4f;
    layered.sheen = 0.8f;
    layered.sheenColor = RGB(0.5f, 0.8f, 1.0f);
    layered.coat = 0.5f;
    layered.coatColor = RGB(1.0f, 0.9f, 0.7f);
    layered.coatRoughness = 0.2f;
    s.materials.push_back(layered);
    render::MaterialDesc sheet = test::thinSheetMaterial("/sheet", RGB(0.4f, 0.6f, 0.3f), 0.8f, 0.3f);
    sheet.transmissionColor = RGB(0.9f, 0.7f, 0.5f);
    s.materials.push_back(sheet);
    s.meshes.push_back(test::quadMesh("/ground", {{{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}}}, 0));
    s.meshes.push_back(test::roundSphereMesh(0.7f, 24, 12, 1, {-0.9f, 0.0f, -0.3f}));
    s.meshes.push_back(test::roundSphereMesh(0.6f, 24, 12, 2, {0.9f, 0.0f, -0.4f}));
    s.meshes.push_back(
        test::quadMesh("/sheet", {{{0, 1.2f, -1}, {2.5f, 1.2f, -1}, {2.5f, 1.2f, 1.8f}, {0, 1.2f, 1.8f}}}, 3));

    // Emits towards -Y.
    s.lights.push_back(test::rectLight("/behindSheet", 2.0f, 1.5f, RGB(3.0f),
                                       Matrix4::translate({1.2, 2.2, 0.4}) * Matrix4::rotateX(-90)));
    // Behind the glass: reached through it from inside.
    s.lights.push_back(test::sphereLight("/backlight", 0.25f, RGB(12.0f), {-1.1, 1.3, 0.1}));
    s.lights.push_back(test::sphereLight("/bulb", 0.3f, RGB(8.0f), {0.4, -2.2, 2.4}));
    s.lights.push_back(blueSkyDome());
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(ReferenceAgreement, PathTracerMatchesNaiveThroughTransmissiveMaterials) {
    expectAgreement(transmissiveScene(), 96, 512);
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
    Image naive = renderImage(NaivePathTracer(settings), s, 8, 4, 1),
          path = renderImage(PathTracer(settings), s, 8, 4, 1);
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
