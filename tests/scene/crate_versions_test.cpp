// Old crate versions and the empty crate (issue #21): OpenUSD's own crate 0.0.1 test layers read
// into the layers their text twins parse to, a 0.0.1 particle cache's arrays and time samples
// decode consistently, and tinyusdz's empty crate opens as an empty stage
// (tests/scene/data/crate/README.md says where each file comes from).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/crate_reader.h"
#include "scene/layer_file.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "scene/usda_writer.h"
#include "tests/support/crate_writer.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

const fs::path kData = FLUENCE_SOURCE_DIR "/tests/scene/data/crate";
const fs::path kVersion001 = kData / "v0.0.1";

std::vector<char> fileBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

std::string versionOf(const fs::path& path) {
    std::vector<char> bytes = fileBytes(path);
    if (bytes.size() < 11) return "";
    return std::to_string(bytes[8]) + "." + std::to_string(bytes[9]) + "." + std::to_string(bytes[10]);
}

// Crate 0.0.1 (padded spec records and path headers, plain structural sections, ranked arrays
// with 32-bit sizes) reads into the layer its text twin parses to: nested defs and overs with
// siblings at every depth (the path tree's sibling offsets), typed attributes, a typed prim.
TEST(CrateVersions, Version001LayersMatchTheirTextTwins) {
    for (auto [crate, text] : {std::pair{"testHasDefiningSpecifier.usdc", "testHasDefiningSpecifier.usda"},
                               std::pair{"test.usdc", "test.usda"}, std::pair{"crate.usd", "ascii.usd"}}) {
        SCOPED_TRACE(crate);
        ASSERT_EQ(versionOf(kVersion001 / crate), "0.0.1");
        std::unique_ptr<Layer> fromCrate = readLayerFile((kVersion001 / crate).string());
        std::unique_ptr<Layer> fromText = parseUsdaFile((kVersion001 / text).string());
        EXPECT_FALSE(fromCrate->rootPrims.empty());
        EXPECT_EQ(writeUsda(*fromCrate), writeUsda(*fromText));
    }
}

// A crate 0.0.1 particle cache: every array at the one time sample has one element per particle,
// the ids are distinct, and the authored extent is the points' bounding box grown by one margin
// on all six sides (0.05, as the exporter wrote it), so the float data decodes where it lies.
TEST(CrateVersions, Version001ArraysAndTimeSamples) {
    const fs::path path = kVersion001 / "Particles_Splash.101.usd";
    ASSERT_EQ(versionOf(path), "0.0.1");
    std::unique_ptr<Layer> layer = readLayerFile(path.string());
    const PrimSpec* points = layer->primAtPath("/World/fx/Particles_Splash/points");
    ASSERT_NE(points, nullptr);
    EXPECT_EQ(points->typeName, "Points");
    auto sampleAt101 = [&](const char* name) -> const Value& {
        const AttributeSpec* attribute = points->attribute(name);
        EXPECT_NE(attribute, nullptr) << name;
        static const Value none;
        if (!attribute || attribute->timeSamples.size() != 1) return none;
        EXPECT_EQ(attribute->timeSamples[0].first, 101.0) << name;
        return attribute->timeSamples[0].second;
    };
    const Value& positions = sampleAt101("points");
    const Value& ids = sampleAt101("primvars:id");
    const Value& extent = sampleAt101("extent");
    EXPECT_EQ(positions.typeName, "point3f[]");
    EXPECT_EQ(ids.typeName, "int[]");
    const std::size_t particles = positions.size();
    EXPECT_GT(particles, 500u);
    EXPECT_EQ(ids.size(), particles);
    EXPECT_EQ(sampleAt101("velocities").size(), particles);
    EXPECT_EQ(sampleAt101("widths").size(), particles);
    std::vector<double> sortedIds(ids.numbers.begin(), ids.numbers.end());
    std::sort(sortedIds.begin(), sortedIds.end());
    EXPECT_EQ(std::adjacent_find(sortedIds.begin(), sortedIds.end()), sortedIds.end());
    ASSERT_EQ(extent.numbers.size(), 6u);
    for (int axis = 0; axis < 3; ++axis) {
        double low = positions.numbers[axis], high = low;
        for (std::size_t i = 0; i < particles; ++i) {
            low = std::min(low, positions.numbers[i * 3 + axis]);
            high = std::max(high, positions.numbers[i * 3 + axis]);
        }
        EXPECT_NEAR(low - extent.numbers[axis], 0.05, 1e-4) << axis;
        EXPECT_NEAR(extent.numbers[3 + axis] - high, 0.05, 1e-4) << axis;
    }
    const AttributeSpec* order = points->attribute("xformOpOrder");
    ASSERT_NE(order, nullptr);
    EXPECT_TRUE(order->uniform);
    EXPECT_EQ(order->defaultValue.strings, std::vector<std::string>{"xformOp:transform"});
}

// Two root prims, a prim with two children (so the path tree has a header with both a child and
// a sibling), properties (the path tree's property bit), arrays, a token array and time samples.
std::vector<char> sceneInCrateVersion(detail::CrateVersion version) {
    namespace T = detail::crate_type;
    using ST = detail::CrateSpecType;
    test::CrateWriter w(version);
    auto specifier = [](std::uint32_t s) { return test::CrateWriter::inlined(T::Specifier, s); };  // def, over, class
    w.spec("/", ST::PseudoRoot,
           {{"defaultPrim", w.tokenValue("World")}, {"primChildren", w.tokenVector({"World", "Other"})}});
    w.spec("/World", ST::Prim,
           {{"specifier", specifier(0)},
            {"typeName", w.tokenValue("Xform")},
            {"primChildren", w.tokenVector({"Mesh", "Sibling"})}});
    w.spec("/World/Mesh", ST::Prim,
           {{"specifier", specifier(0)},
            {"typeName", w.tokenValue("Mesh")},
            {"properties", w.tokenVector({"points", "faceVertexCounts", "tags"})}});
    w.spec("/World/Mesh.points", ST::Attribute,
           {{"typeName", w.tokenValue("point3f[]")},
            {"default", w.array(T::Vec3f, std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5f, -2, 8}, 4)}});
    std::vector<test::CrateWriter::Rep> counts = {w.array(T::Int, std::vector<std::int32_t>{3}, 1),
                                                  w.array(T::Int, std::vector<std::int32_t>{4}, 1)};
    w.spec("/World/Mesh.faceVertexCounts", ST::Attribute,
           {{"typeName", w.tokenValue("int[]")}, {"timeSamples", w.timeSamples({1.0, 24.0}, counts)}});
    w.spec("/World/Mesh.tags", ST::Attribute,
           {{"typeName", w.tokenValue("token[]")}, {"default", w.tokenArray({"a", "b"})}});
    w.spec("/World/Sibling", ST::Prim, {{"specifier", specifier(1)}});
    w.spec("/Other", ST::Prim, {{"specifier", specifier(2)}, {"typeName", w.tokenValue("Scope")}});
    return w.finish();
}

TEST(CrateVersions, EveryLayoutFromTheSpecificationReadsTheSame) {
    const std::string expected = writeUsda(*readCrateBytes(sceneInCrateVersion({0, 8, 0}), "v080.usdc"));
    for (const char* text : {"def Xform \"World\"", "over \"Sibling\"", "class Scope \"Other\"",
                             "point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0.5, -2, 8)]", "1: [3],",
                             "24: [4],", "token[] tags = [\"a\", \"b\"]"})
        EXPECT_NE(expected.find(text), std::string::npos) << text << " not in\n" << expected;
    for (detail::CrateVersion version : std::vector<detail::CrateVersion>{
             {0, 0, 1}, {0, 1, 0}, {0, 2, 0}, {0, 3, 0}, {0, 4, 0}, {0, 5, 0}, {0, 6, 0}, {0, 7, 0}}) {
        SCOPED_TRACE(version.str());
        std::vector<char> bytes = sceneInCrateVersion(version);
        ASSERT_EQ(bytes[9], version.minor);
        EXPECT_EQ(writeUsda(*readCrateBytes(bytes, "old.usdc")), expected);
    }
}

// tinyusdz's empty crate (0.8.0: only the pseudo-root, and a FIELDS section of zero integers,
// which OpenUSD encodes as no bytes at all) opens as an empty stage.
TEST(CrateVersions, EmptyCrateOpensAsAnEmptyStage) {
    const std::string path = (kData / "empty-000.usdc").string();
    std::unique_ptr<Layer> layer = readLayerFile(path);
    EXPECT_TRUE(layer->rootPrims.empty());
    EXPECT_TRUE(layer->metadata.empty());
    std::unique_ptr<Stage> stage = Stage::open(path);
    int prims = 0;
    stage->traverse([&](const PrimSpec&) { return ++prims, true; });
    EXPECT_EQ(prims, 0);
}

// Versions outside 0.0.1 to 0.11.x are refused with the version and the file named.
TEST(CrateVersions, UnknownVersionsAreRefusedNamingTheVersion) {
    std::vector<char> good = fileBytes(kVersion001 / "test.usdc");
    for (auto [major, minor, patch] : {std::tuple{0, 0, 0}, std::tuple{0, 12, 0}, std::tuple{1, 0, 0}}) {
        std::vector<char> bytes = good;
        bytes[8] = static_cast<char>(major), bytes[9] = static_cast<char>(minor), bytes[10] = static_cast<char>(patch);
        const std::string version = std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
        try {
            readCrateBytes(bytes, "future.usdc");
            ADD_FAILURE() << version << " was read";
        } catch (const FileError& error) {
            EXPECT_NE(std::string(error.what()).find("future.usdc"), std::string::npos) << error.what();
            EXPECT_NE(std::string(error.what()).find("crate version " + version), std::string::npos) << error.what();
        }
    }
}

}  // namespace
}  // namespace fluence::usd
