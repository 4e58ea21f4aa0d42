// The USDA reader on the real-world corpus in shared/usd_corpus (skipped when it is absent):
// every text layer parses, OpenUSD's invalid test layers are rejected, binary crate files are not
// taken for text (scene/crate_reader.h reads them), and a few parsed values are spot-checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "scene/usda_parser.h"
#include "tests/support/shared_data.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = test::sharedPath("usd_corpus");

enum class Format { Text, Crate, Other };

Format formatOf(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    char magic[8] = {};
    file.read(magic, sizeof magic);
    std::string start(magic, static_cast<std::size_t>(file.gcount()));
    if (start.rfind("PXR-USDC", 0) == 0) return Format::Crate;
    if (start.rfind("#usda", 0) == 0 || start.rfind("#sdf", 0) == 0) return Format::Text;
    return Format::Other;
}

// Every .usda, .sdf, .usd and .usdc file of the corpus, sorted.
std::vector<fs::path> layerFiles() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
        std::string extension = entry.path().extension().string();
        if (extension == ".usda" || extension == ".sdf" || extension == ".usd" || extension == ".usdc") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// OpenUSD's own rule for its parser tests: a file with "_bad_" in its name must fail to load.
// usdview's invalidSyntax.usda misspells a list-op key on purpose.
bool isInvalidOnPurpose(const fs::path& path) {
    std::string name = path.filename().string();
    return name.find("_bad_") != std::string::npos || name == "invalidSyntax.usda";
}

TEST(UsdaCorpus, EveryTextLayerParses) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    int parsed = 0;
    for (const fs::path& path : layerFiles()) {
        if (path.extension() == ".usdc" || isInvalidOnPurpose(path)) continue;
        Format format = formatOf(path);
        if (format == Format::Crate) continue;
        EXPECT_EQ(format, Format::Text) << path;
        try {
            parseUsdaFile(path.string());
            ++parsed;
        } catch (const std::exception& error) {
            ADD_FAILURE() << error.what();
        }
    }
    std::cout << "[ corpus   ] " << parsed << " text layers parsed\n";
    EXPECT_GE(parsed, 120);
}

TEST(UsdaCorpus, InvalidLayersAreRejected) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    int rejected = 0;
    for (const fs::path& path : layerFiles()) {
        if (!isInvalidOnPurpose(path)) continue;
        try {
            parseUsdaFile(path.string());
            ADD_FAILURE() << path << " parsed, but it is invalid";
        } catch (const ParseError& error) {
            EXPECT_EQ(error.location().file, path.string());
            ++rejected;
        }
    }
    std::cout << "[ corpus   ] " << rejected << " invalid layers rejected\n";
    EXPECT_GE(rejected, 100);
}

TEST(UsdaCorpus, CrateFilesAreNotTakenForText) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    int crates = 0;
    for (const fs::path& path : layerFiles()) {
        if (formatOf(path) != Format::Crate) continue;
        ++crates;
        try {
            parseUsdaFile(path.string());
            ADD_FAILURE() << path << " parsed";
        } catch (const ParseError& error) {
            EXPECT_EQ(error.location().line, 1);
            EXPECT_EQ(error.location().column, 1);
            EXPECT_EQ(error.message(), "a binary USD crate file, not USDA text (usd::readLayerFile reads both)");
        }
    }
    EXPECT_GE(crates, 7);  // the Chess Set geometry, corrupt.usd and tinyusdz's .usdc twins
}

TEST(UsdaCorpus, SpotChecks) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    auto pyramids = parseUsdaFile(
        (kCorpus / "usd-wg-assets/full_assets/SubdivisionSurfaces/Creases_SpinningPyramids.usda").string());
    const PrimSpec* pyramid = pyramids->primAtPath("/World/Pyramid_NoCreases");
    ASSERT_NE(pyramid, nullptr);
    const AttributeSpec* spin = pyramid->attribute("xformOp:transform:xform1");
    ASSERT_NE(spin, nullptr);
    EXPECT_EQ(spin->timeSamples.size(), 193u);
    EXPECT_EQ(spin->timeSamples.front().second.components, 16);
    EXPECT_EQ(findMetadata(pyramid->metadata, "instanceable")->value.asDouble(), 1.0);

    auto instancer =
        parseUsdaFile((kCorpus / "OpenUSD/pxr/usd/usdGeom/testenv/testUsdGeomSubset/PointInstancer.usda").string());
    const PrimSpec* sphere = instancer->primAtPath("/Sphere");
    ASSERT_NE(sphere, nullptr);
    EXPECT_EQ(findMetadata(instancer->metadata, "defaultPrim")->value.asString(), "Sphere");

    auto motionBlur = parseUsdaFile(
        (kCorpus / "OpenUSD/pxr/usdImaging/bin/usdrecord/testenv/MotionBlurTest/motionBlur.usda").string());
    const PrimSpec* moving = motionBlur->primAtPath("/World/Moving_GlowSphere");
    ASSERT_NE(moving, nullptr);
    const AttributeSpec* translate = moving->attribute("xformOp:translate");
    ASSERT_NE(translate, nullptr);
    ASSERT_EQ(translate->timeSamples.size(), 2u);
    EXPECT_EQ(translate->timeSamples[0].first, -1.0);
    EXPECT_EQ(translate->timeSamples[0].second.numbers, (std::vector<double>{5, 2, 0}));
}

}  // namespace
}  // namespace fluence::usd
