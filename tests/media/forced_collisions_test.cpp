// Forced collisions (media/forced_collisions.h): the points follow the density
// p(t) = s(t) exp(-S(t)) / (1 - exp(-S(tMax))) over the largest channel's majorant s (chi-square
// against its distribution function, through a chromatic ramp's segments and an unbounded
// homogeneous medium with a loose majorant); each stratified point lies in its stratum and
// carries the weight 1 / (count p(t)); the weighted sum estimates integrals over the ray without
// bias (normal-theory error); a ray that meets no majorant gets no point.
#include "media/forced_collisions.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "media/homogeneous_medium.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

// Chi-square tests: 2; normal-theory checks: 2 rays x 2 counts x 2 integrands; 1% family-wide each.
const double kChi2Level = test::sidakAlpha(2);
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(8));

// S(t), the largest channel's majorant integrated from 0 to t along `ray`, from the medium's
// segments (the test's own reading of DENSITY).
class MajorantDepth {
public:
    MajorantDepth(const Medium& medium, const MediumRay& ray) : tMax_(ray.tMax) {
        medium.majorants(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const MajorantSegment& s) {
            segments_.push_back(s);
            return true;
        });
    }
    double operator()(double t) const {
        double depth = 0.0;
        for (const MajorantSegment& s : segments_) {
            double from = std::max(0.0, double(s.tMin)), to = std::min({double(s.tMax), double(tMax_), t});
            if (to > from) depth += maxComponent(s.sigmaMaj) * (to - from);
        }
        return depth;
    }
    double rate(double t) const {
        for (const MajorantSegment& s : segments_)
            if (t >= s.tMin && t < s.tMax) return maxComponent(s.sigmaMaj);
        return 0.0;
    }
    double total() const { return (*this)(tMax_); }
    double cdf(double t) const { return -std::expm1(-(*this)(t)) / -std::expm1(-total()); }
    double density(double t) const { return rate(t) * std::exp(-(*this)(t)) / -std::expm1(-total()); }

private:
    float tMax_;
    std::vector<MajorantSegment> segments_;
};

std::vector<ForcedCollision> draw(const Medium& medium, const MediumRay& ray, int count, SampleStream& rng) {
    std::vector<float> u(static_cast<std::size_t>(count));
    for (float& x : u) x = rng.next();
    std::vector<ForcedCollision> points(u.size());
    points.resize(static_cast<std::size_t>(sampleForcedCollisions(medium, ray, u, points)));
    return points;
}

// Pearson's chi-square of single points against the distribution, in 31 equal-probability bins;
// also checks every weight is 1 / p(t). Returns the p-value.
double chi2OfPoints(const Medium& medium, const MediumRay& ray, std::uint64_t seed, const std::string& what) {
    constexpr int kBins = 31, kPoints = 100'000;
    const MajorantDepth depth(medium, ray);
    std::vector<double> observed(kBins, 0.0);
    for (int n = 0; n < kPoints; ++n) {
        SampleStream rng(seed, 0, std::uint64_t(n));
        const std::vector<ForcedCollision> points = draw(medium, ray, 1, rng);
        EXPECT_EQ(points.size(), 1u);
        if (points.empty()) continue;
        EXPECT_NEAR(points[0].weight * depth.density(points[0].t), 1.0, 1e-4) << "t = " << points[0].t;
        observed[std::min(kBins - 1, int(depth.cdf(points[0].t) * kBins))] += 1.0;
    }
    double statistic = 0.0;
    const double expected = double(kPoints) / kBins;
    for (double o : observed) statistic += (o - expected) * (o - expected) / expected;
    const double p = test::upperIncompleteGammaQ(0.5 * (kBins - 1), 0.5 * statistic);
    std::printf("[ measured ] %s: chi2 %.1f over %d cells, p = %.3f\n", what.c_str(), statistic, kBins, p);
    return p;
}

// sigmaT = (0.2, 0.5, 0.1) + (0.8, -0.1, 0.3) x over 0 <= x < 3 in five segments: the largest
// channel changes from segment to segment. The ray stops inside, at x = 2.5.
const test::RampMedium kRamp(RGB(0.2f, 0.5f, 0.1f), RGB(0.8f, -0.1f, 0.3f), 3.0f, 5, true);
const MediumRay kRampRay{Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 2.5f};

TEST(ForcedCollisions, PointsFollowTheConditionedMajorantDensity) {
    EXPECT_GT(chi2OfPoints(kRamp, kRampRay, 61, "chromatic ramp"), kChi2Level);
    const HomogeneousMedium fog({RGB(0.3f, 0.1f, 0.2f), RGB(0.4f, 0.2f, 0.5f)});
    const test::RescaledBoundsMedium loose(fog, 2.0f, 0.0f);
    EXPECT_GT(chi2OfPoints(loose, {Vec3f(0.0f), normalize(Vec3f(1.0f, -2.0f, 0.5f))}, 62, "unbounded, loose"),
              kChi2Level);
}

TEST(ForcedCollisions, StratifiedPointsLieInTheirStrataInOrder) {
    const MajorantDepth depth(kRamp, kRampRay);
    for (int n = 0; n < 2000; ++n) {
        SampleStream rng(63, 0, std::uint64_t(n));
        const std::vector<ForcedCollision> points = draw(kRamp, kRampRay, 3, rng);
        ASSERT_EQ(points.size(), 3u);
        for (int k = 0; k < 3; ++k) {
            const double c = depth.cdf(points[std::size_t(k)].t);
            EXPECT_GE(c, k / 3.0 - 1e-5);
            EXPECT_LE(c, (k + 1) / 3.0 + 1e-5);
            EXPECT_NEAR(points[std::size_t(k)].weight * 3.0 * depth.density(points[std::size_t(k)].t), 1.0, 1e-4);
            if (k > 0) {
                EXPECT_GE(points[std::size_t(k)].t, points[std::size_t(k - 1)].t);
            }
        }
    }
}

TEST(ForcedCollisions, WeightedPointsEstimateIntegralsAlongTheRay) {
    const HomogeneousMedium fog({RGB(0.3f), RGB(0.5f)});
    const MediumRay fogRay{Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f)};
    struct Case {
        const char* what;
        const Medium& medium;
        MediumRay ray;
        std::function<double(double)> f;
        double integral;
    };
    const Case cases[] = {
        {"ramp, 1 + sin t", kRamp, kRampRay, [](double t) { return 1.0 + std::sin(t); }, 3.5 - std::cos(2.5)},
        {"ramp, t^2", kRamp, kRampRay, [](double t) { return t * t; }, 2.5 * 2.5 * 2.5 / 3.0},
        {"unbounded fog, exp(-t / 2)", fog, fogRay, [](double t) { return std::exp(-0.5 * t); }, 2.0},
        {"unbounded fog, t exp(-t)", fog, fogRay, [](double t) { return t * std::exp(-t); }, 1.0},
    };
    for (const Case& c : cases)
        for (int count : {1, 4}) {
            test::MeanEstimate estimate;
            for (int n = 0; n < 40'000; ++n) {
                SampleStream rng(64, std::uint64_t(count), std::uint64_t(n));
                double sum = 0.0;
                for (const ForcedCollision& p : draw(c.medium, c.ray, count, rng)) sum += c.f(p.t) * p.weight;
                estimate.add(sum);
            }
            std::printf("[ measured ] %s, %d points: %.5f +- %.5f (exact %.5f)\n", c.what, count, estimate.mean(),
                        estimate.standardError(), c.integral);
            EXPECT_NEAR(estimate.mean(), c.integral, kZ * estimate.standardError()) << c.what << ", " << count;
        }
}

TEST(ForcedCollisions, ARayThatMeetsNoMajorantGetsNoPoint) {
    std::array<float, 2> u{0.3f, 0.7f};
    std::array<ForcedCollision, 2> points;
    EXPECT_EQ(sampleForcedCollisions(kRamp, {Vec3f(4.0f, 0.0f, 0.0f), Vec3f(1.0f, 0.0f, 0.0f), 10.0f}, u, points), 0);
    EXPECT_EQ(sampleForcedCollisions(kRamp, {Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 0.0f}, u, points), 0);
}

}  // namespace
}  // namespace fluence::media
