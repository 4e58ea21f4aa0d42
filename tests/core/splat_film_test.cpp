// The splat film (core/splat_film.h): sums that do not depend on the order of the adds (shuffled,
// and from several threads), close to the exact sums; positions in the image's pixels, splats
// outside the window dropped; non-finite and negative values refused, large ones clamped, and sums
// saturating the same whatever the order; and the Film resolving its beauty as the mean of its
// samples plus the splat sums divided by the light paths per pixel; render checkpoints keep them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include "core/film.h"
#include "core/film_state.h"
#include "core/splat_film.h"

namespace fluence {
namespace {

struct Splat {
    float x, y;
    RGB value;
};

std::vector<Splat> randomSplats(int n, int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> px(0.0f, float(width)), py(0.0f, float(height));
    std::lognormal_distribution<float> value(0.0f, 3.0f);  // values over many orders of magnitude
    std::vector<Splat> splats;
    for (int i = 0; i < n; ++i)
        splats.push_back({px(random), py(random), RGB(value(random), value(random), value(random))});
    return splats;
}

TEST(SplatFilm, SumsDoNotDependOnTheOrderOrTheThreads) {
    const int width = 7, height = 5;
    std::vector<Splat> splats = randomSplats(20000, width, height, 1);
    SplatFilm inOrder(width, height);
    for (const Splat& s : splats) ASSERT_TRUE(inOrder.add(s.x, s.y, s.value));

    std::vector<Splat> shuffled = splats;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(2));
    SplatFilm threaded(width, height);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            for (std::size_t i = std::size_t(t); i < shuffled.size(); i += 4)
                threaded.add(shuffled[i].x, shuffled[i].y, shuffled[i].value);
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(inOrder.fixedSums(), threaded.fixedSums());

    // Close to the exact sums: each add rounds by at most half a step of 2^-28.
    std::vector<double> exact(std::size_t(width * height * 3), 0.0);
    for (const Splat& s : splats)
        for (int c = 0; c < 3; ++c)
            exact[(std::size_t(s.y) * width + std::size_t(s.x)) * 3 + std::size_t(c)] += s.value[c];
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double want = exact[(std::size_t(y) * width + std::size_t(x)) * 3 + std::size_t(c)];
                EXPECT_NEAR(inOrder.sum(x, y)[std::size_t(c)], want,
                            1e-12 * want + splats.size() * std::ldexp(1.0, -29));
            }
}

TEST(SplatFilm, AddsIntoTheWindowOnly) {
    SplatFilm window(4, 3, 10, 20);  // image pixels x 10..13, y 20..22
    EXPECT_TRUE(window.add(10.0f, 20.0f, RGB(1.0f)));
    EXPECT_TRUE(window.add(13.99f, 22.5f, RGB(2.0f, 3.0f, 4.0f)));
    EXPECT_TRUE(window.add(9.99f, 21.0f, RGB(5.0f)));  // left of the window: dropped
    EXPECT_TRUE(window.add(12.0f, 23.0f, RGB(5.0f)));  // below: dropped
    EXPECT_EQ(window.sum(0, 0)[0], 1.0);
    EXPECT_EQ(window.sum(3, 2)[0], 2.0);
    EXPECT_EQ(window.sum(3, 2)[2], 4.0);
    double total = 0.0;
    for (std::int64_t v : window.fixedSums()) total += double(v);
    EXPECT_EQ(total, std::ldexp(1.0 * 3 + 2 + 3 + 4, SplatFilm::kFractionBits));
}

TEST(SplatFilm, RefusesNonFiniteAndNegativeValuesAndSaturatesInAnyOrder) {
    SplatFilm film(1, 1);
    EXPECT_FALSE(film.add(0.5f, 0.5f, RGB(std::numeric_limits<float>::quiet_NaN(), 1.0f, 1.0f)));
    EXPECT_FALSE(film.add(0.5f, 0.5f, RGB(1.0f, std::numeric_limits<float>::infinity(), 1.0f)));
    EXPECT_FALSE(film.add(0.5f, 0.5f, RGB(1.0f, 1.0f, -1.0f)));
    EXPECT_EQ(film.sum(0, 0)[0], 0.0);
    // One value is clamped to kMaxValue; sums saturate at the largest int64 (2^35 in value units).
    EXPECT_TRUE(film.add(0.5f, 0.5f, RGB(1e30f, 0.0f, 0.0f)));
    EXPECT_EQ(film.sum(0, 0)[0], SplatFilm::kMaxValue);
    const double limit = double(std::numeric_limits<std::int64_t>::max()) / std::ldexp(1.0, SplatFilm::kFractionBits);
    SplatFilm bigFirst(1, 1), smallFirst(1, 1);
    for (int i = 0; i < 9; ++i) bigFirst.add(0.0f, 0.0f, RGB(float(SplatFilm::kMaxValue)));
    bigFirst.add(0.0f, 0.0f, RGB(3.0f));
    smallFirst.add(0.0f, 0.0f, RGB(3.0f));
    for (int i = 0; i < 9; ++i) smallFirst.add(0.0f, 0.0f, RGB(float(SplatFilm::kMaxValue)));
    EXPECT_EQ(bigFirst.fixedSums(), smallFirst.fixedSums());
    EXPECT_EQ(bigFirst.sum(0, 0)[0], limit);
}

// Beauty = the mean of the pixel's samples + its splats / (total samples / pixels).
TEST(SplatFilm, FilmResolvesSplatsPerLightPathOfTheImage) {
    Film film(2, 1, 100.0f);
    EXPECT_EQ(film.splats(), nullptr);
    FilmSample a;
    a.radiance = RGB(1.0f, 2.0f, 3.0f);
    for (int i = 0; i < 3; ++i) film.add(0, 0, a);  // pixel 0: 3 samples
    film.add(1, 0, a);                              // pixel 1: 1 sample; 4 light paths over 2 pixels
    SplatFilm& splats = film.enableSplats();
    EXPECT_EQ(&splats, &film.enableSplats());
    splats.add(1.5f, 0.2f, RGB(4.0f, 0.0f, 8.0f));
    const Image image = film.resolve();
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[0], 1.0f);
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[0], 1.0f + 4.0f / 2.0f);
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[1], 2.0f);
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[2], 3.0f + 8.0f / 2.0f);
}

// Light path layers: each keeps its own sums, apart from the beauty's and the other layers', and
// the film adds them to its light path layers as it adds the beauty's to the beauty.
TEST(SplatFilm, LayersKeepTheirOwnSumsAndResolveIntoTheFilmsLayers) {
    SplatFilm layered(2, 1, 0, 0, 2);
    EXPECT_EQ(layered.layers(), 2);
    EXPECT_TRUE(layered.add(0.5f, 0.5f, RGB(1.0f)));
    EXPECT_TRUE(layered.addToLayer(0, 0.5f, 0.5f, RGB(2.0f)));
    EXPECT_TRUE(layered.addToLayer(1, 1.5f, 0.5f, RGB(3.0f)));
    EXPECT_FALSE(layered.addToLayer(1, 1.5f, 0.5f, RGB(-3.0f)));
    EXPECT_EQ(layered.sum(0, 0)[0], 1.0);
    EXPECT_EQ(layered.sum(1, 0)[0], 0.0);
    EXPECT_EQ(layered.layerSum(0, 0, 0)[1], 2.0);
    EXPECT_EQ(layered.layerSum(1, 0, 0)[1], 0.0);
    EXPECT_EQ(layered.layerSum(1, 1, 0)[2], 3.0);
    EXPECT_EQ(layered.fixedSums().size(), std::size_t(2 * 3 * 3));

    Film film(2, 1, 100.0f, {"a", "b"});
    FilmSample sample;
    sample.radiance = RGB(1.0f);
    sample.clearLightPaths(2);
    sample.addLightPath(1, RGB(0.25f));
    film.add(0, 0, sample);
    film.add(1, 0, sample);  // 2 light paths over 2 pixels
    SplatFilm& splats = film.enableSplats();
    ASSERT_EQ(splats.layers(), 2);
    splats.addToLayer(1, 0.5f, 0.5f, RGB(0.5f));
    const Image image = film.resolve();
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[image.channelIndex("b.R")], 0.25f + 0.5f);
    EXPECT_FLOAT_EQ(image.pixel(1, 0)[image.channelIndex("b.R")], 0.25f);
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[image.channelIndex("a.R")], 0.0f);
    EXPECT_FLOAT_EQ(image.pixel(0, 0)[0], 1.0f);

    std::stringstream bytes;  // a render checkpoint keeps the layers' splats
    writeFilmState(film, bytes);
    Film restored(2, 1, 100.0f, {"a", "b"});
    readFilmState(bytes, restored);
    EXPECT_EQ(restored.resolve().pixels, image.pixels);
}

// A render checkpoint (core/film_state.h) keeps the splats: the film read back resolves the same.
TEST(SplatFilm, FilmStateKeepsTheSplats) {
    Film film(3, 2, 100.0f);
    FilmSample a;
    a.radiance = RGB(0.5f);
    film.add(1, 1, a);
    film.enableSplats().add(2.5f, 0.5f, RGB(1.0f, 2.0f, 3.0f));
    std::stringstream bytes;
    writeFilmState(film, bytes);
    Film restored(3, 2, 100.0f);
    readFilmState(bytes, restored);
    ASSERT_NE(restored.splats(), nullptr);
    EXPECT_EQ(restored.splats()->fixedSums(), film.splats()->fixedSums());
    EXPECT_EQ(restored.resolve().pixels, film.resolve().pixels);
    std::stringstream plain;
    writeFilmState(Film(3, 2, 100.0f), plain);
    Film none(3, 2, 100.0f);
    readFilmState(plain, none);
    EXPECT_EQ(none.splats(), nullptr);
}

}  // namespace
}  // namespace fluence
