// Colour temperature (core/blackbody.h): the CIE's Illuminant A and published Planckian-locus
// chromaticities, luminance 1, and 6500 K close to white in the rendering space.
#include <gtest/gtest.h>

#include "core/blackbody.h"

namespace fluence {
namespace {

Vec3d chromaticity(double kelvin) {
    Vec3d xyz = blackbodyXyz(kelvin);
    double sum = xyz.x + xyz.y + xyz.z;
    return {xyz.x / sum, xyz.y / sum, 0.0};
}

TEST(Blackbody, IlluminantAAndThePlanckianLocus) {
    // CIE Illuminant A is a blackbody at 2856 K: (x, y) = (0.44757, 0.40745) (CIE 015:2018).
    Vec3d a = chromaticity(2856.0);
    EXPECT_NEAR(a.x, 0.44757, 2e-4);
    EXPECT_NEAR(a.y, 0.40745, 2e-4);
    // The Planckian locus as it is usually tabulated to four places (CIE 1931 2 degrees,
    // c2 = 1.4388e-2 m K); an integration of Planck's law over the CIE 5 nm table agrees to 1e-4.
    for (auto [kelvin, x, y] : {std::tuple{1000.0, 0.6528, 0.3444}, std::tuple{2000.0, 0.5267, 0.4133},
                                std::tuple{5000.0, 0.3451, 0.3516}, std::tuple{10000.0, 0.2807, 0.2884}}) {
        Vec3d c = chromaticity(kelvin);
        EXPECT_NEAR(c.x, x, 5e-4) << kelvin << " K";
        EXPECT_NEAR(c.y, y, 5e-4) << kelvin << " K";
    }
}

TEST(Blackbody, RgbHasLuminanceOneAnd6500KIsNearlyWhite) {
    for (double kelvin : {1000.0, 1800.0, 2700.0, 4000.0, 6500.0, 10000.0}) {
        RGB c = blackbodyRgb(kelvin);
        EXPECT_NEAR(luminance(c), 1.0f, 1e-5f) << kelvin << " K";
        EXPECT_GE(std::min({c.x, c.y, c.z}), 0.0f) << kelvin << " K";
    }
    RGB white = blackbodyRgb(6500.0);
    EXPECT_NEAR(white.x, 1.0f, 0.05f);
    EXPECT_NEAR(white.y, 1.0f, 0.05f);
    EXPECT_NEAR(white.z, 1.0f, 0.05f);
    RGB warm = blackbodyRgb(2700.0), cool = blackbodyRgb(10000.0);
    EXPECT_GT(warm.x, warm.y);
    EXPECT_GT(warm.y, warm.z);
    EXPECT_GT(cool.z, cool.y);
    EXPECT_GT(cool.y, cool.x);
}

}  // namespace
}  // namespace fluence
