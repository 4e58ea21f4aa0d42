// Shared by the bdpt tests: bdpt's image against `path`'s within their combined noise, over the
// image per channel and region by region, from independent batches of renders; and the open box
// both render.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators::bdpt_agreement {

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

inline Estimates estimates(const Integrator& integrator, const render::SceneDescription& desc, int spp) {
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
            auto [mean, variance] =
                pixelEstimate(x, y, [](const float* p) { return (double(p[0]) + p[1] + p[2]) / 3.0; });
            const int region = (y / kRegion) * (kSize / kRegion) + x / kRegion;
            e.regionMean[region] += mean / regionPixels;
            e.regionVariance[region] += variance / (regionPixels * regionPixels);
        }
    return e;
}

// Per channel, the image means agree within their combined standard error (a two-sided test at
// the Sidak level of the suite's family); over the regions, the sum of z^2 of the noisy ones is
// chi-square distributed.
inline void expectAgreement(const Estimates& bdpt, const Estimates& path) {
    const double zLimit = test::normalQuantile(0.5 * test::kChi2Alpha);
    for (int c = 0; c < 3; ++c) {
        const double sd = std::sqrt(bdpt.imageVariance[c] + path.imageVariance[c]);
        std::printf("[ measured ] channel %d: bdpt %.5f, path %.5f, combined sd %.5f\n", c, bdpt.imageMean[c],
                    path.imageMean[c], sd);
        EXPECT_LE(std::abs(bdpt.imageMean[c] - path.imageMean[c]), zLimit * sd)
            << "channel " << c << ": bdpt " << bdpt.imageMean[c] << " path " << path.imageMean[c] << " sd " << sd;
    }
    double chi2 = 0.0;
    int noisy = 0;
    std::string worst;
    for (int r = 0; r < kRegions; ++r) {
        const double variance = bdpt.regionVariance[r] + path.regionVariance[r];
        if (variance == 0.0) {
            EXPECT_NEAR(bdpt.regionMean[r], path.regionMean[r], 1e-5 * std::abs(path.regionMean[r]))
                << "noiseless region " << r;
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
}

// The same for bdpt and `path` rendering `scene`. Returns bdpt's estimates.
inline Estimates expectAgreement(const render::SceneDescription& scene, int bdptSpp, int pathSpp) {
    IntegratorSettings settings;
    const Estimates bdpt = estimates(Bdpt(settings), scene, bdptSpp);
    expectAgreement(bdpt, estimates(PathTracer(settings), scene, pathSpp));
    return bdpt;
}

// An open box (floor, ceiling, back and side walls; red and green sides) lit by a rect light
// under its ceiling, seen from the open side.
inline render::SceneDescription cornellBox() {
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

}  // namespace fluence::integrators::bdpt_agreement
