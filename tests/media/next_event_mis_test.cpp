// The density ratios that next-event estimation needs (media/tracking.h, HOW A PATH TRACER USES
// THEM): a light seen through a chromatic heterogeneous medium, reached both by free-flight
// sampling (a flight that escapes) and by ratio tracking (a shadow ray), with the two combined
// by the balance heuristic over both techniques and all three heroes,
//     F = f / average(p_delta + p_ratio)  for each technique's sample,
// must estimate the transmittance without bias. It does only if FreeFlight::lightPdfRatio is
// ratio tracking's density of the flight's null points and TransmittanceEstimate::throughput is
// delta tracking's density of the shadow ray's (each over its own hero density), so this checks
// both, along with their estimates alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "media/free_flight.h"
#include "media/ratio_tracking.h"
#include "tests/media/test_media.h"
#include "tests/support/chi2.h"
#include "tests/support/statistics.h"

namespace fluence::media {
namespace {

// 3 channels x 3 estimators, each at z standard errors, family-wide 1%.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(9));

TEST(NextEventMis, CombiningFreeFlightsAndShadowRaysIsUnbiased) {
    // sigmaT(x) = a + b x over 0 <= x < 3, 4 segments with minorants (so ratio tracking draws at
    // the residual rate, unlike delta tracking), purely absorbing; the light is at x = d.
    const RGB a(0.1f, 1.0f, 2.0f), b(1.5f, 0.2f, -0.6f);
    const float d = 2.0f;
    test::RampMedium ramp(a, b, 3.0f, 4, true);
    const MediumRay ray{Vec3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f), d};
    RGB exact;
    for (int c = 0; c < 3; ++c) exact[c] = std::exp(-(a[c] * d + b[c] * d * d / 2.0f));

    constexpr int kPaths = 40'000;
    test::MeanEstimate combined[3], flightsAlone[3], shadowRaysAlone[3];
    for (int n = 0; n < kPaths; ++n) {
        SampleStream rng(71, 0, n);
        const int hero = sampleHeroChannel(rng.next());
        const FreeFlight flight = sampleFreeFlight(ramp, ray, hero, rng);
        const TransmittanceEstimate shadow = ratioTrackingTransmittance(ramp, ray, hero, rng);
        const bool escaped = flight.event == FlightEvent::Escaped;
        const RGB viaFlight =
            escaped ? flight.throughput / channelAverage(flight.pdfRatio + flight.lightPdfRatio) : RGB(0.0f);
        const RGB viaShadowRay = shadow.throughput / channelAverage(shadow.pdfRatio + shadow.throughput);
        const RGB flightAlone = escaped ? flight.throughput / channelAverage(flight.pdfRatio) : RGB(0.0f);
        for (int c = 0; c < 3; ++c) {
            combined[c].add(viaFlight[c] + viaShadowRay[c]);
            flightsAlone[c].add(flightAlone[c]);
            shadowRaysAlone[c].add(shadow.estimate()[c]);
        }
    }
    for (int c = 0; c < 3; ++c) {
        std::printf(
            "[ measured ] channel %d: MIS %.5f +- %.5f, flights %.5f +- %.5f, shadow rays %.5f +- %.5f "
            "(exact %.5f)\n",
            c, combined[c].mean(), combined[c].standardError(), flightsAlone[c].mean(), flightsAlone[c].standardError(),
            shadowRaysAlone[c].mean(), shadowRaysAlone[c].standardError(), exact[c]);
        EXPECT_NEAR(combined[c].mean(), exact[c], kZ * combined[c].standardError()) << "channel " << c;
        EXPECT_NEAR(flightsAlone[c].mean(), exact[c], kZ * flightsAlone[c].standardError()) << "channel " << c;
        EXPECT_NEAR(shadowRaysAlone[c].mean(), exact[c], kZ * shadowRaysAlone[c].standardError()) << "channel " << c;
    }
}

}  // namespace
}  // namespace fluence::media
