#include "core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

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

TEST(SampleStream, AForkIsStratifiedOverAPixelsSamplesAndTakesNoSlotOfTheSample) {
    // The 64 samples of a pixel fork after the same draws: a fork's k-th value over them puts one
    // value in each interval [i/64, (i+1)/64) (a stratified Sobol slot, not an independent value),
    // for any k. The forked stream's later values are a plain stream's of the same slots, and forks
    // at another dimension, of another pixel and of an independent stream are other values. A
    // fork made through a pixel's cached scrambles equals one made without them.
    constexpr int kSamples = 64, kDraws = 40;
    PixelSlotScrambles pixel(8, 321);
    std::set<float> firstValues;
    std::vector<std::vector<int>> strata(kDraws, std::vector<int>(kSamples, 0));
    for (int sample = 0; sample < kSamples; ++sample) {
        SampleStream parent(pixel, sample, SamplerKind::Sobol), plain(8, 321, sample, SamplerKind::Sobol),
            other(8, 322, sample, SamplerKind::Sobol);
        for (SampleStream* s : {&parent, &plain, &other}) {
            (void)s->next();
            (void)s->next2D();
        }
        SampleStream fork = parent.fork(), plainFork = plain.fork(), otherFork = other.fork();
        (void)parent.next();
        SampleStream later = parent.fork(), independentFork = plain.independentStream().fork();
        for (int k = 0; k < kDraws; ++k) {
            const float u = fork.next();
            EXPECT_EQ(u, plainFork.next());
            const int stratum = int(u * kSamples);
            ASSERT_LT(stratum, kSamples);
            ++strata[k][stratum];
            if (sample == 0) {
                firstValues.insert(u);
                firstValues.insert(later.next());
                firstValues.insert(otherFork.next());
                firstValues.insert(independentFork.next());
            }
        }
        SampleStream neverForked(8, 321, sample, SamplerKind::Sobol);
        (void)neverForked.next();
        (void)neverForked.next2D();
        (void)neverForked.next();
        EXPECT_EQ(parent.dimension(), neverForked.dimension());
        for (int i = 0; i < 3; ++i) EXPECT_EQ(parent.next(), neverForked.next());
    }
    for (int k = 0; k < kDraws; ++k)
        for (int i = 0; i < kSamples; ++i) EXPECT_EQ(strata[k][i], 1) << "draw " << k << ", stratum " << i;
    EXPECT_EQ(firstValues.size(), std::size_t(4 * kDraws));
}

TEST(SampleStream, APixelsSlotScramblesGiveTheSameValuesAsItsStreamsAlone) {
    // The samples of one pixel share a PixelSlotScrambles (as integrators/renderer.cpp's do), drawn
    // in varying orders of 1D and 2D draws, past the cached slots, with the shutter time and lens
    // asked between the draws and independent streams handed out: every value equals a plain
    // stream's of the same counters, bit for bit, under either sampler.
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent}) {
        PixelSlotScrambles pixel(7, 1234);
        for (std::uint64_t sample : {5u, 0u, 1u, 77u, 2u}) {
            SampleStream plain(7, 1234, sample, kind), shared(pixel, sample, kind);
            EXPECT_EQ(plain.shutterTime(), shared.shutterTime());
            const int draws = 2 * int(PixelSlotScrambles::kCachedSlots) + 10 + int(sample % 3);
            for (int i = 0; i < draws; ++i) {
                if ((i + int(sample)) % 3 == 0) {
                    EXPECT_EQ(plain.next(), shared.next()) << "sample " << sample << " draw " << i;
                } else {
                    const Vec2f a = plain.next2D(), b = shared.next2D();
                    EXPECT_EQ(a.x, b.x) << "sample " << sample << " draw " << i;
                    EXPECT_EQ(a.y, b.y) << "sample " << sample << " draw " << i;
                }
                if (i == 40) {
                    EXPECT_EQ(plain.lens().x, shared.lens().x);
                    EXPECT_EQ(plain.lens().y, shared.lens().y);
                    SampleStream a = plain.independentStream(), b = shared.independentStream();
                    EXPECT_EQ(a.next(), b.next());
                }
            }
            EXPECT_EQ(plain.dimension(), shared.dimension());
        }
    }
}

TEST(SampleStream, SkippedDrawsLeaveTheLaterValuesAsDrawnOnes) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent}) {
        SampleStream drawn(3, 9, 11, kind), skipped(3, 9, 11, kind);
        for (int i = 0; i < 20; ++i) {
            (void)drawn.next();
            (void)drawn.next2D();
            skipped.skip();
            skipped.skip2D();
            EXPECT_EQ(drawn.dimension(), skipped.dimension());
            const Vec2f a = drawn.next2D(), b = skipped.next2D();
            EXPECT_EQ(a.x, b.x);
            EXPECT_EQ(a.y, b.y);
            EXPECT_EQ(drawn.next(), skipped.next());
        }
    }
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
