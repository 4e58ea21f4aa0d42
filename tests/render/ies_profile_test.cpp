// render::IesProfile: the table unfolded by its symmetry, UsdLux's angleScale and normalize.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling.h"
#include "render/ies_profile.h"
#include "tests/render/ies_test_table.h"

namespace fluence::render {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(IesProfile, UnfoldsAQuadrantTableOverTheSphere) {
    texture::IesTable table = test::quadrantTable();
    IesProfile profile(table, 0.0f, false);
    for (double v : {0.0, 10.0, 37.0, 90.0, 133.0, 180.0})
        for (double h : {0.0, 20.0, 75.0, 110.0, 200.0, 300.0, 359.0})
            EXPECT_NEAR(profile.candela(float(v * kDeg), float(h * kDeg)), test::tableCandela(table, v, h),
                        2e-4 * test::tableCandela(table, v, h))
                << v << " " << h;
}

TEST(IesProfile, OtherSymmetriesAndAHemisphere) {
    texture::IesTable half;  // 0..180 horizontal: bilateral, 0..90 vertical: a hemisphere
    half.verticalDegrees = {0.0f, 90.0f};
    half.horizontalDegrees = {0.0f, 180.0f};
    half.candela = {10.0f, 10.0f, 20.0f, 20.0f};
    IesProfile p(half, 0.0f, true);
    EXPECT_NEAR(p.candela(0.3f, float(90.0 * kDeg)), 15.0f, 1e-4f);
    EXPECT_NEAR(p.candela(0.3f, float(270.0 * kDeg)), 15.0f, 1e-4f) << "mirrored about the 0-180 plane";
    EXPECT_EQ(p.candela(float(100.0 * kDeg), 0.0f), 0.0f) << "above the table's vertical range";
    // Mean over the hemisphere: the integral of 10 + 10 phi/pi (phi in [0, pi], mirrored) is
    // 2 pi x 15 over the hemisphere, divided by 2 pi.
    EXPECT_NEAR(p.meanIntensity(), 15.0f, 0.01f);
    EXPECT_NEAR(p.factor(0.3f, float(90.0 * kDeg)), 1.0f, 1e-3f);
    texture::IesTable lateral;  // 90..270: mirrored about the 90-270 plane
    lateral.verticalDegrees = {0.0f, 180.0f};
    lateral.horizontalDegrees = {90.0f, 180.0f, 270.0f};
    lateral.candela = {1.0f, 1.0f, 3.0f, 3.0f, 5.0f, 5.0f};
    IesProfile l(lateral, 0.0f, false);
    EXPECT_NEAR(l.candela(1.0f, float(135.0 * kDeg)), 2.0f, 1e-4f);
    EXPECT_NEAR(l.candela(1.0f, float(45.0 * kDeg)), 2.0f, 1e-4f) << "the mirror of 135";
    EXPECT_NEAR(l.candela(1.0f, float(315.0 * kDeg)), 4.0f, 1e-4f) << "the mirror of 225";
}

TEST(IesProfile, AngleScaleKeepsTheZenithAndScalesTowardsIt) {
    // theta_ies = (theta - pi) / (1 + angleScale) + pi, clamped: the RenderMan formula hdEmbree uses.
    texture::IesTable table = test::quadrantTable();
    IesProfile narrow(table, -0.5f, false), wide(table, 1.0f, false), plain(table, 0.0f, false);
    for (double theta : {0.0, 0.4, 1.0, 2.0, 3.0}) {
        double half = std::clamp((theta - M_PI) / 0.5 + M_PI, 0.0, M_PI);
        EXPECT_NEAR(narrow.factor(float(theta), 0.2f), plain.candela(float(half), 0.2f), 1e-3) << theta;
        EXPECT_NEAR(wide.factor(float(theta), 0.2f), plain.candela(float((theta - M_PI) / 2.0 + M_PI), 0.2f), 1e-3)
            << theta;
    }
}

TEST(IesProfile, NormalizeDividesByTheMeanIntensity) {
    // The mean of the table over the sphere, by a quadrature of the test's own lookup.
    texture::IesTable table = test::quadrantTable(3.0f);
    double integral = 0.0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            double v = (i + 0.5) * 180.0 / n, h = (j + 0.5) * 180.0 / n;
            integral += test::tableCandela(table, v, h) * std::sin(v * kDeg) * (M_PI / n) * (M_PI / n);
        }
    IesProfile normalized(table, 0.0f, true);
    EXPECT_NEAR(normalized.meanIntensity(), integral / (4.0 * M_PI), 1e-3 * integral / (4.0 * M_PI));
    EXPECT_NEAR(normalized.factor(0.5f, 0.5f), normalized.candela(0.5f, 0.5f) / normalized.meanIntensity(), 1e-4);
}

}  // namespace
}  // namespace fluence::render
