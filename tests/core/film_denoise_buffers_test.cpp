// The film's denoiser buffers (core/film.h): the half images split by sample index, the variance
// of the mean, and their place in the film state (core/film_state.h).
#include <gtest/gtest.h>

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

TEST(FilmDenoiseBuffers, HalvesSplitEvenAndOddSamplesAndVarianceIsTheMeans) {
    Film film(1, 1, 100.0f);
    film.enableDenoiseBuffers();
    for (float v : {1.0f, 2.0f, 3.0f, 4.0f}) film.add(0, 0, sampleOf(v));
    const Image buffers = film.resolveDenoiseBuffers();
    const float* p = buffers.pixel(0, 0);
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("half0.R")], 2.0f);  // samples 0 and 2
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("half1.R")], 3.0f);  // samples 1 and 3
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("half1.G")], 6.0f);
    // The samples' variance (1, 2, 3, 4: 5/3) over their count.
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("variance.R")], 5.0f / 3.0f / 4.0f);
    EXPECT_FLOAT_EQ(p[buffers.channelIndex("variance.B")], 0.0f);
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
    for (float v : {1.0f, 5.0f, 2.0f}) film.add(1, 0, sampleOf(v));
    std::stringstream state;
    writeFilmState(film, state);

    Film resumed(2, 1, 100.0f);
    resumed.enableDenoiseBuffers();
    std::stringstream copy(state.str());
    readFilmState(copy, resumed);
    resumed.add(1, 0, sampleOf(7.0f));  // the fourth sample: odd, so into half 1
    film.add(1, 0, sampleOf(7.0f));
    EXPECT_EQ(resumed.resolveDenoiseBuffers().pixels, film.resolveDenoiseBuffers().pixels);

    Film without(2, 1, 100.0f);
    std::stringstream again(state.str());
    EXPECT_THROW(readFilmState(again, without), FilmStateError);
}

}  // namespace
}  // namespace fluence
