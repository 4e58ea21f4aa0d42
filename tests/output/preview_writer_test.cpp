// Tests for output/preview_writer.h: display transform, 8-bit rounding, row order, atomicity.
#include "output/preview_writer.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "output/atomic_file.h"
#include "tests/support/temp_dir.h"

namespace {

using fluence::Image;
using fluence::color::ColorManagement;
using fluence::output::OutputError;
using fluence::output::writePreviewPng;
namespace fs = std::filesystem;

using fluence::test::TempDir;

// The embedded config, whatever $OCIO the environment has.
ColorManagement builtin() {
    std::optional<std::string> saved;
    if (const char* old = std::getenv("OCIO")) saved = old;
    ::unsetenv("OCIO");
    ColorManagement cm = ColorManagement::load();
    if (saved) ::setenv("OCIO", saved->c_str(), 1);
    return cm;
}

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> readPng(const std::string& path, int& width, int& height) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return {};
    EXPECT_EQ(std::string(in->format_name()), "png");
    EXPECT_EQ(in->spec().nchannels, 3);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
    width = in->spec().width;
    height = in->spec().height;
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * height * 3);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data())) << in->geterror();
    return bytes;
}

TEST(PreviewWriter, TwoByTwoSrgbValuesAndRowOrder) {
    // Channels deliberately not R,G,B first: the writer picks them by name.
    Image image(2, 2, {"albedo.R", "B", "G", "R", "Z"});
    auto set = [&](int x, int y, float r, float g, float b) {
        float* p = image.pixel(x, y);
        p[image.channelIndex("R")] = r;
        p[image.channelIndex("G")] = g;
        p[image.channelIndex("B")] = b;
        p[image.channelIndex("albedo.R")] = 0.5f;
        p[image.channelIndex("Z")] = 1000.0f;
    };
    set(0, 0, 0.0f, 0.18f, 1.0f);       // top-left
    set(1, 0, 5.0f, -1.0f, 0.5f);       // top-right: clipped above and below
    set(0, 1, 0.0031308f, 0.3f, 0.0f);  // bottom-left: sRGB break point
    set(1, 1, 0.001f, 0.8f, 0.05f);     // bottom-right

    // Expected bytes: round(255 * sRGB_OETF(v)), sRGB per IEC 61966-2-1 (no value near a .5 boundary;
    // 0.18 checks rounding rather than truncation):
    //   0 -> 0; 0.18 -> 0.4613561 -> 117.64 -> 118; 1 -> 255; 5 -> 255; -1 -> 0; 0.5 -> 0.7353570 -> 187.52 -> 188
    //   0.0031308 -> 0.04045 -> 10.31 -> 10; 0.3 -> 0.5838315 -> 148.88 -> 149; 0 -> 0
    //   0.001 -> 0.01292 -> 3.29 -> 3; 0.8 -> 0.9063318 -> 231.11 -> 231; 0.05 -> 0.2478005 -> 63.19 -> 63
    const std::vector<std::uint8_t> expected = {0,  118, 255, 255, 0,   188,  //
                                                10, 149, 0,   3,   231, 63};

    TempDir dir("fluence_png_test");
    const std::string path = dir.file("preview.png");
    const ColorManagement cm = builtin();
    writePreviewPng(path, image, cm);
    EXPECT_EQ(dir.list(), std::vector<std::string>{"preview.png"});
    int w = 0, h = 0;
    const auto bytes = readPng(path, w, h);
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 2);
    ASSERT_EQ(bytes.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(int(bytes[i]), int(expected[i])) << "byte " << i;

    // Explicit display/view give the same file.
    const std::string explicitPath = dir.file("explicit.png");
    writePreviewPng(explicitPath, image, cm, "sRGB", "Standard");
    EXPECT_EQ(readBytes(explicitPath), readBytes(path));
}

TEST(PreviewWriter, RawViewQuantisesLinearValues) {
    Image image(1, 1, {"R", "G", "B"});
    image.pixels = {0.5f, 0.25f, 2.0f};
    TempDir dir("fluence_png_test");
    writePreviewPng(dir.file("raw.png"), image, builtin(), "sRGB", "Raw");
    int w = 0, h = 0;
    const auto bytes = readPng(dir.file("raw.png"), w, h);
    ASSERT_EQ(bytes.size(), 3u);
    EXPECT_EQ(int(bytes[0]), 128);  // 127.5 rounds up
    EXPECT_EQ(int(bytes[1]), 64);   // 63.75
    EXPECT_EQ(int(bytes[2]), 255);
}

TEST(PreviewWriter, ErrorsNamePathAndKeepOldFile) {
    TempDir dir("fluence_png_test");
    const std::string path = dir.file("p.png");
    const ColorManagement cm = builtin();
    Image good(2, 1, {"R", "G", "B"});
    good.pixels = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
    writePreviewPng(path, good, cm);
    const std::string before = readBytes(path);

    Image noRgb(2, 1, {"N.X", "N.Y", "N.Z"});
    Image badSize(2, 1, {"R", "G", "B"});
    badSize.pixels.resize(5);
    for (const Image* bad : {&noRgb, &badSize}) {
        try {
            writePreviewPng(path, *bad, cm);
            ADD_FAILURE() << "expected OutputError";
        } catch (const OutputError& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
    try {
        writePreviewPng(path, good, cm, "sRGB", "No Such View");
        ADD_FAILURE() << "expected OutputError";
    } catch (const OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("No Such View"), std::string::npos) << e.what();
    }
    EXPECT_THROW(writePreviewPng("/no/such/dir/p.png", good, cm), OutputError);
    EXPECT_EQ(dir.list(), std::vector<std::string>{"p.png"});
    EXPECT_EQ(readBytes(path), before);
}

}  // namespace
