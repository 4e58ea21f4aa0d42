// The piecewise-constant image distribution the dome and textured rect lights sample with: cells
// chosen in proportion to their weights (chi-square), empty cells, rows and columns never
// chosen, pdf() agreeing with every sample, the all-zero fallback, and bad weights refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/random.h"
#include "render/light_image_distribution.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

// Draws `samples` points, checks each against pdf() and its cell's weight, and returns the count
// per cell (row-major).
std::vector<double> cellCounts(const ImageDistribution& d, int width, int height, const std::vector<float>& weights,
                               int samples) {
    double mean = 0.0;
    for (float w : weights) mean += w / double(weights.size());
    std::vector<double> counts(weights.size(), 0.0);
    for (int n = 0; n < samples; ++n) {
        ImageDistribution::Sample s = d.sample(SampleStream(13, 0, n).next2D());
        EXPECT_TRUE(s.uv.x >= 0.0f && s.uv.x < 1.0f && s.uv.y >= 0.0f && s.uv.y < 1.0f) << "sample " << n;
        int x = std::min(int(s.uv.x * width), width - 1), y = std::min(int(s.uv.y * height), height - 1);
        EXPECT_EQ(s.pdf, d.pdf(s.uv)) << "sample " << n;
        EXPECT_NEAR(s.pdf, weights[std::size_t(y) * width + x] / mean, 1e-5 * s.pdf) << "sample " << n;
        counts[std::size_t(y) * width + x] += 1.0;
    }
    return counts;
}

TEST(ImageDistribution, CellsAreChosenInProportionToTheirWeights) {
    // 9 x 6 cells: an empty row, an empty column, isolated empty cells and a 1000:1 range.
    constexpr int kWidth = 9, kHeight = 6, kSamples = 200000;
    std::vector<float> weights(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            bool empty = y == 2 || x == 4 || (x + y) % 7 == 0;
            weights[y * kWidth + x] = empty ? 0.0f : std::pow(10.0f, float((x * 5 + y * 3) % 4)) * 0.01f;
        }
    ImageDistribution d(kWidth, kHeight, weights);
    std::vector<double> counts = cellCounts(d, kWidth, kHeight, weights, kSamples);
    double total = 0.0;
    for (float w : weights) total += w;
    double chi2 = 0.0;
    int cells = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        if (weights[i] == 0.0f) {
            EXPECT_EQ(counts[i], 0.0) << "cell " << i << " is empty";
            continue;
        }
        double expected = kSamples * weights[i] / total;
        chi2 += (counts[i] - expected) * (counts[i] - expected) / expected;
        ++cells;
    }
    EXPECT_GT(test::upperIncompleteGammaQ(0.5 * (cells - 1), 0.5 * chi2), test::kChi2Alpha) << "chi2 = " << chi2;
}

TEST(ImageDistribution, OneCellTakesEverySample) {
    std::vector<float> weights(64 * 32, 0.0f);
    weights[17 * 64 + 50] = 3.0f;
    ImageDistribution d(64, 32, weights);
    std::vector<double> counts = cellCounts(d, 64, 32, weights, 1000);
    EXPECT_EQ(counts[17 * 64 + 50], 1000.0);
    EXPECT_EQ(d.pdf({50.5f / 64, 17.5f / 32}), 64.0f * 32.0f);
}

TEST(ImageDistribution, AllZeroWeightsGiveTheUniformDensity) {
    constexpr int kWidth = 5, kHeight = 4, kSamples = 40000;
    ImageDistribution d(kWidth, kHeight, std::vector<float>(kWidth * kHeight, 0.0f));
    std::vector<double> counts = cellCounts(d, kWidth, kHeight, std::vector<float>(kWidth * kHeight, 1.0f), kSamples);
    double chi2 = 0.0, expected = double(kSamples) / (kWidth * kHeight);
    for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_GT(test::upperIncompleteGammaQ(0.5 * (kWidth * kHeight - 1), 0.5 * chi2), test::kChi2Alpha)
        << "chi2 = " << chi2;
    EXPECT_EQ(d.pdf({0.3f, 0.9f}), 1.0f);
}

TEST(ImageDistribution, RefusesNegativeOrNonFiniteWeightsAndWrongSizes) {
    EXPECT_THROW(ImageDistribution(2, 1, {1.0f, -1.0f}), std::invalid_argument);
    EXPECT_THROW(ImageDistribution(2, 1, {1.0f, std::numeric_limits<float>::quiet_NaN()}), std::invalid_argument);
    EXPECT_THROW(ImageDistribution(2, 1, {1.0f, std::numeric_limits<float>::infinity()}), std::invalid_argument);
    EXPECT_THROW(ImageDistribution(2, 2, {1.0f, 1.0f}), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::render
