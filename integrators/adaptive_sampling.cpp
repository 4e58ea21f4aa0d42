#include "integrators/adaptive_sampling.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "integrators/renderer.h"

namespace fluence::integrators {

namespace {

// The samples every pixel takes before a rule applies.
// (a power of two: where a step ends).
std::uint32_t leastSamples(const RenderSettings& settings) {
    return std::bit_ceil(std::uint32_t(std::max(settings.minSamples, kMinSamplesForHalves)));
}

// Pixel (x, y)'s own relative variance per sample (see the header); 0 below kMinSamplesForHalves.
double pixelVariance(const Film& film, int x, int y) {
    const std::uint32_t n = film.samples(x, y);
    if (n < std::uint32_t(kMinSamplesForHalves)) return 0.0;
    const Film::HalfMeans h = film.halfMeans(x, y);
    double sum = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
        const double mean = (h.firstCount * h.first[c] + h.secondCount * h.second[c]) / n;
        sum += h.meanVariance(c) * n / (mean * mean + AdaptiveSampling::kRelativeFloor);
    }
    return sum / 3.0;
}

// The first coordinate of the film's range [first, last) on an axis that shares a block with
// `coordinate`, and the last; image coordinate = film coordinate + offset.
int blockStart(int coordinate, int offset) {
    const int image = coordinate + offset;
    return std::max(0, image - image % AdaptiveSampling::kBlockSize - offset);
}
int blockEnd(int coordinate, int offset, int size) {
    const int image = coordinate + offset;
    return std::min(size, image - image % AdaptiveSampling::kBlockSize + AdaptiveSampling::kBlockSize - offset);
}

// The mean of `own` over each pixel's neighbourhood (see the header): its 3x3 neighbours within its
// block that have at least `least` samples, the pixel itself left out; its own value when no
// neighbour counts.
std::vector<double> neighbourhoodMeans(const Film& film, int windowX, int windowY, const std::vector<double>& own,
                                       std::uint32_t least) {
    const int width = film.width(), height = film.height();
    std::vector<double> filtered(own.size(), 0.0);
    for (int y = 0; y < height; ++y) {
        const int y0 = std::max(y - 1, blockStart(y, windowY)), y1 = std::min(y + 2, blockEnd(y, windowY, height));
        for (int x = 0; x < width; ++x) {
            const int x0 = std::max(x - 1, blockStart(x, windowX)), x1 = std::min(x + 2, blockEnd(x, windowX, width));
            double sum = 0.0;
            int counted = 0;
            for (int v = y0; v < y1; ++v)
                for (int u = x0; u < x1; ++u)
                    if ((u != x || v != y) && film.samples(u, v) >= least) {
                        sum += own[std::size_t(v) * width + u];
                        ++counted;
                    }
            const std::size_t i = std::size_t(y) * width + x;
            filtered[i] = counted > 0 ? sum / counted : own[i];
        }
    }
    return filtered;
}

// The count a pixel that goes on from `n` samples ends its step at: the next power of two, at most
// `most` (see the header).
std::uint32_t stepEnd(std::uint32_t n, int most) { return std::min(std::bit_ceil(n + 1), std::uint32_t(most)); }

// One step the budget rule may give a pixel: from `from` samples to stepEnd(from), lowering the
// pixel's relative MSE a (1 / from - 1 / to) for the cost c (to - from); `gain` is the ratio.
struct BudgetStep {
    double gain;
    std::uint32_t pixel, from, to;
};

}  // namespace

bool AdaptiveSampling::enabled(const RenderSettings& settings) {
    return settings.targetError > 0.0 || settings.meanSamplesPerPixel > 0.0;
}

std::vector<double> AdaptiveSampling::neighbourhoodVariances(const Film& film, int windowX, int windowY) {
    const int width = film.width(), height = film.height();
    std::vector<double> own(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) own[std::size_t(y) * width + x] = pixelVariance(film, x, y);
    return neighbourhoodMeans(film, windowX, windowY, own, kMinSamplesForHalves);
}

std::vector<double> AdaptiveSampling::neighbourhoodCosts(const Film& film, int windowX, int windowY) {
    const int width = film.width(), height = film.height();
    std::vector<double> own(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t n = film.samples(x, y);
            own[std::size_t(y) * width + x] = n > 0 ? film.cost(x, y) / n : 0.0;
        }
    std::vector<double> costs = neighbourhoodMeans(film, windowX, windowY, own, 1);
    for (double& c : costs)
        if (!(c > 0.0)) c = 1.0;  // samples added uncounted: every sample alike
    return costs;
}

double AdaptiveSampling::uniformSamplesOfTheSameCost(const Film& film) {
    double total = 0.0, perSample = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            if (const std::uint32_t n = film.samples(x, y); n > 0) {
                total += film.cost(x, y);
                perSample += film.cost(x, y) / n;
            }
    if (perSample > 0.0) return total / perSample;
    const double pixels = double(film.width()) * double(film.height());  // uncounted: every sample alike
    return pixels > 0.0 ? double(film.totalSamples()) / pixels : 0.0;
}

std::vector<std::uint32_t> AdaptiveSampling::budgetCounts(const Film& film, const RenderSettings& settings, int done) {
    const int width = film.width(), most = settings.samplesPerPixel;
    const std::vector<double> variances = neighbourhoodVariances(film, settings.windowX, settings.windowY);
    const std::vector<double> costs = neighbourhoodCosts(film, settings.windowX, settings.windowY);
    std::vector<std::uint32_t> counts(variances.size());
    std::vector<BudgetStep> steps;
    double left = 0.0;  // the budget, less what the pixels' samples cost
    for (std::size_t i = 0; i < counts.size(); ++i) {
        counts[i] = film.samples(int(i % width), int(i / width));
        left += costs[i] * (settings.meanSamplesPerPixel - counts[i]);
        if (counts[i] != std::uint32_t(done)) continue;  // stopped
        for (std::uint32_t from = counts[i], to; from < std::uint32_t(most); from = to) {
            to = stepEnd(from, most);
            steps.push_back(
                {variances[i] * (1.0 / from - 1.0 / to) / (costs[i] * (to - from)), std::uint32_t(i), from, to});
        }
    }
    // The best gains first; a pixel's steps are in its order (each gains less than the one before).
    std::sort(steps.begin(), steps.end(), [](const BudgetStep& a, const BudgetStep& b) {
        return a.gain != b.gain ? a.gain > b.gain : a.pixel != b.pixel ? a.pixel < b.pixel : a.from < b.from;
    });
    for (const BudgetStep& step : steps) {
        const double cost = costs[step.pixel] * (step.to - step.from);
        if (counts[step.pixel] != step.from || cost > left) continue;  // a step before it was not taken, or too dear
        counts[step.pixel] = step.to;
        left -= cost;
    }
    return counts;
}

std::vector<std::uint32_t> AdaptiveSampling::planPass(const Film& film, const RenderSettings& settings, int done,
                                                      int count) {
    const int width = film.width(), height = film.height();
    std::vector<std::uint32_t> plan(std::size_t(width) * std::size_t(height), 0);
    auto active = [&](std::size_t i) { return film.samples(int(i % width), int(i / width)) == std::uint32_t(done); };
    const bool ruled = enabled(settings) && std::uint32_t(done) >= leastSamples(settings);
    if (!ruled) {
        for (std::size_t i = 0; i < plan.size(); ++i) plan[i] = active(i) ? std::uint32_t(count) : 0;
        return plan;
    }
    // A pixel that goes on takes the pass's samples up to the end of its step.
    const std::uint32_t step =
        std::min(std::uint32_t(count), stepEnd(std::uint32_t(done), settings.samplesPerPixel) - done);
    if (!std::has_single_bit(std::uint32_t(done))) {  // within a step: the pixels still going finish it
        for (std::size_t i = 0; i < plan.size(); ++i) plan[i] = active(i) ? step : 0;
        return plan;
    }
    if (settings.targetError > 0.0) {
        const std::vector<double> variances = neighbourhoodVariances(film, settings.windowX, settings.windowY);
        const double target = settings.targetError * settings.targetError;
        for (std::size_t i = 0; i < plan.size(); ++i) plan[i] = active(i) && variances[i] / done > target ? step : 0;
        return plan;
    }
    const std::vector<std::uint32_t> ends = budgetCounts(film, settings, done);
    for (std::size_t i = 0; i < plan.size(); ++i) plan[i] = active(i) && ends[i] > std::uint32_t(done) ? step : 0;
    return plan;
}

}  // namespace fluence::integrators
