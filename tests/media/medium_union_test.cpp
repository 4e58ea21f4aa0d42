// Media filling space together (media/medium_union.h), owned or borrowed: coefficients add, the
// emission and g are the weighted means, and the majorant pieces bound the sum (the homogeneous
// interior of a glass together with a ramp of smoke crossing it, as render/render_scene.h builds).
#include "media/medium_union.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "media/homogeneous_medium.h"
#include "media/majorant_check.h"
#include "media/ratio_tracking.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

const MediumProperties kInterior{RGB(0.5f, 0.25f, 0.0f), RGB(0.0f, 0.25f, 1.0f), RGB(2.0f, 0.0f, 0.0f), 0.5f};

TEST(MediumUnion, BorrowedMediaAddUp) {
    HomogeneousMedium interior(kInterior);
    test::RampMedium smoke(RGB(1.0f), RGB(0.5f), 4.0f, 3, true, RGB(0.5f), -0.5f);
    MediumUnion both(std::vector<const Medium*>{&interior, &smoke});
    ASSERT_EQ(both.size(), 2u);

    const Vec3f p(2.0f, 0.0f, 0.0f);  // smoke sigmaT 2 per channel there, half scattering
    MediumProperties m = both.at(p);
    EXPECT_EQ(m.sigmaA, kInterior.sigmaA + RGB(1.0f));
    EXPECT_EQ(m.sigmaS, kInterior.sigmaS + RGB(1.0f));
    // Emission: sigmaA-weighted; only the interior emits (red: 0.5 x 2 over 1.5).
    EXPECT_NEAR(m.emission.x, 0.5f * 2.0f / 1.5f, 1e-6f);
    EXPECT_EQ(m.emission.y, 0.0f);
    // g: luminance(sigmaS)-weighted mean of 0.5 and -0.5.
    const float wInterior = luminance(kInterior.sigmaS), wSmoke = luminance(RGB(1.0f));
    EXPECT_NEAR(m.g, (0.5f * wInterior - 0.5f * wSmoke) / (wInterior + wSmoke), 1e-6f);

    // Along x from -1: the interior alone over [0, 1), then both over the smoke's three pieces,
    // then the interior alone again; the bounds hold everywhere.
    const MediumRay ray{Vec3f(-1.0f, 0.0f, 0.0f), Vec3f(1.0f, 0.0f, 0.0f), 8.0f};
    MajorantCheck check = majorantsBound(both, ray);
    EXPECT_TRUE(check.bound) << check.report;
    int pieces = 0;
    both.majorants(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const MajorantSegment&) { return ++pieces > 0; });
    EXPECT_EQ(pieces, 5);
}

TEST(MediumUnion, TransmittanceIsTheProductOfTheMedias) {
    // Extinction adds, so transmittance multiplies: exp(-sigmaT_interior d) times the ramp's
    // exp(-(a d + b d^2 / 2)), estimated by ratio tracking through the union.
    HomogeneousMedium interior(kInterior);
    test::RampMedium smoke(RGB(0.3f, 0.6f, 0.9f), RGB(0.2f), 3.0f, 4, false);
    MediumUnion both(std::vector<const Medium*>{&interior, &smoke});
    const float d = 2.5f;
    const MediumRay ray{Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), d};
    std::array<test::MeanEstimate, 3> e;
    for (int i = 0; i < 20000; ++i) {
        SampleStream rng(3, 0, std::uint64_t(i));
        const int hero = sampleHeroChannel(rng.next());
        TransmittanceEstimate tr = ratioTrackingTransmittance(both, ray, hero, rng);
        RGB estimate = tr.estimate();
        for (int c = 0; c < 3; ++c) e[c].add(estimate[c]);
    }
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(3));
    for (int c = 0; c < 3; ++c) {
        const RGB a(0.3f, 0.6f, 0.9f);
        const double expected =
            std::exp(-(kInterior.sigmaA[c] + kInterior.sigmaS[c]) * d - (a[c] * d + 0.2 * d * d / 2));
        EXPECT_NEAR(e[c].mean(), expected, z * e[c].standardError() + 1e-6) << "channel " << c;
    }
}

}  // namespace
}  // namespace fluence::media
