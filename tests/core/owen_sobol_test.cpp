// The Sobol sampler (core/owen_sobol.h, SampleStream with SamplerKind::Sobol): its draws are the
// definition's values bit for bit; every power-of-two prefix of one pixel's samples is a
// (0,m,2)-net in each slot of next2D() (and the lens), and stratified in each slot of next(); pixels
// and slots are decorrelated; and the mean squared error of a smooth 2D integral falls faster than
// 1/N, which independent samples cannot do.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "core/owen_sobol.h"
#include "core/random.h"

namespace fluence {
namespace {

// Value `slot` (1, 2, ...) of sample `index` of a pixel: the slot-th draw of its stream.
Vec2f pairInSlot(std::uint64_t seed, std::uint64_t pixel, std::uint32_t index, int slot) {
    SampleStream stream(seed, pixel, index, SamplerKind::Sobol);
    for (int s = 1; s < slot; ++s) stream.next2D();
    return stream.next2D();
}

float valueInSlot(std::uint64_t seed, std::uint64_t pixel, std::uint32_t index, int slot) {
    SampleStream stream(seed, pixel, index, SamplerKind::Sobol);
    for (int s = 1; s < slot; ++s) stream.next();
    return stream.next();
}

// Whether every elementary interval [i/2^a, (i+1)/2^a) x [j/2^(m-a), (j+1)/2^(m-a)) holds exactly
// one of the 2^m points, for every a from 0 to m.
bool isZeroMTwoNet(const std::vector<Vec2f>& points, int m) {
    for (int a = 0; a <= m; ++a) {
        const int nx = 1 << a, ny = 1 << (m - a);
        std::vector<int> count(std::size_t(nx) * std::size_t(ny), 0);
        for (const Vec2f& p : points) {
            const int i = static_cast<int>(p.x * float(nx)), j = static_cast<int>(p.y * float(ny));
            if (i < 0 || i >= nx || j < 0 || j >= ny) return false;
            ++count[std::size_t(j) * std::size_t(nx) + std::size_t(i)];
        }
        for (int c : count)
            if (c != 1) return false;
    }
    return true;
}

TEST(OwenSobol, SobolMatricesGiveTheirKnownFirstPoints) {
    // Dimension 0 is van der Corput; dimension 1 (in index order, not Gray-code order) 0, 1/2, 3/4,
    // 1/4, 5/8, 1/8.
    const float second[] = {0.0f, 0.5f, 0.75f, 0.25f, 0.625f, 0.125f};
    const float first[] = {0.0f, 0.5f, 0.25f, 0.75f, 0.125f, 0.625f};
    for (std::uint32_t i = 0; i < 6; ++i) {
        EXPECT_EQ(fractionToFloat(sobolDimension0(i)), first[i]) << i;
        EXPECT_EQ(fractionToFloat(sobolDimension1(i)), second[i]) << i;
    }
}

// Dimension 1 as the direction numbers define it: v_1 = 1/2, v_{k+1} = v_k ^ (v_k >> 1), the
// point the xor of the v_{k+1} of the index's set bits k (the loop the transform replaces).
std::uint32_t sobolDimension1ByDirectionNumbers(std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1)
        if (index & 1u) x ^= v;
    return x;
}

TEST(OwenSobol, SecondDimensionIsItsDirectionNumbersAtEveryIndex) {
    for (std::uint32_t i = 0; i < (1u << 20); ++i)
        ASSERT_EQ(sobolDimension1(i), sobolDimension1ByDirectionNumbers(i)) << i;
    std::uint64_t state = 1;
    for (int n = 0; n < (1 << 20); ++n) {
        const auto i = static_cast<std::uint32_t>(mix64(state++));
        ASSERT_EQ(sobolDimension1(i), sobolDimension1ByDirectionNumbers(i)) << i;
    }
}

TEST(OwenSobol, DrawsAreTheNestedScramblesOfTheShuffledIndexBitForBit) {
    // owenSobol1D/2D leave out the bit reversals that cancel (core/owen_sobol.h); written out in
    // full, the scramble of each dimension's value at the index's own scramble must give the same.
    std::uint64_t state = 3;
    for (int n = 0; n < (1 << 18); ++n) {
        const std::uint32_t index = n < 4096 ? std::uint32_t(n) : static_cast<std::uint32_t>(mix64(state++));
        const std::uint64_t seed = mix64(state++), ySeed = mix64(state++);
        const std::uint32_t shuffled = nestedUniformScramble(index, static_cast<std::uint32_t>(seed));
        const float x = fractionToFloat(nestedUniformScramble(sobolDimension0(shuffled), std::uint32_t(seed >> 32)));
        const float y = fractionToFloat(
            nestedUniformScramble(sobolDimension1ByDirectionNumbers(shuffled), static_cast<std::uint32_t>(ySeed)));
        const Vec2f p = owenSobol2D(SobolIndex(index), seed, ySeed);
        ASSERT_EQ(p.x, x) << index;
        ASSERT_EQ(p.y, y) << index;
        ASSERT_EQ(owenSobol1D(SobolIndex(index), seed), x) << index;
    }
}

TEST(OwenSobol, AStreamsValuesAreThoseImagesWereRenderedWith) {
    // Values of SampleStream(7, 4242, sample, Sobol) taken from the sampler as first merged
    // (4d28e55): a change here changes every image rendered with it.
    struct Expected {
        std::uint64_t sample;
        float time, lensX, lensY, a, b, c, d, e;
    };
    const Expected expected[] = {
        {0, 0x1.645818p-1f, 0x1.e62a8p-5f, 0x1.cde106p-1f, 0x1.1b130cp-2f, 0x1.04d6p-8f, 0x1.eaf3dcp-1f, 0x1.809p-6f,
         0x1.17fa58p-3f},
        {5, 0x1.4fda94p-2f, 0x1.1b70ap-1f, 0x1.6c078p-6f, 0x1.ecc2b8p-3f, 0x1.ef1cap-2f, 0x1.9b4698p-1f, 0x1.89ef42p-1f,
         0x1.9c15dp-1f},
        {1000003, 0x1.e847cp-1f, 0x1.bd30ap-4f, 0x1.56488p-2f, 0x1.39a9bap-1f, 0x1.c1792cp-1f, 0x1.845d9p-2f,
         0x1.061cp-10f, 0x1.d34e7ep-1f},
    };
    for (const Expected& e : expected) {
        SampleStream stream(7, 4242, e.sample, SamplerKind::Sobol);
        EXPECT_EQ(stream.shutterTime(), e.time) << e.sample;
        EXPECT_EQ(stream.lens().x, e.lensX) << e.sample;
        EXPECT_EQ(stream.lens().y, e.lensY) << e.sample;
        const Vec2f first = stream.next2D();
        EXPECT_EQ(first.x, e.a) << e.sample;
        EXPECT_EQ(first.y, e.b) << e.sample;
        EXPECT_EQ(stream.next(), e.c) << e.sample;
        const Vec2f third = stream.next2D();
        EXPECT_EQ(third.x, e.d) << e.sample;
        EXPECT_EQ(third.y, e.e) << e.sample;
    }
}

TEST(OwenSobol, NestedScrambleIsABijectionThatKeepsLeadingDigitsTogether) {
    // Points agreeing in their first k digits still agree in them after the scramble.
    for (std::uint32_t seed : {1u, 0xdeadbeefu, 12345u})
        for (std::uint32_t x = 0; x < 4096; ++x) {
            const std::uint32_t a = x << 20, b = a | (x * 2654435761u >> 12);
            EXPECT_EQ(nestedUniformScramble(a, seed) >> 20, nestedUniformScramble(b, seed) >> 20);
        }
    std::vector<bool> seen(1 << 16, false);
    for (std::uint32_t x = 0; x < (1u << 16); ++x) seen[nestedUniformScramble(x << 16, 77u) >> 16] = true;
    for (bool s : seen) EXPECT_TRUE(s);
}

TEST(OwenSobol, EveryPowerOfTwoPrefixOfAPixelsPairsIsANet) {
    for (std::uint64_t pixel : {0ull, 7ull, 123456ull})
        for (int slot : {1, 2, 5}) {
            std::vector<Vec2f> points, lens;
            for (int m = 0; m <= 10; ++m) {
                while (points.size() < (std::size_t(1) << m)) {
                    points.push_back(pairInSlot(3, pixel, std::uint32_t(points.size()), slot));
                    lens.push_back(SampleStream(3, pixel, lens.size(), SamplerKind::Sobol).lens());
                }
                EXPECT_TRUE(isZeroMTwoNet(points, m)) << "pixel " << pixel << " slot " << slot << " 2^" << m;
                EXPECT_TRUE(isZeroMTwoNet(lens, m)) << "lens, pixel " << pixel << " 2^" << m;
            }
        }
}

TEST(OwenSobol, EveryPowerOfTwoPrefixOfAPixelsValuesIsStratified) {
    for (std::uint64_t pixel : {1ull, 99ull})
        for (int slot : {1, 3}) {
            for (int m = 0; m <= 10; ++m) {
                std::vector<int> count(std::size_t(1) << m, 0), time(std::size_t(1) << m, 0);
                for (std::uint32_t i = 0; i < (1u << m); ++i) {
                    ++count[std::size_t(valueInSlot(5, pixel, i, slot) * float(1 << m))];
                    ++time[std::size_t(SampleStream(5, pixel, i, SamplerKind::Sobol).shutterTime() * float(1 << m))];
                }
                for (std::size_t c = 0; c < count.size(); ++c) {
                    ASSERT_EQ(count[c], 1) << "pixel " << pixel << " slot " << slot << " 2^" << m;
                    ASSERT_EQ(time[c], 1) << "shutter, pixel " << pixel << " 2^" << m;
                }
            }
        }
}

// The sample correlation of n pairs (a, b).
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= double(a.size()), mb /= double(b.size());
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

TEST(OwenSobol, PixelsAndSlotsAreDecorrelated) {
    // Across 4096 pixels, sample 3 of slot 1: uniform over 64 cells (chi-square, 63 degrees of
    // freedom: mean 63, sd 11.2; 120 is 5 sd), uncorrelated between neighbouring pixels and
    // between slots (|r| under 5 / sqrt(n)).
    constexpr int kPixels = 4096;
    std::vector<double> x, xNext, y, otherSlot;
    std::vector<int> cells(64, 0);
    for (int p = 0; p < kPixels; ++p) {
        const Vec2f a = pairInSlot(11, std::uint64_t(p), 3, 1), b = pairInSlot(11, std::uint64_t(p) + 1, 3, 1);
        ++cells[std::size_t(int(a.y * 8.0f) * 8 + int(a.x * 8.0f))];
        x.push_back(a.x), y.push_back(a.y), xNext.push_back(b.x);
        otherSlot.push_back(pairInSlot(11, std::uint64_t(p), 3, 2).x);
    }
    double chi2 = 0;
    for (int c : cells) chi2 += (c - kPixels / 64.0) * (c - kPixels / 64.0) / (kPixels / 64.0);
    EXPECT_LT(chi2, 120.0);
    const double bound = 5.0 / std::sqrt(double(kPixels));
    EXPECT_LT(std::abs(correlation(x, xNext)), bound);
    EXPECT_LT(std::abs(correlation(x, y)), bound);
    EXPECT_LT(std::abs(correlation(x, otherSlot)), bound);

    // Within one pixel, over its 1024 samples: the slots' values are uncorrelated too.
    std::vector<double> s1, s2, s3;
    for (std::uint32_t i = 0; i < 1024; ++i) {
        SampleStream stream(11, 42, i, SamplerKind::Sobol);
        s1.push_back(stream.next());
        s2.push_back(stream.next2D().x);
        s3.push_back(stream.next());
    }
    EXPECT_LT(std::abs(correlation(s1, s2)), 5.0 / 32.0);
    EXPECT_LT(std::abs(correlation(s1, s3)), 5.0 / 32.0);
}

// The slope of log(MSE) against log(N) for the mean of f over N samples of slot 2 of a pixel,
// the MSE over 128 pixels (independent scrambles), N = 16, 64, ..., 4096.
double mseSlope(SamplerKind kind, const std::function<double(Vec2f)>& f, double exact) {
    std::vector<double> logN, logMse;
    for (int n = 16; n <= 4096; n *= 4) {
        double squared = 0;
        for (int pixel = 0; pixel < 128; ++pixel) {
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                SampleStream stream(21, std::uint64_t(pixel), std::uint64_t(i), kind);
                stream.next2D();
                sum += f(stream.next2D());
            }
            squared += (sum / n - exact) * (sum / n - exact);
        }
        logN.push_back(std::log(double(n)));
        logMse.push_back(std::log(squared / 128.0));
    }
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < logN.size(); ++i) mx += logN[i], my += logMse[i];
    mx /= double(logN.size()), my /= double(logN.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < logN.size(); ++i) {
        sxy += (logN[i] - mx) * (logMse[i] - my);
        sxx += (logN[i] - mx) * (logN[i] - mx);
    }
    return sxy / sxx;
}

TEST(OwenSobol, ErrorOfASmoothIntegralFallsFasterThanOneOverN) {
    // A Gaussian bump in the unit square, its integral exact from erf.
    constexpr double mx = 0.4, my = 0.55, s = 0.25;
    const auto f = [&](Vec2f p) {
        return std::exp(-((p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my)) / (2 * s * s));
    };
    const auto axis = [&](double m) {
        return s * std::sqrt(M_PI / 2) * (std::erf((1 - m) / (s * M_SQRT2)) + std::erf(m / (s * M_SQRT2)));
    };
    const double exact = axis(mx) * axis(my);
    // 128 replicates: log(MSE) has a standard deviation near sqrt(2 / 128) = 0.125 for Gaussian
    // errors, so the fitted slope's is 0.125 / sqrt(sum (log N - mean)^2) = 0.03. Independent
    // samples give -1 (checked within 5 such deviations); scrambled Sobol's is near -3 for a smooth
    // integrand: required below -1.5, well clear of -1.
    const double independent = mseSlope(SamplerKind::Independent, f, exact);
    EXPECT_NEAR(independent, -1.0, 0.15);
    const double sobol = mseSlope(SamplerKind::Sobol, f, exact);
    EXPECT_LT(sobol, -1.5) << "independent's slope " << independent;
    std::printf("MSE slopes: independent %.2f, sobol %.2f\n", independent, sobol);
}

}  // namespace
}  // namespace fluence
