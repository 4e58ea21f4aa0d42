// A generic chi-square goodness-of-fit test for direction samplers (after Mitsuba's chi2 and
// pbrt-v4's tests): draw N directions, histogram them over the sphere in equal-area cells
// (cos theta x phi), integrate the claimed pdf over each cell, pool cells with an expected count
// below 5, and compute the p-value of Pearson's statistic. A sampler whose samples follow its
// pdf fails at rate `alpha` by chance; seeds are fixed, so a passing test keeps passing.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/random.h"
#include "core/vec.h"

namespace fluence::test {

// Regularised upper incomplete gamma Q(a, x) (series for x < a + 1, continued fraction
// otherwise; Numerical Recipes §6.2 formulation, written from the definitions).
inline double upperIncompleteGammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-15) break;
        }
        return 1.0 - sum * std::exp(logPrefix);
    }
    // Lentz's method for the continued fraction.
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::abs(c) < 1e-300) c = 1e-300;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(logPrefix) * h;
}

struct Chi2Result {
    double pValue = 0.0;
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    std::string report;  // cells with the largest deviations, for failure messages
};

// A sampler returns a unit direction (or nullopt for a rejected sample); `pdf` is its density
// in solid angle. Samples that are rejected count towards no cell but the expected counts still
// integrate the pdf, so a sampler that silently drops mass fails.
inline Chi2Result chi2SphereTest(const std::function<std::optional<Vec3f>(Vec2f)>& sample,
                                 const std::function<double(const Vec3f&)>& pdf, int sampleCount = 1'000'000,
                                 int thetaBins = 31, int phiBins = 61, std::uint64_t seed = 7) {
    const double kTwoPi = 2.0 * 3.14159265358979323846;
    std::vector<double> observed(std::size_t(thetaBins) * phiBins, 0.0), expected(observed.size(), 0.0);
    auto cellOf = [&](const Vec3f& w) {
        double z = std::clamp(double(w.z), -1.0, 1.0);
        int i = std::min(thetaBins - 1, int((z + 1.0) * 0.5 * thetaBins));
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0) phi += kTwoPi;
        int j = std::min(phiBins - 1, int(phi / kTwoPi * phiBins));
        return std::size_t(i) * phiBins + j;
    };
    for (int n = 0; n < sampleCount; ++n) {
        SampleStream rng(seed, 0, std::uint64_t(n));
        if (auto w = sample(rng.next2D())) observed[cellOf(*w)] += 1.0;
    }
    // Integrate the pdf over each cell with a midpoint rule in (z, phi), where dA = dz dphi.
    // Where the pdf drops to zero (the edge of a cone or of a light), a coarse grid misjudges the
    // cells the edge crosses: every cell that straddles a zero/non-zero boundary, or borders a
    // cell on the other side of one, is integrated again on a 16x finer grid.
    const double dz = 2.0 / thetaBins, dphi = kTwoPi / phiBins;
    enum Support : char { kZero, kPositive, kMixed };
    auto integrateCell = [&](int i, int j, int sub, Support& support) {
        double sum = 0.0;
        bool sawZero = false, sawPositive = false;
        for (int a = 0; a < sub; ++a)
            for (int b = 0; b < sub; ++b) {
                double z = -1.0 + (i + (a + 0.5) / sub) * dz;
                double phi = (j + (b + 0.5) / sub) * dphi;
                double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                double p = pdf(Vec3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
                (p > 0.0 ? sawPositive : sawZero) = true;
                sum += p;
            }
        support = sawZero && sawPositive ? kMixed : (sawPositive ? kPositive : kZero);
        return sum / (double(sub) * sub) * dz * dphi * sampleCount;
    };
    std::vector<Support> support(observed.size());
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j)
            expected[std::size_t(i) * phiBins + j] = integrateCell(i, j, 8, support[std::size_t(i) * phiBins + j]);
    auto nearEdge = [&](int i, int j) {
        Support own = support[std::size_t(i) * phiBins + j];
        if (own == kMixed) return true;
        for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj) {
                int ni = i + di, nj = (j + dj + phiBins) % phiBins;
                if (ni >= 0 && ni < thetaBins && support[std::size_t(ni) * phiBins + nj] != own) return true;
            }
        return false;
    };
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j)
            if (nearEdge(i, j)) {
                Support ignored;
                expected[std::size_t(i) * phiBins + j] = integrateCell(i, j, 128, ignored);
            }
    // Pool low-expectation cells into one.
    Chi2Result result;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    std::ostringstream worst;
    for (std::size_t c = 0; c < observed.size(); ++c) {
        if (expected[c] < 5.0) {
            pooledObserved += observed[c];
            pooledExpected += expected[c];
            continue;
        }
        double d = observed[c] - expected[c];
        result.statistic += d * d / expected[c];
        ++cells;
        if (d * d / expected[c] > 30.0)
            worst << " cell " << c << ": observed " << observed[c] << " expected " << expected[c] << ";";
    }
    if (pooledExpected >= 5.0) {
        double d = pooledObserved - pooledExpected;
        result.statistic += d * d / pooledExpected;
        ++cells;
    } else if (pooledObserved > 5.0 * std::max(1.0, pooledExpected) + 10.0) {
        // Samples land where the pdf says there is (almost) nothing.
        result.statistic = 1e9;
        worst << " " << pooledObserved << " samples where the pdf integrates to " << pooledExpected << ";";
    }
    result.degreesOfFreedom = std::max(1, cells - 1);
    result.pValue = upperIncompleteGammaQ(0.5 * result.degreesOfFreedom, 0.5 * result.statistic);
    result.report = "chi2 = " + std::to_string(result.statistic) + ", dof = " + std::to_string(result.degreesOfFreedom) +
                    ", p = " + std::to_string(result.pValue) + worst.str();
    return result;
}

// Significance of one chi-square test: the suite runs about twenty of them, so each uses the
// Sidak-corrected level for a family-wide false-failure rate of 1%: 1 - (1 - 0.01)^(1/20).
inline constexpr double kChi2FamilySize = 20;
inline const double kChi2Alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChi2FamilySize);

}  // namespace fluence::test
