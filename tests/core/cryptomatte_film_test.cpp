// Cryptomatte accumulation (core/cryptomatte_film.h): counts per name and layer, coverage over the
// pixel's samples, the ranking, and samples that name nothing.
#include "core/cryptomatte_film.h"

#include <gtest/gtest.h>

namespace fluence {
namespace {

FilmSample named(std::uint32_t object, std::uint32_t material) {
    FilmSample s;
    s.objectName = object;
    s.materialName = material;
    return s;
}

TEST(CryptomatteFilm, CoverageIsTheFractionOfThePixelsSamples) {
    CryptomatteFilm film(2, 2, {CryptomatteSource::Object, CryptomatteSource::Material});
    // Pixel (1, 0): object 7 four times, object 3 twice, two misses; materials 0 (x3) and none.
    for (int i = 0; i < 4; ++i) film.add(1, 0, named(7, 0));
    film.add(1, 0, named(3, kNoName));
    film.add(1, 0, named(3, kNoName));
    film.add(1, 0, FilmSample{});
    film.add(1, 0, FilmSample{});
    EXPECT_EQ(film.samples(1, 0), 8u);

    const auto objects = film.ranked(1, 0, 0);
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[0].name, 7u);
    EXPECT_FLOAT_EQ(objects[0].coverage, 0.5f);
    EXPECT_EQ(objects[1].name, 3u);
    EXPECT_FLOAT_EQ(objects[1].coverage, 0.25f);

    const auto materials = film.ranked(1, 0, 1);
    ASSERT_EQ(materials.size(), 1u);
    EXPECT_EQ(materials[0].name, 0u);
    EXPECT_FLOAT_EQ(materials[0].coverage, 0.5f);

    EXPECT_TRUE(film.ranked(0, 0, 0).empty());  // other pixels untouched
    EXPECT_EQ(film.samples(0, 1), 0u);
}

// Equal coverages rank by name index, whatever order the samples came in.
TEST(CryptomatteFilm, RankingIsDeterministic) {
    CryptomatteFilm a(1, 1, {CryptomatteSource::Object}), b(1, 1, {CryptomatteSource::Object});
    for (std::uint32_t name : {5u, 2u, 9u}) a.add(0, 0, named(name, kNoName));
    for (std::uint32_t name : {9u, 5u, 2u}) b.add(0, 0, named(name, kNoName));
    const auto ra = a.ranked(0, 0, 0), rb = b.ranked(0, 0, 0);
    ASSERT_EQ(ra.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(ra[i].name, rb[i].name);
        EXPECT_EQ(ra[i].coverage, rb[i].coverage);
    }
    EXPECT_EQ(ra[0].name, 2u);
    EXPECT_EQ(ra[2].name, 9u);
}

}  // namespace
}  // namespace fluence
