// The statistics the tests' tolerances rest on (tests/support/statistics.h), against values from
// tables of Student's t and the incomplete beta function's closed forms.
#include "tests/support/statistics.h"

#include <gtest/gtest.h>

namespace fluence::test {
namespace {

TEST(TestStatistics, IncompleteBetaMatchesClosedForms) {
    // I_x(1, 1) = x; I_x(a, 1) = x^a; I_x(1, b) = 1 - (1 - x)^b.
    for (double x : {0.05, 0.3, 0.5, 0.8, 0.99}) {
        EXPECT_NEAR(regularizedIncompleteBeta(1.0, 1.0, x), x, 1e-12);
        EXPECT_NEAR(regularizedIncompleteBeta(2.5, 1.0, x), std::pow(x, 2.5), 1e-12);
        EXPECT_NEAR(regularizedIncompleteBeta(1.0, 3.0, x), 1.0 - std::pow(1.0 - x, 3.0), 1e-12);
    }
}

TEST(TestStatistics, StudentQuantilesMatchTheTables) {
    EXPECT_NEAR(studentQuantile(0.025, 1), 12.706, 1e-3);
    EXPECT_NEAR(studentQuantile(0.025, 3), 3.182, 1e-3);
    EXPECT_NEAR(studentQuantile(0.005, 5), 4.032, 1e-3);
    EXPECT_NEAR(studentQuantile(0.05, 10), 1.812, 1e-3);
    EXPECT_NEAR(studentQuantile(0.025, 1e7), 1.960, 1e-3);  // the normal limit
}

TEST(TestStatistics, WelchBandUsesUnbiasedVariancesAndSatterthwaiteDegrees) {
    MeanEstimate a, b;
    for (double v : {1.0, 2.0, 3.0}) a.add(v);        // variance 1, standard error^2 1/3
    for (double v : {0.0, 4.0, 8.0, 12.0}) b.add(v);  // variance 80/3, standard error^2 20/3
    EXPECT_NEAR(a.unbiasedStandardError(), std::sqrt(1.0 / 3.0), 1e-12);
    const double va = 1.0 / 3.0, vb = 20.0 / 3.0, dof = (va + vb) * (va + vb) / (va * va / 2 + vb * vb / 3);
    EXPECT_NEAR(welchBand(a, b, 0.05), studentQuantile(0.025, dof) * std::sqrt(va + vb), 1e-9);
}

}  // namespace
}  // namespace fluence::test
