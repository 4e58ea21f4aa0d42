// texture::loadImage: float files come back as written, 8-bit sRGB files are decoded to linear
// (alpha left alone), Raw and SRGB override the file, images inside USDZ packages read as their
// entries, and unreadable files name themselves.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"
#include "texture/image_loader.h"

namespace fluence::texture {
namespace {

using test::writeImage;

TEST(ImageLoader, FloatExrComesBackAsWritten) {
    test::TempDir dir;
    std::vector<float> pixels = {0.0f, 0.5f, 2.0f, 1.0f, 10.0f, -0.25f, 1e-3f, 0.5f, 3.0f, 4.0f, 5.0f, 0.0f};
    writeImage(dir.file("a.exr"), 3, 1, 4, OIIO::TypeDesc::FLOAT, pixels);
    Image image = loadImage(dir.file("a.exr"));
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 1);
    EXPECT_EQ(image.channels, 4);
    EXPECT_EQ(image.alphaChannel, 3);
    EXPECT_EQ(image.pixels, pixels);
}

TEST(ImageLoader, EightBitPngIsDecodedFromSrgbExceptAlpha) {
    test::TempDir dir;
    // Two pixels, top row first: (128, 255, 0, 128) and (10, 64, 192, 255).
    std::vector<std::uint8_t> pixels = {128, 255, 0, 128, 10, 64, 192, 255};
    writeImage(dir.file("b.png"), 1, 2, 4, OIIO::TypeDesc::UINT8, pixels);
    Image image = loadImage(dir.file("b.png"));
    ASSERT_EQ(image.channels, 4);
    EXPECT_NEAR(image.at(0, 0, 0), 0.2158605f, 1e-5f);  // sRGB 128/255
    EXPECT_NEAR(image.at(0, 0, 1), 1.0f, 1e-6f);
    EXPECT_EQ(image.at(0, 0, 2), 0.0f);
    EXPECT_NEAR(image.at(0, 0, 3), 128.0f / 255.0f, 1e-6f) << "alpha is not decoded";
    EXPECT_NEAR(image.at(0, 1, 0), 10.0f / 255.0f / 12.92f, 1e-7f) << "the linear toe";
    EXPECT_NEAR(image.at(0, 1, 2), 0.5271151f, 1e-5f);  // sRGB 192/255

    Image raw = loadImage(dir.file("b.png"), SourceColorSpace::Raw);
    EXPECT_NEAR(raw.at(0, 0, 0), 128.0f / 255.0f, 1e-6f);
}

TEST(ImageLoader, SrgbOverridesALinearFile) {
    test::TempDir dir;
    writeImage(dir.file("c.exr"), 1, 1, 3, OIIO::TypeDesc::FLOAT, std::vector<float>{0.5f, 0.5f, 0.5f});
    EXPECT_EQ(loadImage(dir.file("c.exr")).pixels[0], 0.5f);
    EXPECT_NEAR(loadImage(dir.file("c.exr"), SourceColorSpace::SRGB).pixels[0], 0.2140411f, 1e-6f);
}

TEST(ImageLoader, RadianceHdrIsLinear) {
    test::TempDir dir;
    // RGBE keeps 8-bit mantissas under one exponent per pixel: good to 1% of the pixel's largest value.
    std::vector<float> pixels = {0.25f, 0.5f, 0.75f, 100.0f, 60.0f, 30.0f};
    writeImage(dir.file("d.hdr"), 2, 1, 3, OIIO::TypeDesc::FLOAT, pixels);
    Image image = loadImage(dir.file("d.hdr"));
    ASSERT_EQ(image.pixels.size(), pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
        EXPECT_NEAR(image.pixels[i], pixels[i], 0.01f * (i < 3 ? 0.75f : 100.0f)) << i;
}

TEST(ImageLoader, UnreadableFilesNameThemselves) {
    test::TempDir dir;
    try {
        loadImage(dir.file("missing.exr"));
        FAIL() << "expected ImageLoadError";
    } catch (const ImageLoadError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
    }
}

// A dome or rect light's texture inside a USDZ package (scene/package_files.h) reads as its entry.
TEST(ImageLoader, PackagedImagesReadAsTheirEntries) {
    const std::filesystem::path package = test::sharedPath("usd_corpus/tinyusdz/models/texture-cat-plane.usdz");
    FLUENCE_REQUIRE_SHARED(package);
    Image image = loadImage(package.generic_string() + "[textures/texture-cat.jpg]");
    EXPECT_GT(image.width, 1);
    EXPECT_GT(image.height, 1);
    EXPECT_GE(image.channels, 3);
    EXPECT_THROW(loadImage(package.generic_string() + "[textures/no-such.jpg]"), ImageLoadError);
}

TEST(ImageLoader, SrgbTransferFunction) {
    EXPECT_EQ(srgbToLinear(0.0f), 0.0f);
    EXPECT_NEAR(srgbToLinear(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgbToLinear(0.04045f), 0.0031308f, 1e-6f);
    EXPECT_NEAR(srgbToLinear(0.5f), 0.2140411f, 1e-6f);
}

}  // namespace
}  // namespace fluence::texture
