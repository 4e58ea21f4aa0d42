// The UsdUVTexture texture system: orientation (st up), wrap modes, colour spaces, UDIM tiles,
// grey files, unreadable files, and mip-mapped filtering of wide footprints.
#include "texture/texture_system.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::texture {
namespace {

using Rgba = std::array<float, 4>;

class TextureSystemTest : public ::testing::Test {
protected:
    TextureSystemTest() : system(color::ColorManagement::load()) {}

    // A 2x2 float EXR: top-left red, top-right green, bottom-left blue, bottom-right white.
    std::string quadrants() {
        std::string path = dir.file("quadrants.exr");
        test::writeImage<float>(path, 2, 2, 3, OIIO::TypeDesc::FLOAT, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
        return path;
    }
    const TextureSystem::Texture& open(const std::string& path, SourceColorSpace space = SourceColorSpace::Auto) {
        std::string error;
        const TextureSystem::Texture* t = system.open(path, space, error);
        EXPECT_TRUE(t) << error;
        return *t;
    }
    Rgba at(const TextureSystem::Texture& t, float s, float tt, Wrap wrap = Wrap::Repeat, const Footprint& f = {}) {
        Rgba v{-1, -1, -1, -1};
        EXPECT_TRUE(system.lookup(t, s, tt, f, wrap, wrap, v));
        return v;
    }

    test::TempDir dir;
    TextureSystem system;
};

TEST_F(TextureSystemTest, StGrowsRightAndUpFromTheBottomLeftCorner) {
    const auto& t = open(quadrants());
    EXPECT_EQ(at(t, 0.25f, 0.75f), (Rgba{1, 0, 0, 1})) << "top-left";
    EXPECT_EQ(at(t, 0.75f, 0.75f), (Rgba{0, 1, 0, 1})) << "top-right";
    EXPECT_EQ(at(t, 0.25f, 0.25f), (Rgba{0, 0, 1, 1})) << "bottom-left";
    EXPECT_EQ(at(t, 0.75f, 0.25f), (Rgba{1, 1, 1, 1})) << "bottom-right";
}

TEST_F(TextureSystemTest, WrapModesOutsideTheUnitSquare) {
    const auto& t = open(quadrants());
    EXPECT_EQ(at(t, 1.25f, 0.75f, Wrap::Repeat), (Rgba{1, 0, 0, 1}));
    EXPECT_EQ(at(t, 1.25f, 0.75f, Wrap::Clamp), (Rgba{0, 1, 0, 1}));
    EXPECT_EQ(at(t, 1.25f, 0.75f, Wrap::Mirror), (Rgba{0, 1, 0, 1}));
    Rgba black = at(t, 1.25f, 0.75f, Wrap::Black);
    EXPECT_EQ(black[0], 0.0f);
    EXPECT_EQ(black[1], 0.0f);
    EXPECT_EQ(black[2], 0.0f);
}

TEST_F(TextureSystemTest, EightBitFilesAreSrgbUnlessRaw) {
    std::string path = dir.file("grey.png");
    test::writeImage<std::uint8_t>(path, 1, 1, 3, OIIO::TypeDesc::UINT8, {128, 128, 128});
    const float encoded = 128.0f / 255.0f;
    const float linear = std::pow((encoded + 0.055f) / 1.055f, 2.4f);  // IEC 61966-2-1
    EXPECT_NEAR(at(open(path), 0.5f, 0.5f)[0], linear, 1e-3f) << "auto: an 8-bit file is sRGB";
    EXPECT_NEAR(at(open(path, SourceColorSpace::SRGB), 0.5f, 0.5f)[0], linear, 1e-3f);
    EXPECT_NEAR(at(open(path, SourceColorSpace::Raw), 0.5f, 0.5f)[0], encoded, 1e-6f) << "raw: as stored";
    EXPECT_NEAR(at(open(quadrants(), SourceColorSpace::Auto), 0.25f, 0.75f)[0], 1.0f, 1e-6f)
        << "auto: floats are linear";
}

// A named colour space of the config (a MaterialX colorspace) converts the file's values through
// OCIO, as ColorManagement converts a colour from that space; an unknown name is an error.
TEST_F(TextureSystemTest, NamedColourSpacesConvertThroughTheConfig) {
    const std::string path = dir.file("acescg.exr");
    test::writeImage<float>(path, 1, 1, 3, OIIO::TypeDesc::FLOAT, {0.8f, 0.3f, 0.1f});
    std::string error;
    const TextureSystem::Texture* t = system.open(path, SourceColorSpace::Raw, error, "acescg");
    ASSERT_TRUE(t) << error;
    const RGB expected = color::ColorManagement::load().toRenderingSpace("acescg", RGB(0.8f, 0.3f, 0.1f));
    const Rgba v = at(*t, 0.5f, 0.5f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[std::size_t(c)], expected[c], 1e-5f) << c;
    EXPECT_GT(std::abs(v[0] - 0.8f), 0.05f) << "acescg is not the rendering space: the values change";
    EXPECT_EQ(system.open(path, SourceColorSpace::Raw, error, "no_such_space"), nullptr);
    EXPECT_NE(error.find(path), std::string::npos) << error;
}

TEST_F(TextureSystemTest, GreyFilesReadAsGreyRgbAndAlphaIsKept) {
    std::string grey = dir.file("grey.exr"), greyAlpha = dir.file("grey_alpha.exr");
    test::writeImage<float>(grey, 1, 1, 1, OIIO::TypeDesc::FLOAT, {0.25f});
    test::writeImage<float>(greyAlpha, 1, 1, 2, OIIO::TypeDesc::FLOAT, {0.25f, 0.5f});
    EXPECT_EQ(at(open(grey), 0.5f, 0.5f), (Rgba{0.25f, 0.25f, 0.25f, 1.0f}));
    EXPECT_EQ(at(open(greyAlpha), 0.5f, 0.5f), (Rgba{0.25f, 0.25f, 0.25f, 0.5f}));
}

TEST_F(TextureSystemTest, UdimTilesByIntegerSt) {
    auto tile = [&](int number, float r, float g, float b) {
        test::writeImage<float>(dir.file("tiles." + std::to_string(number) + ".exr"), 2, 2, 3, OIIO::TypeDesc::FLOAT,
                                {r, g, b, r, g, b, 0, 0, 0, 0, 0, 0});  // top row coloured, bottom row black
    };
    tile(1001, 1, 0, 0);
    tile(1002, 0, 1, 0);
    tile(1011, 0, 0, 1);
    const auto& t = open(dir.file("tiles.<UDIM>.exr"));
    EXPECT_EQ(at(t, 0.5f, 0.75f), (Rgba{1, 0, 0, 1})) << "tile 1001, top half";
    EXPECT_EQ(at(t, 0.5f, 0.25f), (Rgba{0, 0, 0, 1})) << "tile 1001, bottom half";
    EXPECT_EQ(at(t, 1.5f, 0.75f), (Rgba{0, 1, 0, 1})) << "tile 1002";
    EXPECT_EQ(at(t, 0.5f, 1.75f), (Rgba{0, 0, 1, 1})) << "tile 1011";
    Rgba none{};
    EXPECT_FALSE(system.lookup(t, 2.5f, 0.5f, {}, Wrap::Repeat, Wrap::Repeat, none)) << "tile 1003 does not exist";
}

TEST_F(TextureSystemTest, UnreadableFilesAreNamed) {
    std::string error;
    EXPECT_EQ(system.open(dir.file("missing.png"), SourceColorSpace::Auto, error), nullptr);
    EXPECT_NE(error.find("missing.png"), std::string::npos) << error;
    EXPECT_EQ(system.open(dir.file("none.<UDIM>.png"), SourceColorSpace::Auto, error), nullptr);
    EXPECT_NE(error.find("none.<UDIM>.png"), std::string::npos) << error;
}

TEST_F(TextureSystemTest, WideFootprintsAverageTheTexels) {
    // A 256x256 checkerboard of 1-texel squares: a point lookup sees 0 or 1, a footprint of many
    // texels (a coarser mip level, made on first use) sees their mean.
    const int n = 256;
    std::string path = dir.file("checker.exr");
    test::writeTexelChecker(path, n);
    const auto& t = open(path);
    float point = at(t, (10 + 0.5f) / n, 1.0f - (20 + 0.5f) / n)[0];
    EXPECT_EQ(point, 0.0f) << "texel (10, 20)";
    float wide = at(t, 0.5f, 0.5f, Wrap::Repeat, {16.0f / n, 0.0f, 0.0f, 16.0f / n})[0];
    EXPECT_NEAR(wide, 0.5f, 0.02f);
}

}  // namespace
}  // namespace fluence::texture
