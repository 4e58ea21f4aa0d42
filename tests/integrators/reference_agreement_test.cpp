// `path` (NEE + MIS) against `naive` (BSDF sampling only) on a scene with every kind of light
// that BSDF sampling can reach, and on one of transmissive materials lit from both sides: if an
// MIS weight or a light pdf were wrong (or next-event estimation missed the side a transmitted
// path leaves by), the two estimates of the image would disagree, block by block, by more than
// their noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"
#include "tests/support/statistics.h"

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

// Means of 8x8-pixel blocks of the image, per channel, with the variance of each mean and the sum
// of the squares of its per-pixel terms (each a one-degree-of-freedom estimate: see blockMeans),
// from which the variance's effective degrees of freedom follow (Welch-Satterthwaite).
struct BlockEstimates {
    std::vector<double> mean, variance, squaredTerms;  // index: (block * 3 + channel)
};
constexpr int kBlock = 8;

Image renderImage(const Integrator& integrator, const render::SceneDescription& desc, int size, int spp,
                  std::uint64_t seed) {
    return test_support::renderWith(integrator, desc, size, spp, 0, seed).image;
}

// Two independent renders (seeds firstSeed and firstSeed + 1) of spp/2 samples each. Pixels differ
// in expected value, so their spread is not noise; the difference of the two renders is: each
// pixel's noise variance is estimated without bias by (a - b)^2 / 2.
BlockEstimates blockMeans(const Integrator& integrator, const render::SceneDescription& desc, int size, int spp,
                          std::uint64_t firstSeed) {
    Image a = renderImage(integrator, desc, size, spp / 2, firstSeed),
          b = renderImage(integrator, desc, size, spp / 2, firstSeed + 1);
    const int blocks = (size / kBlock) * (size / kBlock);
    BlockEstimates e{std::vector<double>(blocks * 3, 0.0), std::vector<double>(blocks * 3, 0.0),
                     std::vector<double>(blocks * 3, 0.0)};
    const double n = kBlock * kBlock;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            int block = (y / kBlock) * (size / kBlock) + x / kBlock;
            for (int c = 0; c < 3; ++c) {
                double va = a.pixel(x, y)[c], vb = b.pixel(x, y)[c];
                e.mean[block * 3 + c] += 0.5 * (va + vb) / n;
                // Var of the pixel's two-half average: ((a - b)^2 / 2) / 2; of the block mean: / n^2.
                const double term = 0.25 * (va - vb) * (va - vb) / (n * n);
                e.variance[block * 3 + c] += term;
                e.squaredTerms[block * 3 + c] += term * term;
            }
        }
    return e;
}

// The x with P(chi-square(1) > x) = tail: z^2 for a normal z whose two-sided tail is `tail`.
double chiSquareOneDofQuantile(double tail) {
    if (!(tail < 1.0)) return 0.0;
    double lo = 0.0, hi = 1.0;
    while (test::upperIncompleteGammaQ(0.5, 0.5 * hi) > tail && hi < 1e4) hi *= 2.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (test::upperIncompleteGammaQ(0.5, 0.5 * mid) > tail ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// `path` and `naive` on the same scene, block by block: the difference of each block mean and its
// variance (0 for a block without noise in either render, one that sees only the dome).
struct Agreement {
    BlockEstimates path, naive;
    std::vector<double> difference, variance;
    double chi2 = 0.0;
    int noisy = 0;  // the block means with noise: chi2's degrees of freedom
    double pValue = 1.0;
    std::string worst;  // the blocks with z^2 > 9
};

// Every 8x8 block and channel gives t = (path - naive) / sd. Its variance is estimated, a sum of
// per-pixel one-degree-of-freedom terms, so t follows Student's t with the sum's effective degrees
// of freedom nu = (sum of terms)^2 / (sum of squared terms) (Welch-Satterthwaite), not a normal
// law: a block where only a few pixels are noisy (the corners, mostly dome) has a nu of a few, and
// its t has heavy tails (treating it as normal made 12 of 40 seed sets fail at alpha = 0.0005,
// bench/results/2026-12-05-reference-agreement.md). So each t is mapped to the z^2 of the same
// two-sided tail probability (the chi-square(1) quantile of Student's tail), and under agreement
// the sum of those z^2 is chi-square with as many degrees of freedom as there are noisy block means. The variance of a
// difference is the sum of the two variances only if the renders are independent: `path` renders
// with seeds pathSeed and pathSeed + 1, `naive` with naiveSeed and naiveSeed + 1, which must be
// two others (the same seeds give both the same camera jitter, and the statistic too little noise).
Agreement measureAgreement(const render::SceneDescription& scene, int pathSpp, int naiveSpp, std::uint64_t pathSeed,
                           std::uint64_t naiveSeed) {
    IntegratorSettings settings;
    Agreement a;
    a.path = blockMeans(PathTracer(settings), scene, 32, pathSpp, pathSeed);
    a.naive = blockMeans(NaivePathTracer(settings), scene, 32, naiveSpp, naiveSeed);
    for (std::size_t i = 0; i < a.path.mean.size(); ++i) {
        a.difference.push_back(a.path.mean[i] - a.naive.mean[i]);
        a.variance.push_back(a.path.variance[i] + a.naive.variance[i]);
        if (a.variance.back() == 0.0) continue;
        const double t = std::abs(a.difference.back()) / std::sqrt(a.variance.back());
        const double dof = a.variance.back() * a.variance.back() / (a.path.squaredTerms[i] + a.naive.squaredTerms[i]);
        const double z2 = chiSquareOneDofQuantile(2.0 * test::studentUpperTail(t, dof));
        a.chi2 += z2;
        ++a.noisy;
        if (z2 > 9.0)
            a.worst += " block " + std::to_string(i / 3) + " channel " + std::to_string(i % 3) + ": path " +
                       std::to_string(a.path.mean[i]) + " naive " + std::to_string(a.naive.mean[i]) + " (sd " +
                       std::to_string(std::sqrt(a.path.variance[i])) + ", " +
                       std::to_string(std::sqrt(a.naive.variance[i])) + ");";
    }
    a.pValue = a.noisy > 0 ? test::upperIncompleteGammaQ(0.5 * a.noisy, 0.5 * a.chi2) : 1.0;
    return a;
}

// The seeds of the tests: path 1 and 2, naive 3 and 4.
constexpr std::uint64_t kPathSeed = 1, kNaiveSeed = 3;

void expectAgreement(const render::SceneDescription& scene, int pathSpp, int naiveSpp) {
    const Agreement a = measureAgreement(scene, pathSpp, naiveSpp, kPathSeed, kNaiveSeed);
    double pathTotal = 0.0;
    for (std::size_t i = 0; i < a.path.mean.size(); ++i) {
        pathTotal += a.path.mean[i];
        if (a.variance[i] == 0.0) {  // a block that sees only the dome agrees to float rounding
            EXPECT_NEAR(a.path.mean[i], a.naive.mean[i], 1e-6 * a.naive.mean[i]) << "noiseless block " << i / 3;
        }
    }
    ASSERT_GT(a.noisy, 0);
    EXPECT_GT(a.pValue, test::kChi2Alpha) << "chi2 " << a.chi2 << " over " << a.noisy << " block means;" << a.worst;
    EXPECT_GT(pathTotal / double(a.path.mean.size()), 0.05) << "the scene is lit";
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

// The calibration of the two tests above, a long check that is not run by default:
//   integrators_tests --gtest_also_run_disabled_tests --gtest_filter='ReferenceAgreement.DISABLED_*'
// Over `sets` independent sets of seeds (path 4k + 1 and 4k + 2, naive 4k + 3 and 4k + 4) the
// p-values of the statistic must be uniform (Kolmogorov-Smirnov), and the block differences pooled
// over all sets (z = sum of differences / sqrt(sum of variances): the sets' samples together) must
// still agree, which a bias too small for one set to show would not. It prints the p-values of
// the old design too, naive on path's seeds. With each block's z taken as normal, the every-light
// case failed its uniformity check (KS p 5e-5: 12 of 40 sets below alpha) while its pooled
// differences agreed (p 0.94): no bias, but tails far heavier than chi-square's, from blocks of
// almost no noise (bench/results/2026-12-05-reference-agreement.md). With Student's t at the
// Welch-Satterthwaite degrees of freedom (measureAgreement): 1 of 40 sets below alpha (a block of
// 64 noisy pixels, z 4.6: the pixels' heavy tails, which no t law captures), pooled p 0.94; the
// p-values now lean high (KS p 0.0024 every light, 0.0028 transmissive: conservative, the
// effective degrees of freedom of a sum of one-degree terms are underestimated), so both
// calibration checks still fail their KS line, on the safe side.
struct Calibration {
    std::vector<double> pValues;
    double pooledChi2 = 0.0;
    int pooledDof = 0;
    double pooledP = 1.0;
    std::string pooledWorst;  // the block means whose pooled |z| > 3, with z
    std::string failures;     // the sets that fail at kChi2Alpha, with their worst blocks
};

Calibration calibrate(const render::SceneDescription& scene, int pathSpp, int naiveSpp, int sets,
                      bool naiveOnPathSeeds) {
    Calibration c;
    std::vector<double> difference, variance;
    for (int k = 0; k < sets; ++k) {
        const std::uint64_t pathSeed = 4 * k + 1, naiveSeed = naiveOnPathSeeds ? pathSeed : pathSeed + 2;
        const Agreement a = measureAgreement(scene, pathSpp, naiveSpp, pathSeed, naiveSeed);
        c.pValues.push_back(a.pValue);
        if (a.pValue < test::kChi2Alpha)
            c.failures += "\n  set " + std::to_string(k) + ": chi2 " + std::to_string(a.chi2) + " over " +
                          std::to_string(a.noisy) + ";" + a.worst;
        difference.resize(a.difference.size(), 0.0);
        variance.resize(a.variance.size(), 0.0);
        for (std::size_t i = 0; i < a.difference.size(); ++i) {
            difference[i] += a.difference[i];
            variance[i] += a.variance[i];
        }
    }
    for (std::size_t i = 0; i < difference.size(); ++i)
        if (variance[i] > 0.0) {
            const double z = difference[i] / std::sqrt(variance[i]);
            c.pooledChi2 += z * z;
            ++c.pooledDof;
            if (std::abs(z) > 3.0)
                c.pooledWorst += " block " + std::to_string(i / 3) + " channel " + std::to_string(i % 3) + ": z " +
                                 std::to_string(z) + ";";
        }
    c.pooledP = test::upperIncompleteGammaQ(0.5 * c.pooledDof, 0.5 * c.pooledChi2);
    return c;
}

std::string describe(const Calibration& c) {
    std::vector<double> sorted = c.pValues;
    std::sort(sorted.begin(), sorted.end());
    const auto below = [&](double level) {
        return std::count_if(sorted.begin(), sorted.end(), [&](double p) { return p < level; });
    };
    std::string text = "KS p " + std::to_string(test::kolmogorovSmirnovUniformP(c.pValues)) +
                       "; below 0.05: " + std::to_string(below(0.05)) + ", below 0.01: " + std::to_string(below(0.01)) +
                       ", below alpha: " + std::to_string(below(test::kChi2Alpha)) + " of " +
                       std::to_string(sorted.size()) + "; pooled chi2 " + std::to_string(c.pooledChi2) + " over " +
                       std::to_string(c.pooledDof) + ", p " + std::to_string(c.pooledP) + c.pooledWorst +
                       "\n  p-values by seed set (the first: path's seeds 1 and 2):";
    for (double p : c.pValues) text += " " + std::to_string(p);
    text += c.failures;
    return text;
}

void expectCalibrated(const char* name, const render::SceneDescription& scene, int pathSpp, int naiveSpp, int sets) {
    const Calibration independent = calibrate(scene, pathSpp, naiveSpp, sets, false);
    const Calibration shared = calibrate(scene, pathSpp, naiveSpp, sets, true);
    std::printf("%s, independent seeds: %s\n%s, naive on path's seeds: %s\n", name, describe(independent).c_str(), name,
                describe(shared).c_str());
    EXPECT_GT(test::kolmogorovSmirnovUniformP(independent.pValues), 0.01);
    EXPECT_GT(independent.pooledP, test::kChi2Alpha);
}

TEST(ReferenceAgreement, DISABLED_EveryLightTypeStatisticIsCalibrated) {
    expectCalibrated("every light type", everyLightScene(), 128, 1024, 40);
}

TEST(ReferenceAgreement, DISABLED_TransmissiveStatisticIsCalibrated) {
    expectCalibrated("transmissive", transmissiveScene(), 96, 512, 20);
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
