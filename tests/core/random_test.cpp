#include "core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace fluence {
namespace {

TEST(SampleStream, IsAPureFunctionOfItsCounters) {
    SampleStream a(1, 2, 3), b(1, 2, 3);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(a.next(), b.next());
}

TEST(SampleStream, DifferentCountersGiveDifferentStreams) {
    std::set<float> firsts;
    for (std::uint64_t seed : {0u, 1u})
        for (std::uint64_t pixel : {0u, 1u, 1000u})
            for (std::uint64_t sample : {0u, 1u, 2u}) firsts.insert(SampleStream(seed, pixel, sample).next());
    EXPECT_EQ(firsts.size(), 18u);
}

TEST(SampleStream, IndependentStreamsTakeNoSlotOfTheSample) {
    // Under Sobol, the values after a walk drawn from independent streams are those of the same
    // slots without the walk, whatever the walk drew; the streams are pure functions of the
    // sample's counters and of how many were handed out before, and differ from each other.
    SampleStream plain(4, 5, 6, SamplerKind::Sobol), walked(4, 5, 6, SamplerKind::Sobol);
    EXPECT_EQ(plain.next(), walked.next());
    SampleStream first = walked.independentStream(), second = walked.independentStream();
    SampleStream again(4, 5, 6, SamplerKind::Sobol);
    again.next();
    SampleStream firstAgain = again.independentStream();
    std::set<float> values;
    for (int i = 0; i < 37; ++i) {
        const float a = first.next(), b = second.next();
        EXPECT_EQ(a, firstAgain.next());
        values.insert(a);
        values.insert(b);
    }
    EXPECT_EQ(values.size(), 74u);
    EXPECT_EQ(walked.dimension(), plain.dimension());
    for (int i = 0; i < 3; ++i) EXPECT_EQ(plain.next(), walked.next());
}

TEST(SampleStream, ValuesAreInTheUnitIntervalWithUniformMoments) {
    constexpr int kN = 1 << 20;
    double sum = 0, sum2 = 0, lag = 0;
    float previous = 0.5f;
    for (int i = 0; i < kN; ++i) {
        SampleStream s(42, std::uint64_t(i) / 16, std::uint64_t(i) % 16);
        float u = s.next();
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        sum += u;
        sum2 += double(u) * u;
        lag += (double(u) - 0.5) * (double(previous) - 0.5);
        previous = u;
    }
    // Mean 1/2 (sd 1/sqrt(12 N)), second moment 1/3 (sd sqrt(4/45/N)), lag-1 covariance 0
    // (sd 1/(12 sqrt N)); 5 standard deviations.
    EXPECT_NEAR(sum / kN, 0.5, 5 / std::sqrt(12.0 * kN));
    EXPECT_NEAR(sum2 / kN, 1.0 / 3.0, 5 * std::sqrt(4.0 / 45.0 / kN));
    EXPECT_NEAR(lag / kN, 0.0, 5 / (12.0 * std::sqrt(double(kN))));
}

TEST(SampleStream, ToUnitFloatNeverReachesOne) {
    EXPECT_LT(toUnitFloat(~std::uint64_t(0)), 1.0f);
    EXPECT_EQ(toUnitFloat(0), 0.0f);
}

}  // namespace
}  // namespace fluence
