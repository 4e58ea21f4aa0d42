// The homogeneous medium (media/homogeneous_medium.h): its coefficients everywhere, and one exact
// majorant segment over whatever range is asked, bounded or not.
#include "media/homogeneous_medium.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "media/majorant_check.h"

namespace fluence::media {
namespace {

const MediumProperties kFog{RGB(0.1f, 0.2f, 0.3f), RGB(1.0f, 0.5f, 0.25f), RGB(0.0f, 2.0f, 0.0f), 0.4f};

std::vector<MajorantSegment> segmentsOf(const Medium& medium, float tMin, float tMax) {
    std::vector<MajorantSegment> segments;
    medium.majorants(Vec3f(1.0f, 2.0f, 3.0f), Vec3f(0.0f, 0.0f, 1.0f), tMin, tMax, [&](const MajorantSegment& s) {
        segments.push_back(s);
        return true;
    });
    return segments;
}

TEST(HomogeneousMedium, HasItsCoefficientsEverywhere) {
    HomogeneousMedium medium(kFog);
    for (Vec3f p : {Vec3f(0.0f), Vec3f(-1e6f, 3.0f, 1e6f)}) {
        MediumProperties m = medium.at(p);
        EXPECT_EQ(m.sigmaA, kFog.sigmaA);
        EXPECT_EQ(m.sigmaS, kFog.sigmaS);
        EXPECT_EQ(m.emission, kFog.emission);
        EXPECT_EQ(m.g, kFog.g);
    }
}

TEST(HomogeneousMedium, IsOneExactSegmentOverTheRange) {
    HomogeneousMedium medium(kFog);
    const float inf = std::numeric_limits<float>::infinity();
    for (auto [tMin, tMax] : {std::pair(0.0f, 2.5f), std::pair(1.0f, inf)}) {
        std::vector<MajorantSegment> segments = segmentsOf(medium, tMin, tMax);
        ASSERT_EQ(segments.size(), 1u);
        EXPECT_EQ(segments[0].tMin, tMin);
        EXPECT_EQ(segments[0].tMax, tMax);
        EXPECT_EQ(segments[0].sigmaMaj, kFog.sigmaA + kFog.sigmaS);
        EXPECT_EQ(segments[0].sigmaMin, kFog.sigmaA + kFog.sigmaS);
    }
    EXPECT_TRUE(segmentsOf(medium, 2.0f, 2.0f).empty());
    MajorantCheck check = majorantsBound(medium, MediumRay{Vec3f(0.5f), normalize(Vec3f(1.0f, -2.0f, 0.5f)), 10.0f});
    EXPECT_TRUE(check.bound) << check.report;
}

}  // namespace
}  // namespace fluence::media
