// Equiangular distance sampling (media/equiangular.h): the samples follow the density pdf()
// claims (chi-square over the segment, through the generic harness), the density integrates to 1
// over the segment, including an unbounded one, and it is exactly the closed form
// D / ((thetaB - thetaA) (D^2 + (t - Delta)^2)); and a light whose centre lies on the ray's line
// keeps a finite density that its samples still follow.
#include "media/equiangular.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/chi2.h"

namespace fluence::media {
namespace {

struct Case {
    const char* what;
    Vec3f origin, direction;
    float tMin, tMax;
    Vec3f centre;
};

// Chi-square tests in this file: one per case, at the level that keeps the family-wide rate of
// the sampling suites (tests/support/chi2.h).
const Case kCases[] = {
    {"centre beside the middle", Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 0.0f, 4.0f, Vec3f(2.0f, 0.3f, 0.0f)},
    {"centre behind the start", Vec3f(0.0f), normalize(Vec3f(1.0f, 1.0f, 0.0f)), 0.5f, 3.0f, Vec3f(-1.0f, 0.0f, 0.5f)},
    {"centre beyond the end, far", Vec3f(1.0f, 2.0f, 3.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 2.0f,
     Vec3f(1.0f, 2.5f, -40.0f)},
    {"centre near the line", Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f), 0.0f, 2.0f, Vec3f(0.01f, 1.2f, 0.0f)},
    {"centre on the line", Vec3f(0.0f), Vec3f(0.0f, 1.0f, 0.0f), 0.0f, 2.0f, Vec3f(0.0f, 1.2f, 0.0f)},
};

TEST(EquiangularDistance, SamplesFollowThePdf) {
    for (const Case& c : kCases) {
        const EquiangularDistance d(c.origin, c.direction, c.tMin, c.tMax, c.centre);
        const test::Chi2Result r =
            test::chi2IntervalTest([&](SampleStream& rng) { return std::optional<double>(d.sample(rng.next())); },
                                   [&](double t) { return double(d.pdf(float(t))); }, c.tMin, c.tMax);
        std::printf("[ measured ] %s: %s\n", c.what, r.report.c_str());
        EXPECT_GT(r.pValue, test::kChi2Alpha) << c.what << ": " << r.report;
    }
}

// The trapezoidal rule over 2^20 steps (2^22 near a centre on the line, where the density peaks).
double integral(const EquiangularDistance& d, double t0, double t1, int steps) {
    const double h = (t1 - t0) / steps;
    double sum = 0.5 * (d.pdf(float(t0)) + d.pdf(float(t1)));
    for (int i = 1; i < steps; ++i) sum += d.pdf(float(t0 + i * h));
    return sum * h;
}

TEST(EquiangularDistance, PdfIntegratesToOne) {
    for (const Case& c : kCases) {
        const EquiangularDistance d(c.origin, c.direction, c.tMin, c.tMax, c.centre);
        const bool peaked =
            dot(c.centre - c.origin, c.direction) > 0.0f && length(cross(c.centre - c.origin, c.direction)) < 0.1f;
        EXPECT_NEAR(integral(d, c.tMin, c.tMax, peaked ? 1 << 22 : 1 << 20), 1.0, 1e-3) << c.what;
    }
    // Unbounded: t in [0, inf) for a centre 1 unit off the line at Delta = 2. Beyond T the density
    // is D / ((thetaB - thetaA) (D^2 + (t - Delta)^2)) and integrates to
    // (pi / 2 - atan((T - Delta) / D)) / (thetaB - thetaA) in closed form.
    const EquiangularDistance unbounded(Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 0.0f,
                                        std::numeric_limits<float>::infinity(), Vec3f(2.0f, 1.0f, 0.0f));
    const double thetaA = std::atan(-2.0), thetaB = 0.5 * 3.14159265358979323846, far = 200.0;
    const double tail = (thetaB - std::atan(far - 2.0)) / (thetaB - thetaA);
    EXPECT_NEAR(integral(unbounded, 0.0, far, 1 << 22) + tail, 1.0, 1e-3);
    EXPECT_GT(unbounded.sample(0.999999f), 100.0f);
}

TEST(EquiangularDistance, PdfIsTheClosedForm) {
    // Centre (2, 0.3, 0) beside the segment t in [0, 4] along x: Delta = 2, D = 0.3.
    const EquiangularDistance d(Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), 0.0f, 4.0f, Vec3f(2.0f, 0.3f, 0.0f));
    const double span = 2.0 * std::atan(2.0 / 0.3);
    for (double t : {0.0, 0.5, 1.9, 2.0, 3.7, 4.0})
        EXPECT_NEAR(d.pdf(float(t)), 0.3 / (span * (0.09 + (t - 2.0) * (t - 2.0))), 1e-5 * d.pdf(2.0f)) << t;
    EXPECT_EQ(d.pdf(-0.01f), 0.0f);
    EXPECT_EQ(d.pdf(4.01f), 0.0f);
    // Equal angles, equal probabilities: the median is the closest point, Delta.
    EXPECT_NEAR(d.sample(0.5f), 2.0f, 1e-5f);
}

}  // namespace
}  // namespace fluence::media
