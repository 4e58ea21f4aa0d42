// The statistics of the film's half buffers (core/film.h): their variance of the pixel's mean is
// unbiased when the samples are independent, and under the Owen-scrambled Sobol sampler it measures
// the error the nets make instead of overstating it by the factor of even- and odd-indexed halves.
//
// Each test renders a film of kPixels one-pixel "images" of an integrand over the unit square, each
// pixel a stream of its own (core/random.h), and compares the mean over the pixels of the film's
// variance channel, V, with the variance of the pixels' means about the integral, T.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "core/film.h"
#include "core/random.h"

namespace fluence {
namespace {

constexpr int kPixels = 4096;

struct Estimate {
    double variance = 0.0;           // V: the mean of the film's variance channel over the pixels
    double varianceError = 0.0;      // its standard error (the channel's spread over sqrt(kPixels))
    double trueVariance = 0.0;       // T: the mean over the pixels of (pixel mean - integral)²
    double trueVarianceError = 0.0;  // its standard error, likewise
};

// Renders kPixels pixels of `samples` samples of f(stream), whose integral is `integral`.
template <typename Integrand>
Estimate estimate(SamplerKind kind, std::uint32_t samples, double integral, Integrand f) {
    Film film(kPixels, 1, 100.0f);
    film.enableDenoiseBuffers();
    for (int p = 0; p < kPixels; ++p)
        for (std::uint32_t i = 0; i < samples; ++i) {
            SampleStream stream(11, std::uint64_t(p), i, kind);
            FilmSample s;
            s.radiance = RGB(float(f(stream)), 0.0f, 0.0f);
            film.add(p, 0, s);
        }
    const Image image = film.resolve(), buffers = film.resolveDenoiseBuffers();
    const int mean = image.channelIndex("R"), variance = buffers.channelIndex("variance.R");
    double v = 0, v2 = 0, t = 0, t2 = 0;
    for (int p = 0; p < kPixels; ++p) {
        const double e = buffers.pixel(p, 0)[variance], d = image.pixel(p, 0)[mean] - integral;
        v += e;
        v2 += e * e;
        t += d * d;
        t2 += d * d * d * d;
    }
    const double n = kPixels;
    Estimate out;
    out.variance = v / n;
    out.varianceError = std::sqrt(std::max(0.0, v2 / n - out.variance * out.variance) / n);
    out.trueVariance = t / n;
    out.trueVarianceError = std::sqrt(std::max(0.0, t2 / n - out.trueVariance * out.trueVariance) / n);
    return out;
}

// Independent uniform samples in [0, 1): sigma² = 1/12, so the mean of n has variance 1 / (12 n),
// known exactly. V is a mean of kPixels independent estimates, so by the central limit theorem it
// lies within 4 of its standard errors of its expectation but for a chance of 6e-5 per count; the
// counts cover powers of two, both splits of the others (k below and above 2^(M-1)) and odd n.
TEST(FilmHalfBuffers, VarianceOfTheMeanIsUnbiasedForIndependentSamples) {
    for (std::uint32_t n : {2u, 3u, 5u, 8u, 13u, 24u, 32u}) {
        const Estimate e =
            estimate(SamplerKind::Independent, n, 0.5, [](SampleStream& stream) { return double(stream.next()); });
        const double expected = 1.0 / (12.0 * n);
        EXPECT_NEAR(e.variance, expected, 4.0 * e.varianceError) << n << " samples";
    }
}

// A smooth integrand under Sobol: its pixel means are nets, whose error falls like n^-3 (Owen 1997,
// "Scrambled net variance for integrals of smooth functions"). The halves of n = 2^m samples are
// nets of n/2, so E (A - B)² / 4 <= Var A (Cauchy-Schwarz, the halves alike) = 2^3 = 8 times the
// whole net's variance, asymptotically: V / T must stay below 8. Even- and odd-indexed halves are
// random halves of one net, whose difference reads the error of independent samples: measured
// (the halves split that way, this test) V / T = 166 at 16 samples, 1970 at 64, against 5.9 here.
// The bound is checked with the ratio's error: V / T + 4 standard errors (both estimates' relative
// errors added in quadrature, the delta method) below 8.
TEST(FilmHalfBuffers, SobolNetsOfASmoothIntegrandAreNotOverstated) {
    const double integral = (std::exp(1.0) - 1.0) * std::sin(2.0) / 2.0;  // of e^x cos(2y)
    for (std::uint32_t n : {16u, 64u}) {
        const Estimate e = estimate(SamplerKind::Sobol, n, integral, [](SampleStream& stream) {
            const Vec2f u = stream.next2D();
            return std::exp(double(u.x)) * std::cos(2.0 * u.y);
        });
        const double ratio = e.variance / e.trueVariance;
        const double ratioError =
            ratio * std::hypot(e.varianceError / e.variance, e.trueVarianceError / e.trueVariance);
        EXPECT_LT(ratio + 4.0 * ratioError, 8.0) << n << " samples: V " << e.variance << " T " << e.trueVariance;
    }
}

}  // namespace
}  // namespace fluence
