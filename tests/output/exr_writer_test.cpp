// Tests for output/exr_writer.h: bit-exact round trip through OpenImageIO, header attributes,
// atomic replacement.
#include "output/exr_writer.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "output/atomic_file.h"
#include "tests/support/temp_dir.h"

namespace {

using fluence::Image;
using fluence::output::ExrHeader;
using fluence::output::OutputError;
using fluence::output::writeExr;
namespace fs = std::filesystem;

using fluence::test::TempDir;

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::vector<std::string> kChannels = {"R",   "G",   "B",   "albedo.R", "albedo.G",   "albedo.B",
                                            "N.X", "N.Y", "N.Z", "Z",        "sampleCount"};

// A 5x3 image (odd sizes on purpose) whose every value differs, with special values mixed in.
Image makeTestImage() {
    Image image(5, 3, kChannels);
    const float specials[] = {-0.0f,
                              -1.5f,
                              1.0e30f,
                              -3.0e38f,
                              std::numeric_limits<float>::max(),
                              std::numeric_limits<float>::denorm_min(),
                              1.0e-40f,
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              16777217.0f,
                              0.1f};
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<float>(static_cast<int>(i * 37 % 1001) - 500) * 0.0123f + 1.0f / (i + 3);
    for (std::size_t i = 0; i < std::size(specials); ++i) image.pixels[i * 13 % image.pixels.size()] = specials[i];
    // Recognisable corners: top-left pixel R = 1, bottom-left pixel R = 2.
    image.pixel(0, 0)[0] = 1.0f;
    image.pixel(0, 2)[0] = 2.0f;
    return image;
}

ExrHeader makeHeader() {
    ExrHeader header;
    header.strings = {{"fluence/version", "0.1.0"}, {"fluence/scene", "/scenes/kitchen.usda"}};
    header.floats = {{"fluence/renderTimeSeconds", 12.5f}, {"fluence/spp", 64.0f}};
    header.dataChannels = {"N.X", "N.Y", "N.Z", "Z", "sampleCount"};
    return header;
}

TEST(ExrWriter, RoundTripIsBitExactWithMetadata) {
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("beauty.exr");
    const Image image = makeTestImage();
    writeExr(path, image, makeHeader());
    EXPECT_EQ(dir.list(), std::vector<std::string>{"beauty.exr"});

    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(std::string(in->format_name()), "openexr");
    EXPECT_EQ(spec.width, 5);
    EXPECT_EQ(spec.height, 3);
    EXPECT_EQ(spec.tile_width, 0);  // scanline
    ASSERT_EQ(spec.nchannels, static_cast<int>(kChannels.size()));
    for (int c = 0; c < spec.nchannels; ++c) EXPECT_EQ(spec.channelformat(c), OIIO::TypeDesc::FLOAT) << c;
    // Every name survives. The order does not: an EXR channel list is sorted by name in the file
    // and each reader picks its own presentation order. OIIO 2.4 lists R, G, B first, then the
    // other unlayered channels, then each layer (components in R,G,B / X,Y,Z order).
    std::vector<std::string> names = spec.channelnames;
    EXPECT_EQ(names, (std::vector<std::string>{"R", "G", "B", "Z", "sampleCount", "N.X", "N.Y", "N.Z", "albedo.R",
                                               "albedo.G", "albedo.B"}));
    std::vector<std::string> sortedNames = names, sortedExpected = kChannels;
    std::sort(sortedNames.begin(), sortedNames.end());
    std::sort(sortedExpected.begin(), sortedExpected.end());
    ASSERT_EQ(sortedNames, sortedExpected);

    // Compare every value bit for bit, channel by name.
    std::vector<float> pixels(image.pixels.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) << in->geterror();
    const std::size_t nc = kChannels.size();
    for (std::size_t c = 0; c < nc; ++c) {
        const int written = image.channelIndex(names[c]);
        ASSERT_GE(written, 0) << names[c];
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const float got = pixels[(static_cast<std::size_t>(y) * image.width + x) * nc + c];
                const float want = image.pixel(x, y)[written];
                ASSERT_EQ(std::bit_cast<std::uint32_t>(got), std::bit_cast<std::uint32_t>(want))
                    << names[c] << " at (" << x << "," << y << "): " << got << " vs " << want;
            }
    }
    EXPECT_EQ(pixels[0], 1.0f);           // R of the top-left pixel: row 0 is the top
    EXPECT_EQ(pixels[2 * 5 * nc], 2.0f);  // R of the first pixel of the last row

    EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
    const OIIO::ParamValue* chroma = spec.find_attribute("chromaticities");
    ASSERT_NE(chroma, nullptr);
    EXPECT_EQ(chroma->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8));
    const float expected[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    const float* got = static_cast<const float*>(chroma->data());
    for (int i = 0; i < 8; ++i) EXPECT_EQ(got[i], expected[i]) << i;
    EXPECT_EQ(spec.get_string_attribute("colorSpace"), "lin_rec709");
    // OIIO does not write "oiio:" attributes into EXR files, and its 2.4 EXR reader reports
    // "oiio:ColorSpace" as "Linear" for every EXR: the "colorSpace" attribute is the one that persists.
    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "Linear");
    EXPECT_EQ(spec.get_string_attribute("fluence/version"), "0.1.0");
    EXPECT_EQ(spec.get_string_attribute("fluence/scene"), "/scenes/kitchen.usda");
    EXPECT_EQ(spec.get_float_attribute("fluence/renderTimeSeconds"), 12.5f);
    EXPECT_EQ(spec.get_float_attribute("fluence/spp"), 64.0f);
    EXPECT_EQ(spec.get_string_attribute("fluence/dataChannels"), "N.X,N.Y,N.Z,Z,sampleCount");
    in->close();
}

TEST(ExrWriter, FixedDateTimeGivesIdenticalBytes) {
    // OIIO stamps EXRs with the current time ("capDate", from "DateTime") unless one is given; with
    // a fixed DateTime the same image writes the same bytes.
    TempDir dir("fluence_exr_test");
    ExrHeader header = makeHeader();
    header.strings.emplace_back("DateTime", "2026:01:02 03:04:05");
    writeExr(dir.file("a.exr"), makeTestImage(), header);
    writeExr(dir.file("b.exr"), makeTestImage(), header);
    EXPECT_EQ(readBytes(dir.file("a.exr")), readBytes(dir.file("b.exr")));
    auto in = OIIO::ImageInput::open(dir.file("a.exr"));
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(in->spec().get_string_attribute("DateTime"), "2026:01:02 03:04:05");
}

TEST(ExrWriter, RawExrHeaderHasRealChromaticitiesAttribute) {
    // OpenEXR's own type name for the attribute is "chromaticities" (Imf::ChromaticitiesAttribute):
    // find it in the raw header bytes as <name>\0<type>\0<size = 32, little endian>.
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("c.exr");
    writeExr(path, makeTestImage(), makeHeader());
    const std::string bytes = readBytes(path);
    const std::string needle = std::string("chromaticities\0chromaticities\0\x20\0\0\0", 34);
    const auto at = bytes.find(needle);
    ASSERT_NE(at, std::string::npos);
    float values[8];
    std::memcpy(values, bytes.data() + at + needle.size(), sizeof values);
    EXPECT_EQ(values[0], 0.64f);
    EXPECT_EQ(values[7], 0.3290f);
    EXPECT_NE(bytes.find(std::string("compression\0compression\0\x01\0\0\0\x03", 29)), std::string::npos)
        << "ZIP_COMPRESSION (3)";
}

TEST(ExrWriter, CustomChromaticitiesAndColorSpace) {
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("ap1.exr");
    ExrHeader header;
    header.colorSpace = "acescg";
    header.chromaticities = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
    Image image(2, 2, {"R", "G", "B"});
    writeExr(path, image, header);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(in->spec().get_string_attribute("colorSpace"), "acescg");
    const OIIO::ParamValue* chroma = in->spec().find_attribute("chromaticities");
    ASSERT_NE(chroma, nullptr);
    EXPECT_EQ(static_cast<const float*>(chroma->data())[6], 0.32168f);
    EXPECT_EQ(in->spec().find_attribute("fluence/dataChannels"), nullptr);
}

TEST(ExrWriter, PixelAspectRatioIsTheStandardAttribute) {
    // OpenEXR's pixelAspectRatio is a float attribute: <name>\0float\0<size = 4><value>.
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("par.exr");
    ExrHeader header;
    header.pixelAspectRatio = 2.0f;
    writeExr(path, Image(2, 2, {"R", "G", "B"}), header);
    const std::string bytes = readBytes(path);
    const std::string needle = std::string("pixelAspectRatio\0float\0\x04\0\0\0", 27);
    const auto at = bytes.find(needle);
    ASSERT_NE(at, std::string::npos);
    float value = 0.0f;
    std::memcpy(&value, bytes.data() + at + needle.size(), sizeof value);
    EXPECT_EQ(value, 2.0f);
}

// Per-channel pixel types: values converted (uint rounded and clamped, not normalised), the
// compression, m44f matrices and colorInteropID as asked; a type list of another length refused.
TEST(ExrWriter, ChannelTypesCompressionMatricesAndInteropId) {
    using fluence::output::PixelType;
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("typed.exr");
    Image image(2, 1, {"R", "Z", "id"});
    image.pixels = {0.5f, 1.0f / 3.0f, 6.6f, 1.0f, 2.0f, -3.0f};
    ExrHeader header;
    header.channelTypes = {PixelType::Float, PixelType::Half, PixelType::Uint};
    header.compression = "piz";
    header.colorInteropId = "lin_rec709_scene";
    std::array<float, 16> m{};
    for (int i = 0; i < 16; ++i) m[std::size_t(i)] = float(i);
    header.matrices = {{"worldToCamera", m}};
    writeExr(path, image, header);

    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.channelformat(0), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(spec.channelformat(1), OIIO::TypeDesc::HALF);
    EXPECT_EQ(spec.channelformat(2), OIIO::TypeDesc::UINT);
    EXPECT_EQ(spec.get_string_attribute("compression"), "piz");
    EXPECT_EQ(spec.get_string_attribute("colorInteropID"), "lin_rec709_scene");
    const OIIO::ParamValue* stored = spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
    ASSERT_NE(stored, nullptr);
    EXPECT_EQ(std::memcmp(stored->data(), m.data(), sizeof m), 0);
    std::uint32_t ids[2];
    ASSERT_TRUE(in->read_image(0, 0, 2, 3, OIIO::TypeDesc::UINT, ids));
    EXPECT_EQ(ids[0], 7u);
    EXPECT_EQ(ids[1], 0u);
    float z[2];
    ASSERT_TRUE(in->read_image(0, 0, 1, 2, OIIO::TypeDesc::FLOAT, z));
    EXPECT_NEAR(z[0], 1.0f / 3.0f, 1e-3f);  // stored in half precision
    EXPECT_NE(z[0], 1.0f / 3.0f);
    EXPECT_EQ(z[1], 2.0f);
    in->close();

    header.channelTypes.pop_back();
    EXPECT_THROW(writeExr(path, image, header), OutputError);
}

TEST(ExrWriter, MissingDirectoryThrowsAndLeavesNothing) {
    try {
        writeExr("/no/such/dir/x.exr", makeTestImage(), makeHeader());
        FAIL() << "expected OutputError";
    } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write /no/such/dir/x.exr: directory does not exist");
    }
    EXPECT_FALSE(fs::exists("/no/such/dir"));
}

TEST(ExrWriter, InconsistentImageIsRejectedAndOldFileSurvives) {
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("frame.exr");
    writeExr(path, makeTestImage(), makeHeader());
    const std::string good = readBytes(path);

    Image bad = makeTestImage();
    bad.pixels.pop_back();  // buffer no longer matches width*height*channels
    try {
        writeExr(path, bad, makeHeader());
        FAIL() << "expected OutputError";
    } catch (const OutputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path), std::string::npos) << message;
        EXPECT_NE(message.find("pixel buffer"), std::string::npos) << message;
    }
    Image dup(1, 1, {"R", "G", "R"});
    EXPECT_THROW(writeExr(path, dup, {}), OutputError);
    Image empty;
    EXPECT_THROW(writeExr(path, empty, {}), OutputError);

    EXPECT_EQ(dir.list(), std::vector<std::string>{"frame.exr"});
    EXPECT_EQ(readBytes(path), good);
}

TEST(ExrWriter, ReplacesExistingFileCompletely) {
    TempDir dir("fluence_exr_test");
    const std::string path = dir.file("frame.exr");
    {
        std::ofstream out(path, std::ios::binary);
        out << std::string(1 << 20, 'x');  // a large non-EXR file: no trailing garbage may remain
    }
    Image image(3, 2, {"R", "G", "B"});
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<float>(i);
    writeExr(path, image);
    EXPECT_EQ(dir.list(), std::vector<std::string>{"frame.exr"});
    EXPECT_LT(fs::file_size(path), 1u << 20);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    std::vector<float> pixels(image.pixels.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data()));
    EXPECT_EQ(pixels, image.pixels);
}

}  // namespace
