// The film's denoiser buffers (core/film.h): the half images split by sample index into the halves
// of power-of-two prefixes, the variance of the mean from them, and their place in the film state
// (core/film_state.h). Their statistics: tests/core/film_half_buffers_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <sstream>

#include "core/film.h"
#include "core/film_state.h"

namespace fluence {
namespace {

FilmSample sampleOf(float value) {
    FilmSample s;
    s.radiance = RGB(value, 2.0f * value, 0.0f);
    return s;
}

TEST(FilmDenoiseBuffers, HalvesSplitThePowerOfTwoCountAndVarianceIsTheirDifferences) {
    Film film(1, 1, 100.0f);
    film.enableDenoiseBuffers();
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f}) film.add(0, 0, sampleOf(v));
    const Image buffers = film.resolveDenoiseBuffers();
    const float* p = buffers.pixel(0, 0);
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("half0.R")], 1.5f);  // samples 0 and 1
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("half1.R")], 3.5f);  // samples 2 and 3
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("half1.G")], 7.0f);
    // (half0 - half1)² n0 n1 / n²: 4 x 2 x 2 / 16.
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("variance.R")], 1.0f);
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("variance.G")], 4.0f);
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("variance.B")], 0.0f);
}

// For n = 2^M + k samples (1 <= k <= 2^M) the first half is [0, 2^M) when k >= 2^(M-1), else
// [0, 2^(M-1)); one sample is in both halves.
TEST(FilmDenoiseBuffers, FirstHalfIsThePowerOfTwoPrefixThatKeepsTheCountsWithinTwice) {
    const std::uint32_t firstCounts[] = {1, 1, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8, 16};
    Film film(1, 1, 100.0f);
    film.enableDenoiseBuffers();
    for (std::uint32_t n = 1; n <= std::size(firstCounts); ++n) {
        film.add(0, 0, sampleOf(float(n)));  // sample n - 1 has the value n
        const Film::HalfMeans h = film.halfMeans(0, 0);
        const std::uint32_t first = firstCounts[n - 1], second = n == 1 ? 0 : n - first;
        EXPECT_EQ(h.firstCount, first) << n;
        EXPECT_EQ(h.secondCount, second) << n;
        EXPECT_DOUBLE_EQ(h.first[0], (1.0 + first) / 2.0) << n;  // the mean of 1 .. first
        if (n > 1) {
            EXPECT_DOUBLE_EQ(h.second[0], (first + 1.0 + n) / 2.0) << n;  // the mean of first + 1 .. n
            EXPECT_LE(std::max(first, second), 2 * std::min(first, second)) << n;
        }
    }
}

TEST(FilmDenoiseBuffers, FeatureVarianceIsThatOfTheFeaturesMeansAMissCountingAsZero) {
    Film film(1, 1, 100.0f);
    film.enableDenoiseBuffers();
    for (float albedo : {0.2f, 0.8f, 0.2f}) {
        FilmSample s = sampleOf(1.0f);
        s.hit = true;
        s.albedo = RGB(albedo, 0.5f, 0.0f);
        s.normal = Vec3f(0.0f, 0.0f, 1.0f);
        film.add(0, 0, s);
    }
    film.add(0, 0, sampleOf(1.0f));  // a miss: albedo and normal 0
    const Image buffers = film.resolveDenoiseBuffers();
    const float* p = buffers.pixel(0, 0);
    // albedo.R's samples 0.2, 0.8, 0.2, 0: mean 0.3, squares' sum 0.72; (0.72 - 4 0.09) / 3 / 4.
    EXPECT_NEAR(p[buffers.channelIndex("albedoVariance.R")], 0.03f, 1e-7f);
    // albedo.G's 0.5, 0.5, 0.5, 0 and N.Z's 1, 1, 1, 0: v, v, v, 0 have the variance v² / 4.
    EXPECT_NEAR(p[buffers.channelIndex("albedoVariance.G")], 0.25f / 4.0f / 4.0f, 1e-7f);
    EXPECT_NEAR(p[buffers.channelIndex("NVariance.Z")], 1.0f / 4.0f / 4.0f, 1e-7f);
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("NVariance.X")], 0.0f);
}

TEST(FilmDenoiseBuffers, WithoutThemResolvingIsAnError) {
    Film film(2, 2, 100.0f);
    EXPECT_FALSE(film.hasDenoiseBuffers());
    EXPECT_THROW(film.resolveDenoiseBuffers(), std::logic_error);
}

TEST(FilmDenoiseBuffers, CheckpointStateKeepsThemAndRefusesAFilmWithout) {
    Film film(2, 1, 100.0f);
    film.enableDenoiseBuffers();
    for (float v : {1.0f, 5.0f, 2.0f, 3.0f}) film.add(1, 0, sampleOf(v));
    std::stringstream state;
    writeFilmState(film, state);

    Film resumed(2, 1, 100.0f);
    resumed.enableDenoiseBuffers();
    std::stringstream copy(state.str());
    readFilmState(copy, resumed);
    for (float v : {7.0f, 0.5f}) {  // sample 4 moves the prefixes on: they must have been saved
        resumed.add(1, 0, sampleOf(v));
        film.add(1, 0, sampleOf(v));
    }
    EXPECT_EQ(resumed.resolveDenoiseBuffers().pixels, film.resolveDenoiseBuffers().pixels);

    Film without(2, 1, 100.0f);
    std::stringstream again(state.str());
    EXPECT_THROW(readFilmState(again, without), FilmStateError);
}

}  // namespace
}  // namespace fluence
