#include "core/film.h"

#include <gtest/gtest.h>

namespace fluence {
namespace {

TEST(FilmSample, ACopyWithSomeLightPathLayersHasEveryOtherFieldAndThoseLayers) {
    // withLightPaths(n) copies the fields before the layers as they are and the first n layers.
    FilmSample s;
    s.radiance = RGB(1, 2, 3);
    s.hit = true;
    s.albedo = RGB(0.5f, 0.25f, 0.125f);
    s.normal = Vec3f(0, 0.6f, 0.8f);
    s.depth = 7.0f;
    s.objectName = 11;
    s.materialName = 13;
    constexpr auto kLayers = std::size_t(kMaxLightPathLayers);
    for (std::size_t i = 0; i < 3 * kLayers; ++i) s.lightPaths[i] = float(i) + 0.5f;
    for (std::size_t layers : {std::size_t(0), std::size_t(2), kLayers}) {
        const FilmSample c = s.withLightPaths(layers);
        EXPECT_EQ(c.radiance, s.radiance);
        EXPECT_EQ(c.hit, s.hit);
        EXPECT_EQ(c.albedo, s.albedo);
        EXPECT_EQ(c.normal, s.normal);
        EXPECT_EQ(c.depth, s.depth);
        EXPECT_EQ(c.objectName, s.objectName);
        EXPECT_EQ(c.materialName, s.materialName);
        for (std::size_t i = 0; i < 3 * layers; ++i) EXPECT_EQ(c.lightPaths[i], s.lightPaths[i]) << i;
    }
}

TEST(Film, ResolvesMeansCoverageMinDepthAndCounts) {
    Film film(2, 1, 1000.0f);
    auto hitSample = [](RGB radiance, RGB albedo, Vec3f normal, float depth) {
        FilmSample s;
        s.radiance = radiance;
        s.hit = true;
        s.albedo = albedo;
        s.normal = normal;
        s.depth = depth;
        return s;
    };
    const FilmSample a = hitSample(RGB(1, 2, 3), RGB(0.5f), Vec3f(0, 0, 1), 4.0f);
    const FilmSample b = hitSample(RGB(3, 2, 1), RGB(0.25f), Vec3f(0, 1, 0), 2.0f);
    FilmSample miss;
    miss.radiance = RGB(1, 1, 1);
    film.add(0, 0, a);
    film.add(0, 0, b);
    film.add(0, 0, miss);
    film.add(1, 0, miss);
    Image image = film.resolve();
    ASSERT_EQ(image.channels, film.channelNames());
    const float* p = image.pixel(0, 0);
    EXPECT_FLOAT_EQ(p[image.channelIndex("R")], 5.0f / 3.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("B")], 5.0f / 3.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("A")], 2.0f / 3.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("albedo.R")], 0.25f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("N.Z")], 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("Z")], 2.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("sampleCount")], 3.0f);
    const float* q = image.pixel(1, 0);
    EXPECT_FLOAT_EQ(q[image.channelIndex("Z")], 1000.0f);  // nothing hit: the far clip
    EXPECT_FLOAT_EQ(q[image.channelIndex("A")], 0.0f);
    EXPECT_EQ(film.totalSamples(), 4u);
}

TEST(Film, ResolvesLightPathLayersAfterTheOtherChannels) {
    Film film(1, 1, 1000.0f, {"diffuse", "specular"});
    FilmSample a, b;
    a.clearLightPaths(2);
    b.clearLightPaths(2);
    a.addLightPath(0, RGB(1, 2, 3));
    a.addLightPath(1, RGB(0.5f));
    b.addLightPath(0, RGB(3, 2, 1));
    film.add(0, 0, a);
    film.add(0, 0, b);
    Image image = film.resolve();
    ASSERT_EQ(image.channels, film.channelNames());
    EXPECT_EQ(image.channels.back(), "specular.B");
    const float* p = image.pixel(0, 0);
    EXPECT_FLOAT_EQ(p[image.channelIndex("diffuse.R")], 2.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("diffuse.B")], 2.0f);
    EXPECT_FLOAT_EQ(p[image.channelIndex("specular.G")], 0.25f);
}

TEST(Film, RefusesMoreLightPathLayersThanItHolds) {
    EXPECT_THROW(Film(1, 1, 1.0f, std::vector<std::string>(kMaxLightPathLayers + 1, "x")), std::invalid_argument);
}

TEST(Film, SumsEachPixelsSampleCostsWithoutChangingItsImage) {
    Film counted(2, 1, 1000.0f), uncounted(2, 1, 1000.0f);
    FilmSample s;
    s.radiance = RGB(0.5f);
    counted.add(0, 0, s, 3.0);
    counted.add(0, 0, s, 4.5);
    counted.add(1, 0, s);
    for (int i = 0; i < 2; ++i) uncounted.add(0, 0, s);
    uncounted.add(1, 0, s);
    EXPECT_EQ(counted.cost(0, 0), 7.5);
    EXPECT_EQ(counted.cost(1, 0), 0.0) << "a sample added without a cost costs nothing";
    EXPECT_EQ(counted.resolve().pixels, uncounted.resolve().pixels);
}

}  // namespace
}  // namespace fluence
