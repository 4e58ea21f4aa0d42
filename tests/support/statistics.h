// The sample mean of independent values with its standard error, for tests whose tolerance
// comes from the estimator's own spread, Welch's t band for two such means, and the
// Kolmogorov-Smirnov test of p-values' uniformity (the calibration of a statistical test).
//
// The values added must be independent estimates of ONE expected value: whole renders (or batches
// of samples) with different seeds, or pixels of a region whose expected radiance is uniform. The
// pixels of an image with contrast are not: their spread holds the contrast too, and a band built
// from it lets a bias pass (hence batches in the radiosity and sppm tests).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace fluence::test {

class MeanEstimate {
public:
    void add(double v) {
        sum_ += v;
        sumSquares_ += v * v;
        ++count_;
    }
    int count() const { return count_; }
    double mean() const { return sum_ / count_; }
    double standardError() const {
        double m = mean();
        return std::sqrt(std::max(0.0, sumSquares_ / count_ - m * m) / count_);
    }
    // The estimate of k times the same values.
    MeanEstimate scaled(double k) const {
        MeanEstimate e = *this;
        e.sum_ *= k;
        e.sumSquares_ *= k * k;
        return e;
    }
    // The standard error from the unbiased sample variance (divisor n - 1), the one Student's t uses.
    double unbiasedStandardError() const {
        const double m = mean();
        return std::sqrt(std::max(0.0, sumSquares_ - count_ * m * m) / (count_ - 1) / count_);
    }

private:
    double sum_ = 0.0, sumSquares_ = 0.0;
    int count_ = 0;
};

// The regularised incomplete beta function I_x(a, b), from its continued fraction (evaluated
// with the modified Lentz method) on the side x < (a + 1) / (a + b + 2) where it converges fast,
// and the symmetry I_x(a, b) = 1 - I_{1-x}(b, a) on the other.
inline double regularizedIncompleteBeta(double a, double b, double x) {
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 1.0;
    if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - regularizedIncompleteBeta(b, a, 1.0 - x);
    const double front =
        std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x)) / a;
    constexpr double kTiny = 1e-300;
    double f = 1.0, c = 1.0, d = 0.0;
    for (int i = 0; i <= 400; ++i) {
        const int m = i / 2;
        double numerator;
        if (i == 0)
            numerator = 1.0;
        else if (i % 2 == 0)
            numerator = m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
        else
            numerator = -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
        d = 1.0 + numerator * d;
        d = 1.0 / (std::abs(d) < kTiny ? kTiny : d);
        c = 1.0 + numerator / (std::abs(c) < kTiny ? kTiny : c);
        const double step = c * d;
        f *= step;
        if (std::abs(1.0 - step) < 1e-14) break;
    }
    return front * (f - 1.0);
}

// P(T > t) for Student's t with `dof` degrees of freedom (t >= 0).
inline double studentUpperTail(double t, double dof) {
    return 0.5 * regularizedIncompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
}

// The one-sided quantile t with P(T > t) = alpha (alpha in (0, 0.5)), by bisection.
inline double studentQuantile(double alpha, double dof) {
    double lo = 0.0, hi = 1e3;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (studentUpperTail(mid, dof) > alpha ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Half-width of the two-sided band, at significance `alpha`, within which two independent means
// agree: Welch's t test (unbiased variances, Welch-Satterthwaite degrees of freedom). Each
// estimate needs at least two values.
inline double welchBand(const MeanEstimate& a, const MeanEstimate& b, double alpha) {
    const double va = std::pow(a.unbiasedStandardError(), 2), vb = std::pow(b.unbiasedStandardError(), 2);
    const double variance = va + vb;
    if (variance == 0.0) return 0.0;
    const double dof = variance * variance / (va * va / (a.count() - 1) + vb * vb / (b.count() - 1));
    return studentQuantile(alpha / 2.0, dof) * std::sqrt(variance);
}

// The p-value of the Kolmogorov-Smirnov test that `values` (in [0, 1]) are uniform: the largest
// distance D between their empirical distribution and the identity, and P(D' > D) from the
// Kolmogorov distribution, Q(l) = 2 sum_j (-1)^(j-1) exp(-2 j^2 l^2), at l = (sqrt(n) + 0.12 +
// 0.11 / sqrt(n)) D (Stephens' correction for small n, within 1% from n = 10 on).
inline double kolmogorovSmirnovUniformP(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const double n = double(values.size());
    double d = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i)
        d = std::max({d, (double(i) + 1.0) / n - values[i], values[i] - double(i) / n});
    const double l = (std::sqrt(n) + 0.12 + 0.11 / std::sqrt(n)) * d;
    if (l < 0.2) return 1.0;  // P(D' <= D) < 1e-10; the series converges slowly here
    double q = 0.0;
    for (int j = 1; j <= 100; ++j) q += (j % 2 ? 2.0 : -2.0) * std::exp(-2.0 * j * j * l * l);
    return std::clamp(q, 0.0, 1.0);
}

}  // namespace fluence::test
