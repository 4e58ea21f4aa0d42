// Film state round trip (core/film_state.h): a film written and read back holds every sum, count,
// cost, depth, light path layer and splat exactly, goes on summing to the same bits as the original, and a state
// of another shape, other layers, another version, or cut short is refused with a message saying so.
#include "core/film_state.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

#include "core/random.h"

namespace fluence {
namespace {

constexpr int kWidth = 5, kHeight = 3;

// Sample n of pixel (x, y): values with full mantissas, some misses, and light path layers.
FilmSample sampleFor(int x, int y, int n) {
    SampleStream rng(7, std::uint64_t(y * kWidth + x), std::uint64_t(n));
    FilmSample s;
    s.radiance = RGB(rng.next() * 3.0f, rng.next(), rng.next() * 0.1f);
    s.hit = rng.next() < 0.7f;
    s.albedo = RGB(rng.next(), rng.next(), rng.next());
    s.normal = Vec3f(rng.next(), rng.next(), rng.next());
    s.depth = 1.0f + rng.next() * 10.0f;
    s.clearLightPaths(2);
    s.addLightPath(0, RGB(rng.next(), 0.0f, rng.next()));
    s.addLightPath(1, RGB(0.0f, rng.next(), 0.0f));
    return s;
}

// Adds samples first..first+count-1 to every pixel but (0, 0), which stops early (as adaptive
// sampling stops pixels), so pixels hold different counts.
void addSamples(Film& film, int first, int count) {
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int n = first; n < first + count; ++n)
                if (x + y > 0 || n < 3) film.add(x, y, sampleFor(x, y, n), 1.0 + 0.37 * double(n + x));
}

Film makeFilm() { return Film(kWidth, kHeight, 500.0f, {"diffuse", "specular"}); }

void expectSameBits(const Film& a, const Film& b) {
    const Image ia = a.resolve(), ib = b.resolve();
    ASSERT_EQ(ia.channels, ib.channels);
    ASSERT_EQ(ia.pixels.size(), ib.pixels.size());
    EXPECT_EQ(std::memcmp(ia.pixels.data(), ib.pixels.data(), ia.pixels.size() * sizeof(float)), 0);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            EXPECT_EQ(a.samples(x, y), b.samples(x, y));
            const double ea = a.relativeError(x, y), eb = b.relativeError(x, y);
            EXPECT_EQ(std::memcmp(&ea, &eb, sizeof ea), 0) << x << ", " << y;  // the luminance sums too
            const double ca = a.cost(x, y), cb = b.cost(x, y);
            EXPECT_EQ(std::memcmp(&ca, &cb, sizeof ca), 0) << x << ", " << y;  // adaptive sampling's costs
        }
}

TEST(FilmState, RoundTripHoldsEverySumAndGoesOnToTheSameBits) {
    Film original = makeFilm();
    addSamples(original, 0, 7);
    std::stringstream bytes;
    writeFilmState(original, bytes);

    Film restored = makeFilm();
    readFilmState(bytes, restored);
    expectSameBits(original, restored);
    EXPECT_EQ(restored.samples(0, 0), 3u);
    EXPECT_EQ(restored.samples(1, 0), 7u);

    addSamples(original, 7, 9);
    addSamples(restored, 7, 9);
    expectSameBits(original, restored);
}

TEST(FilmState, TheSplatFilmRoundTrips) {
    Film original = makeFilm();
    addSamples(original, 0, 4);
    ASSERT_TRUE(original.enableSplats().add(2.5f, 1.5f, RGB(0.3f, 0.2f, 0.1f)));
    std::stringstream bytes;
    writeFilmState(original, bytes);
    Film restored = makeFilm();
    readFilmState(bytes, restored);
    ASSERT_NE(restored.splats(), nullptr);
    expectSameBits(original, restored);
    EXPECT_EQ(restored.splats()->sum(2, 1), original.splats()->sum(2, 1));
}

TEST(FilmState, AnEmptyFilmRoundTrips) {
    Film original(2, 2, 10.0f);
    std::stringstream bytes;
    writeFilmState(original, bytes);
    Film restored(2, 2, 10.0f);
    readFilmState(bytes, restored);
    EXPECT_EQ(restored.totalSamples(), 0u);
    EXPECT_EQ(restored.resolve().pixels, original.resolve().pixels);
}

// The message of the FilmStateError that reading `bytes` into `film` throws ("" if none).
std::string readError(const std::string& bytes, Film& film) {
    std::istringstream in(bytes);
    try {
        readFilmState(in, film);
    } catch (const FilmStateError& e) {
        return e.what();
    }
    return "";
}

TEST(FilmState, RefusesAnotherShapeOtherLayersAndCutData) {
    Film original = makeFilm();
    addSamples(original, 0, 2);
    std::ostringstream out;
    writeFilmState(original, out);
    const std::string bytes = out.str();

    Film wider(kWidth + 1, kHeight, 500.0f, {"diffuse", "specular"});
    EXPECT_NE(readError(bytes, wider).find("5x3, this one 6x3"), std::string::npos) << readError(bytes, wider);
    Film otherLayers(kWidth, kHeight, 500.0f, {"diffuse"});
    EXPECT_NE(readError(bytes, otherLayers).find("(diffuse, specular), this one's (diffuse)"), std::string::npos);
    Film otherFar(kWidth, kHeight, 100.0f, {"diffuse", "specular"});
    EXPECT_NE(readError(bytes, otherFar).find("far depth"), std::string::npos);
    Film fits = makeFilm();
    EXPECT_NE(readError(bytes.substr(0, bytes.size() - 1), fits).find("ends early"), std::string::npos);
    EXPECT_EQ(readError(bytes, fits), "");
}

TEST(FilmState, RefusesAStateOfAnotherVersionSayingWhichAndWhy) {
    Film original = makeFilm();
    std::ostringstream out;
    writeFilmState(original, out);
    std::string bytes = out.str();
    const std::uint32_t older = kFilmStateVersion - 1;  // version 4: even/odd halves, no feature squares
    std::memcpy(bytes.data(), &older, sizeof older);
    Film film = makeFilm();
    const std::string message = readError(bytes, film);
    EXPECT_NE(message.find("film state version " + std::to_string(older) + " (this build reads version " +
                           std::to_string(kFilmStateVersion)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("render it again without resuming"), std::string::npos) << message;
}

}  // namespace
}  // namespace fluence
