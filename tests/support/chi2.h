// A generic chi-square goodness-of-fit test for direction samplers (after Mitsuba's chi2 and
// pbrt-v4's tests): draw N directions, histogram them over the whole sphere in equal-area cells
// (cos theta x phi), integrate the claimed pdf over each cell, pool cells with an expected count
// below 5, and compute the p-value of Pearson's statistic. A sampler whose samples follow its
// pdf fails at rate `alpha` by chance; seeds are fixed, so a passing test keeps passing. The same
// test for distance samplers over an interval (chi2IntervalTest). Also here: adaptive integration
// of a density over the sphere, and the significance levels the statistical tests use.
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

// A direction sampler draws from its random stream (as many dimensions as it needs) and returns
// a unit direction, or nullopt for a rejected sample; a DirectionPdf is its density in solid
// angle, over the whole sphere (so transmission and two-sided samplers need nothing special).
using DirectionSampler = std::function<std::optional<Vec3f>(SampleStream&)>;
using DirectionPdf = std::function<double(const Vec3f&)>;

struct Chi2Options {
    int sampleCount = 1'000'000;
    int thetaBins = 31;  // equal-area rows in cos theta over [-1, 1]
    int phiBins = 61;
    std::uint64_t seed = 7;
};

// The integral of a density over a region of the sphere, with an estimate of its error.
struct SphereIntegral {
    double value = 0.0;
    double error = 0.0;  // of the quadrature only; see kFloatDensityRounding
};

// The relative rounding of a density evaluated in float, which the quadrature error does not
// include and which can be systematic (float(1/pi) is 4e-8 low): a few ulps of 1.2e-7.
inline constexpr double kFloatDensityRounding = 4 * 1.2e-7;

namespace detail {

inline constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// Midpoint rule with kPoints x kPoints points over the rectangle [z0, z1] x [phi0, phi1] of the
// sphere's (z = cos theta, phi) parametrisation, where dA = dz dphi; it also records whether the
// density was zero or positive at the points (a support edge crosses the rectangle if both).
inline constexpr int kPoints = 6;
struct Estimate {
    double value = 0.0;
    bool sawZero = false, sawPositive = false;
};
inline Estimate midpointRule(const DirectionPdf& pdf, double z0, double z1, double phi0, double phi1) {
    double cosPhi[kPoints], sinPhi[kPoints];
    for (int b = 0; b < kPoints; ++b) {
        double phi = phi0 + (b + 0.5) / kPoints * (phi1 - phi0);
        cosPhi[b] = std::cos(phi);
        sinPhi[b] = std::sin(phi);
    }
    Estimate e;
    for (int a = 0; a < kPoints; ++a) {
        double z = z0 + (a + 0.5) / kPoints * (z1 - z0);
        double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        for (int b = 0; b < kPoints; ++b) {
            double p = pdf(Vec3f(float(r * cosPhi[b]), float(r * sinPhi[b]), float(z)));
            (p > 0.0 ? e.sawPositive : e.sawZero) = true;
            e.value += p;
        }
    }
    e.value *= (z1 - z0) * (phi1 - phi0) / (kPoints * kPoints);
    return e;
}

// Adaptive integration: the rectangle's estimate `coarse` is compared with the sum of its four
// quarters' estimates; where they differ by more than `tolerance` (a peaked lobe) each quarter is
// refined in turn with half the tolerance, at most `depth` times. Where a support edge crosses
// the rectangle (the horizon, the edge of a cone) the two estimates can agree by chance while
// both are wrong, so such rectangles are refined to the full depth whatever they agree to, unless
// they hold less than the tolerance.
// The integral of a rectangle with an estimate of its error, and whether the density was seen
// to be zero or positive in it.
struct CellIntegral {
    double value = 0.0, error = 0.0;
    bool sawZero = false, sawPositive = false;
};

inline void adaptiveIntegral(const DirectionPdf& pdf, double z0, double z1, double phi0, double phi1,
                             const Estimate& coarse, double tolerance, int depth, CellIntegral& out) {
    const double zm = 0.5 * (z0 + z1), pm = 0.5 * (phi0 + phi1);
    const double quarters[4][4] = {{z0, zm, phi0, pm}, {z0, zm, pm, phi1}, {zm, z1, phi0, pm}, {zm, z1, pm, phi1}};
    Estimate estimates[4];
    double fine = 0.0;
    bool sawZero = coarse.sawZero, sawPositive = coarse.sawPositive;
    for (int q = 0; q < 4; ++q) {
        estimates[q] = midpointRule(pdf, quarters[q][0], quarters[q][1], quarters[q][2], quarters[q][3]);
        fine += estimates[q].value;
        sawZero |= estimates[q].sawZero;
        sawPositive |= estimates[q].sawPositive;
    }
    out.sawZero |= sawZero;
    out.sawPositive |= sawPositive;
    // A support edge matters only where the rectangle holds more than the tolerance (not where a
    // density underflows to zero in its far tail).
    bool edge = sawZero && sawPositive && std::max(fine, coarse.value) > tolerance;
    if ((!edge && std::abs(fine - coarse.value) <= tolerance) || depth == 0) {
        out.value += fine;
        out.error += std::abs(fine - coarse.value);
        return;
    }
    for (int q = 0; q < 4; ++q)
        adaptiveIntegral(pdf, quarters[q][0], quarters[q][1], quarters[q][2], quarters[q][3], estimates[q],
                         0.5 * tolerance, depth - 1, out);
}

// The integral of `pdf` over cell (i, j) of a thetaBins x phiBins equal-area grid: the cell is
// cut into splits x splits rectangles, each integrated adaptively until it is good to its share
// of `tolerance(coarse estimate of the cell)`.
template <typename Tolerance>
inline CellIntegral integrateCell(const DirectionPdf& pdf, int i, int j, int thetaBins, int phiBins,
                                  const Tolerance& tolerance, int splits) {
    constexpr int kMaxDepth = 7;  // kPoints * 2^7 = 768 points a side in the finest rectangles
    const double z0 = -1.0 + 2.0 * i / thetaBins, dz = 2.0 / thetaBins / splits;
    const double phi0 = kTwoPi * j / phiBins, dphi = kTwoPi / phiBins / splits;
    const double cellTolerance = tolerance(midpointRule(pdf, z0, z0 + dz * splits, phi0, phi0 + dphi * splits).value);
    CellIntegral result;
    for (int a = 0; a < splits; ++a)
        for (int b = 0; b < splits; ++b) {
            double za = z0 + a * dz, pb = phi0 + b * dphi;
            Estimate coarse = midpointRule(pdf, za, za + dz, pb, pb + dphi);
            adaptiveIntegral(pdf, za, za + dz, pb, pb + dphi, coarse, cellTolerance / splits, kMaxDepth, result);
        }
    return result;
}

// Integrals of `pdf` over every cell of a thetaBins x phiBins equal-area grid (row-major). A cell
// whose points all saw the same support (all zero, or all positive) but which borders a cell that
// saw another can still hide a support edge between its points (a small light in a corner, the
// rim of a cone along its side): it is integrated again from an 8 x 8 split (48 x 48 points).
template <typename Tolerance>
inline std::vector<CellIntegral> integrateGrid(const DirectionPdf& pdf, int thetaBins, int phiBins,
                                               const Tolerance& tolerance) {
    std::vector<CellIntegral> cells(std::size_t(thetaBins) * phiBins);
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j)
            cells[std::size_t(i) * phiBins + j] = integrateCell(pdf, i, j, thetaBins, phiBins, tolerance, 1);
    auto support = [&](int i, int j) {
        const CellIntegral& c = cells[std::size_t(i) * phiBins + (j + phiBins) % phiBins];
        return int(c.sawZero) + 2 * int(c.sawPositive);
    };
    std::vector<std::size_t> suspects;
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j) {
            int own = support(i, j);
            if (own == 3) continue;  // mixed: already refined along its edge
            bool differs = false;
            for (int di = -1; di <= 1; ++di)
                for (int dj = -1; dj <= 1; ++dj)
                    if (i + di >= 0 && i + di < thetaBins && support(i + di, j + dj) != own) differs = true;
            if (differs) suspects.push_back(std::size_t(i) * phiBins + j);
        }
    for (std::size_t c : suspects)
        cells[c] = integrateCell(pdf, int(c / phiBins), int(c % phiBins), thetaBins, phiBins, tolerance, 8);
    return cells;
}

}  // namespace detail

// The integral of a density over the whole sphere, adaptively to a relative accuracy of about
// `relativeTolerance` per cell of a 32 x 64 grid; `error` sums the refinement's last corrections.
// The grid is turned so that its poles, where (z, phi) cells degenerate and a narrow feature can
// fall between every quadrature point, lie on the x axis, away from the normal where microfacet
// distributions and near-normal lobes peak; and so that the horizon z = 0, where BSDF densities
// drop to zero, runs along cell boundaries (the grid's meridians at 90 and 270 degrees).
inline SphereIntegral integrateOverSphere(const DirectionPdf& pdf, double relativeTolerance = 1e-4) {
    constexpr int kThetaBins = 32, kPhiBins = 64;
    DirectionPdf turned = [&](const Vec3f& w) { return pdf(Vec3f(w.z, -w.y, w.x)); };
    SphereIntegral total;
    for (const detail::CellIntegral& cell : detail::integrateGrid(turned, kThetaBins, kPhiBins, [&](double coarse) {
             return relativeTolerance * std::abs(coarse) + 1e-12;
         })) {
        total.value += cell.value;
        total.error += cell.error;
    }
    return total;
}

namespace detail {

// Pearson's statistic of observed against expected counts, cells with an expected count below 5
// pooled into one, and its p-value (degrees of freedom: the cells used, less one).
inline Chi2Result pearson(const std::vector<double>& observed, const std::vector<double>& expected) {
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
    result.report = "chi2 = " + std::to_string(result.statistic) +
                    ", dof = " + std::to_string(result.degreesOfFreedom) + ", p = " + std::to_string(result.pValue) +
                    worst.str();
    return result;
}

}  // namespace detail

// Draws options.sampleCount directions (sample n from the stream (seed, 0, n)), histograms them
// in equal-area cells (cos theta x phi) over the whole sphere, integrates the pdf over each cell,
// pools cells with an expected count below 5, and returns the p-value of Pearson's statistic.
// Samples that are rejected count towards no cell but the expected counts still integrate the
// pdf, so a sampler that silently drops mass fails. Each cell's integral is refined adaptively
// until its error is below 1% of the count's standard deviation sqrt(expected), and along
// support edges to the finest level, so peaked lobes and the edges of cones are integrated
// accurately without a fine grid everywhere.
inline Chi2Result chi2SphereTest(const DirectionSampler& sample, const DirectionPdf& pdf,
                                 const Chi2Options& options = {}) {
    const int thetaBins = options.thetaBins, phiBins = options.phiBins, sampleCount = options.sampleCount;
    std::vector<double> observed(std::size_t(thetaBins) * phiBins, 0.0), expected(observed.size(), 0.0);
    auto cellOf = [&](const Vec3f& w) {
        double z = std::clamp(double(w.z), -1.0, 1.0);
        int i = std::min(thetaBins - 1, int((z + 1.0) * 0.5 * thetaBins));
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0) phi += detail::kTwoPi;
        int j = std::min(phiBins - 1, int(phi / detail::kTwoPi * phiBins));
        return std::size_t(i) * phiBins + j;
    };
    for (int n = 0; n < sampleCount; ++n) {
        SampleStream rng(options.seed, 0, std::uint64_t(n));
        if (auto w = sample(rng)) observed[cellOf(*w)] += 1.0;
    }
    std::vector<detail::CellIntegral> integrals = detail::integrateGrid(pdf, thetaBins, phiBins, [&](double coarse) {
        return 0.01 * std::sqrt(std::max(1.0, coarse * sampleCount)) / sampleCount;
    });
    for (std::size_t c = 0; c < expected.size(); ++c) expected[c] = sampleCount * integrals[c].value;
    return detail::pearson(observed, expected);
}

// The same test for a sampler of two uniform numbers (the first two of each sample's stream).
inline Chi2Result chi2SphereTest(const std::function<std::optional<Vec3f>(Vec2f)>& sample, const DirectionPdf& pdf,
                                 int sampleCount = 1'000'000, int thetaBins = 31, int phiBins = 61,
                                 std::uint64_t seed = 7) {
    return chi2SphereTest([&](SampleStream& rng) { return sample(rng.next2D()); }, pdf,
                          Chi2Options{sampleCount, thetaBins, phiBins, seed});
}

// A distance sampler draws t in [t0, t1] (t1 finite) from its stream, or nullopt for a rejected
// sample; an IntervalPdf is its density per unit length.
using DistanceSampler = std::function<std::optional<double>(SampleStream&)>;
using IntervalPdf = std::function<double(double)>;

// The chi-square test of a sampler over the interval [t0, t1]: `bins` equal cells, each cell's
// expected count the pdf integrated over it by adaptive Simpson quadrature (to 1% of the count's
// standard deviation, so peaked densities are integrated as accurately as flat ones), pooled and
// tested as chi2SphereTest's. Sample n is drawn from the stream (seed, 0, n).
inline Chi2Result chi2IntervalTest(const DistanceSampler& sample, const IntervalPdf& pdf, double t0, double t1,
                                   int bins = 101, int sampleCount = 1'000'000, std::uint64_t seed = 7) {
    std::vector<double> observed(std::size_t(bins), 0.0), expected(std::size_t(bins), 0.0);
    const double width = (t1 - t0) / bins;
    for (int n = 0; n < sampleCount; ++n) {
        SampleStream rng(seed, 0, std::uint64_t(n));
        if (const std::optional<double> t = sample(rng); t && *t >= t0 && *t <= t1)
            observed[std::size_t(std::clamp(int((*t - t0) / width), 0, bins - 1))] += 1.0;
    }
    // Simpson's rule on [a, b] refined where halving it changes the value by more than `tolerance`.
    std::function<double(double, double, double, double, double, double, int)> simpson =
        [&](double a, double b, double fa, double fm, double fb, double tolerance, int depth) {
            const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
            const double flm = pdf(lm), frm = pdf(rm);
            const double whole = (b - a) * (fa + 4.0 * fm + fb) / 6.0;
            const double left = (m - a) * (fa + 4.0 * flm + fm) / 6.0, right = (b - m) * (fm + 4.0 * frm + fb) / 6.0;
            if (depth >= 40 || std::abs(left + right - whole) <= 15.0 * tolerance)
                return left + right + (left + right - whole) / 15.0;
            return simpson(a, m, fa, flm, fm, 0.5 * tolerance, depth + 1) +
                   simpson(m, b, fm, frm, fb, 0.5 * tolerance, depth + 1);
        };
    for (int b = 0; b < bins; ++b) {
        const double a = t0 + b * width;
        // Start from 16 panels, so that a narrow peak is seen by some quadrature point.
        double integral = 0.0;
        for (int i = 0; i < 16; ++i) {
            const double pa = a + width * i / 16.0, pb = a + width * (i + 1) / 16.0;
            const double coarse = (pb - pa) * pdf(0.5 * (pa + pb));
            const double tolerance = 0.01 * std::sqrt(std::max(1.0, coarse * sampleCount)) / sampleCount / 16.0;
            integral += simpson(pa, pb, pdf(pa), pdf(0.5 * (pa + pb)), pdf(pb), tolerance, 0);
        }
        expected[std::size_t(b)] = sampleCount * integral;
    }
    return detail::pearson(observed, expected);
}

// The level at which each of `familySize` independent tests must be run for a family-wide
// false-failure rate of `familyAlpha` (Sidak's correction): 1 - (1 - familyAlpha)^(1/familySize).
inline double sidakAlpha(double familySize, double familyAlpha = 0.01) {
    return 1.0 - std::pow(1.0 - familyAlpha, 1.0 / familySize);
}

// Significance of one chi-square test of the sampling, light and integrator suites: they run
// about twenty, so each uses the Sidak-corrected level for a family-wide rate of 1%.
inline constexpr double kChi2FamilySize = 20;
inline const double kChi2Alpha = sidakAlpha(kChi2FamilySize);

// The one-sided standard-normal quantile z with P(Z > z) = alpha, for tolerances of k standard
// errors chosen from a significance level (bisection on erfc; alpha in (0, 0.5)).
inline double normalQuantile(double alpha) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace fluence::test
