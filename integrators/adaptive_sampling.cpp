#include "integrators/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

#include "integrators/renderer.h"

namespace fluence::integrators {

namespace {

// The samples every pixel takes before a rule applies.
int leastSamples(const RenderSettings& settings) { return std::max(settings.minSamples, kMinSamplesForHalves); }

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

// pixelVariance of every pixel of the film, row by row.
std::vector<double> pixelVariances(const Film& film) {
    std::vector<double> own(std::size_t(film.width()) * std::size_t(film.height()));
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) own[std::size_t(y) * film.width() + x] = pixelVariance(film, x, y);
    return own;
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

// Per pixel of the film, row by row: whether it has at least `least` samples (counts in its
// neighbours' means).
std::vector<char> countingPixels(const Film& film, std::uint32_t least) {
    std::vector<char> counts(std::size_t(film.width()) * std::size_t(film.height()));
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) counts[std::size_t(y) * film.width() + x] = film.samples(x, y) >= least;
    return counts;
}

// The mean over the others of a `sum` of `counted` values that includes pixel i's own when it counts.
double meanOfOthers(double sum, int counted, std::size_t i, const std::vector<double>& own,
                    const std::vector<char>& counts) {
    const int others = counted - (counts[i] ? 1 : 0);
    return others > 0 ? (sum - (counts[i] ? own[i] : 0.0)) / others : own[i];
}

// The mean of `own` over each pixel's neighbourhood (see the header): its neighbours within
// kNeighbourhoodRadius and within its block that have at least `least` samples, the pixel itself
// left out; its own value when no neighbour counts. Summed by rows, then the rows' sums by columns
// (2 (2 r + 1) reads a pixel, not (2 r + 1)^2).
std::vector<double> neighbourhoodMeans(const Film& film, int windowX, int windowY, const std::vector<double>& own,
                                       std::uint32_t least) {
    constexpr int radius = AdaptiveSampling::kNeighbourhoodRadius;
    const int width = film.width(), height = film.height();
    const std::vector<char> counts = countingPixels(film, least);
    std::vector<double> rowSums(own.size(), 0.0);
    std::vector<int> rowCounts(own.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * width + x, row = std::size_t(y) * width;
            const int x1 = std::min(x + radius + 1, blockEnd(x, windowX, width));
            for (int u = std::max(x - radius, blockStart(x, windowX)); u < x1; ++u)
                if (counts[row + u]) {
                    rowSums[i] += own[row + u];
                    ++rowCounts[i];
                }
        }
    std::vector<double> filtered(own.size(), 0.0);
    for (int y = 0; y < height; ++y) {
        const int y0 = std::max(y - radius, blockStart(y, windowY)),
                  y1 = std::min(y + radius + 1, blockEnd(y, windowY, height));
        for (int x = 0; x < width; ++x) {
            double sum = 0.0;
            int counted = 0;
            for (int v = y0; v < y1; ++v) {
                sum += rowSums[std::size_t(v) * width + x];
                counted += rowCounts[std::size_t(v) * width + x];
            }
            const std::size_t i = std::size_t(y) * width + x;
            filtered[i] = meanOfOthers(sum, counted, i, own, counts);
        }
    }
    return filtered;
}

// The mean of `own` over each pixel's whole block (see the header), the pixel itself left out, over
// the pixels with at least `least` samples; its own value when no other counts. Each block is summed
// once and the pixel's own value taken back out (a read per pixel, not the block's 63).
std::vector<double> blockMeans(const Film& film, int windowX, int windowY, const std::vector<double>& own,
                               std::uint32_t least) {
    const int width = film.width(), height = film.height();
    const std::vector<char> counts = countingPixels(film, least);
    std::vector<double> means(own.size(), 0.0);
    for (int by = 0; by < height; by = blockEnd(by, windowY, height))
        for (int bx = 0; bx < width; bx = blockEnd(bx, windowX, width)) {
            const int x1 = blockEnd(bx, windowX, width), y1 = blockEnd(by, windowY, height);
            double sum = 0.0;
            int counted = 0;
            for (int v = by; v < y1; ++v)
                for (int u = bx; u < x1; ++u)
                    if (const std::size_t i = std::size_t(v) * width + u; counts[i]) {
                        sum += own[i];
                        ++counted;
                    }
            for (int v = by; v < y1; ++v)
                for (int u = bx; u < x1; ++u) {
                    const std::size_t i = std::size_t(v) * width + u;
                    means[i] = meanOfOthers(sum, counted, i, own, counts);
                }
        }
    return means;
}

// An active pixel of the budget rule: its deviation sqrt(a / c) and its cost per sample c.
struct BudgetPixel {
    double deviation, cost;
};

// The sample count an active pixel ends with when the budget rule's factor is t: sqrt(a / c) t,
// between what it has and `most`.
double budgetCount(const BudgetPixel& p, double t, int done, int most) {
    return std::clamp(p.deviation * t, double(done), double(most));
}

// The budget rule's factor t (counts sqrt(a / c) t) that spends `budget` (a cost) over the film,
// given the active pixels and the cost already fixed (stopped pixels'); 0 when the budget is spent,
// infinite when every active pixel may go to `most`.
double budgetFactor(const std::vector<BudgetPixel>& pixels, double fixed, double budget, int done, int most) {
    auto total = [&](double t) {
        double sum = fixed;
        for (const BudgetPixel& p : pixels) sum += p.cost * budgetCount(p, t, done, most);
        return sum;
    };
    double smallest = 0.0;
    for (const BudgetPixel& p : pixels)
        if (p.deviation > 0.0 && (smallest == 0.0 || p.deviation < smallest)) smallest = p.deviation;
    if (smallest == 0.0 || total(0.0) >= budget) return 0.0;
    double hi = most / smallest;
    if (total(hi) <= budget) return INFINITY;
    double lo = hi * 1e-12;
    for (int i = 0; i < 48; ++i) {  // bisection in the logarithm: the same steps on any machine
        const double mid = std::sqrt(lo * hi);
        (total(mid) > budget ? hi : lo) = mid;
    }
    return lo;
}

}  // namespace

bool AdaptiveSampling::enabled(const RenderSettings& settings) {
    return settings.targetError > 0.0 || settings.meanSamplesPerPixel > 0.0;
}

std::vector<double> AdaptiveSampling::neighbourhoodVariances(const Film& film, int windowX, int windowY) {
    return neighbourhoodMeans(film, windowX, windowY, pixelVariances(film), kMinSamplesForHalves);
}

std::vector<double> AdaptiveSampling::budgetVariances(const Film& film, int windowX, int windowY) {
    const std::vector<double> own = pixelVariances(film);
    std::vector<double> variances = neighbourhoodMeans(film, windowX, windowY, own, kMinSamplesForHalves);
    const std::vector<double> block = blockMeans(film, windowX, windowY, own, kMinSamplesForHalves);
    for (std::size_t i = 0; i < variances.size(); ++i) variances[i] = std::max(variances[i], block[i]);
    return variances;
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

AdaptiveSampling::PassPlan AdaptiveSampling::planPass(const Film& film, const RenderSettings& settings, int done,
                                                      int count) {
    const int width = film.width(), height = film.height();
    PassPlan plan;
    plan.samples.assign(std::size_t(width) * std::size_t(height), 0);
    auto samples = [&](std::size_t i) { return film.samples(int(i % width), int(i / width)); };
    auto active = [&](std::size_t i) { return samples(i) == std::uint32_t(done); };
    const int most = settings.samplesPerPixel;
    // Sets pixel i's samples of the pass, and adds the count it ends with, `goal` if it is active.
    auto decide = [&](std::size_t i, std::uint32_t taken, double goal) {
        plan.samples[i] = taken;
        plan.expectedTotal += active(i) ? std::uint64_t(std::max(goal, double(done + taken))) : samples(i);
    };
    const bool budgeted = enabled(settings) && settings.targetError <= 0.0;
    if (!enabled(settings) || done < leastSamples(settings)) {
        // Before the rules apply, a budget render's pixels are expected to end near its mean (an
        // upper estimate: where samples cost unevenly, the mean count ends below it). Not
        // std::clamp: --min-spp may exceed --spp (--mean-spp 1 caps at 8), and the cap wins.
        const double goal =
            budgeted ? std::min(std::max(std::ceil(settings.meanSamplesPerPixel), double(leastSamples(settings))),
                                double(most))
                     : double(most);
        for (std::size_t i = 0; i < plan.samples.size(); ++i) decide(i, active(i) ? std::uint32_t(count) : 0, goal);
        return plan;
    }
    if (!budgeted) {
        const std::vector<double> variances = neighbourhoodVariances(film, settings.windowX, settings.windowY);
        const double target = settings.targetError * settings.targetError;
        for (std::size_t i = 0; i < plan.samples.size(); ++i)
            decide(i, active(i) && variances[i] / done > target ? std::uint32_t(count) : 0, most);
        return plan;
    }
    const std::vector<double> variances = budgetVariances(film, settings.windowX, settings.windowY);
    const std::vector<double> costs = neighbourhoodCosts(film, settings.windowX, settings.windowY);
    std::vector<BudgetPixel> pixels;
    double fixed = 0.0, budget = 0.0;
    for (std::size_t i = 0; i < plan.samples.size(); ++i) {
        budget += settings.meanSamplesPerPixel * costs[i];
        if (active(i))
            pixels.push_back({std::sqrt(variances[i] / costs[i]), costs[i]});
        else
            fixed += costs[i] * samples(i);
    }
    const double t = budgetFactor(pixels, fixed, budget, done, most);
    std::size_t next = 0;
    for (std::size_t i = 0; i < plan.samples.size(); ++i) {
        const double wanted = !active(i)      ? 0.0
                              : std::isinf(t) ? most
                                              : std::round(budgetCount(pixels[next], t, done, most));
        if (active(i)) ++next;
        decide(i, std::uint32_t(std::clamp(wanted - done, 0.0, double(count))), wanted);
    }
    return plan;
}

}  // namespace fluence::integrators
