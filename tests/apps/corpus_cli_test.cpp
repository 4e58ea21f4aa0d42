// `fluence info` and `fluence render` on the real-world corpus in shared/usd_corpus (skipped when
// it is absent): every valid layer opens, every invalid one is rejected with file:line:column,
// crate files open (and the damaged corrupt.usd is rejected with a clear error), production assets with missing textures fail
// naming them (exit 4) and render to a finite EXR with --allow-missing, and two render as intended: usdrecord's SmallObjectTest (no camera,
// a DomeLight with an HDR file) and the Teapot's Fancy variant (UsdUVTexture maps).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "tests/support/cli.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = test::sharedPath("usd_corpus");

std::string firstBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    char buffer[8] = {};
    in.read(buffer, sizeof buffer);
    return std::string(buffer, std::size_t(in.gcount()));
}

std::vector<fs::path> corpusLayers() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus)) {
        std::string ext = entry.path().extension().string();
        if (ext == ".usda" || ext == ".sdf" || ext == ".usd" || ext == ".usdc") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// OpenUSD's rule for its parser tests: a file with "_bad_" in its name must fail to load;
// usdview's invalidSyntax.usda misspells a list-op key on purpose.
bool invalidOnPurpose(const fs::path& p) {
    std::string name = p.filename().string();
    return name.find("_bad_") != std::string::npos || name == "invalidSyntax.usda";
}

class CorpusCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_corpus"};
    test::RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
};

TEST_F(CorpusCli, InfoOpensEveryValidLayerAndRejectsEveryInvalidOne) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    const std::regex location(":[0-9]+:[0-9]+: ");
    int opened = 0, rejected = 0, crates = 0;
    for (const fs::path& path : corpusLayers()) {
        std::string start = firstBytes(path);
        test::RunResult r = run("info '" + path.string() + "'");
        if (start.rfind("PXR-USDC", 0) == 0 && path.filename() == "corrupt.usd") {
            EXPECT_EQ(r.exitCode, 4) << path;
            EXPECT_NE(r.err.find("damaged or unsupported USD crate file"), std::string::npos) << r.err;
            ++rejected;
        } else if (start.rfind("PXR-USDC", 0) == 0) {
            EXPECT_EQ(r.exitCode, 0) << path << "\n" << r.err;
            EXPECT_NE(r.out.find("\nprims ("), std::string::npos) << path;
            ++crates;
        } else if (invalidOnPurpose(path)) {
            EXPECT_EQ(r.exitCode, 3) << path;
            EXPECT_TRUE(std::regex_search(r.err, location)) << "no file:line:column in: " << r.err;
            ++rejected;
        } else {
            EXPECT_EQ(r.exitCode, 0) << path << "\n" << r.err;
            EXPECT_NE(r.out.find("\nprims ("), std::string::npos) << path;
            ++opened;
        }
    }
    EXPECT_GE(opened, 120);
    EXPECT_GE(rejected, 100);
    EXPECT_GE(crates, 10);
}

TEST_F(CorpusCli, UnregisteredMetadataAndUnknownTypesOpenWithAWarning) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    const fs::path dir = kCorpus / "OpenUSD/pxr/usd/usd/testenv/testUsdFlatten";
    test::RunResult r = run("info '" + (dir / "badMetadata.usd").string() + "'");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find("unregistered metadata field 'noSuchField'"), std::string::npos) << r.err;
    r = run("info '" + (dir / "badPropertyTypeNames.usd").string() + "'");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find("unknown value type 'unknownType'"), std::string::npos) << r.err;
}

void expectFiniteRender(const test::RunResult& r, const fs::path& exr) {
    ASSERT_EQ(r.exitCode, 0) << r.err;
    test::ExrImage img = test::readExr(exr);
    for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v));
}

TEST_F(CorpusCli, SpinningPyramidsRenders) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    fs::path scene = kCorpus / "usd-wg-assets/full_assets/SubdivisionSurfaces/Creases_SpinningPyramids.usda";
    fs::path out = tmp_.path() / "pyramids.exr";
    expectFiniteRender(run("render '" + scene.string() + "' -o '" + out.string() + "' -r 64 64 --spp 2"), out);
}

TEST_F(CorpusCli, StandardShaderBallRefusesItsMissingAssetsUnlessAllowed) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    fs::path scene = kCorpus / "usd-wg-assets/full_assets/StandardShaderBall/standard_shader_ball_scene.usda";
    fs::path out = tmp_.path() / "ball.exr";
    test::RunResult r = run("render '" + scene.string() + "' -o '" + out.string() + "' -r 64 64 --spp 2");
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("wall_back.ACEScg.exr (authored as"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    r = run("render '" + scene.string() + "' -o '" + out.string() + "' -r 64 64 --spp 2 --allow-missing");
    expectFiniteRender(r, out);
    EXPECT_NE(r.err.find("plastic_openpbr.mtlx@ ignored"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("asset not found:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("wall_back.ACEScg.exr"), std::string::npos) << r.err;
}

TEST_F(CorpusCli, SmallObjectTestIsFramedAndLitByItsDome) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    fs::path scene = kCorpus / "OpenUSD/pxr/usdImaging/bin/usdrecord/testenv/SmallObjectTest/test.usda";
    fs::path out = tmp_.path() / "small.exr";
    test::RunResult r = run("render '" + scene.string() + "' -o '" + out.string() + "' -r 48 32 --spp 4");
    expectFiniteRender(r, out);
    EXPECT_NE(r.err.find("the stage has no camera; framing the whole scene"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("not found"), std::string::npos) << "the HDR is found: " << r.err;
    test::ExrImage img = test::readExr(out);
    EXPECT_EQ(img.at(24, 16, "A"), 1.0f) << "the object sits in the middle of the frame";
    EXPECT_EQ(img.at(0, 0, "A"), 0.0f) << "with the environment around it";
    // The blue displayColor object, lit: blue dominates its pixel; the dome is bright around it.
    EXPECT_GT(img.at(24, 16, "B"), img.at(24, 16, "R"));
    EXPECT_GT(img.at(0, 31, "R") + img.at(0, 31, "G") + img.at(0, 31, "B"), 0.1f);
}

TEST_F(CorpusCli, FancyTeapotRendersWithItsTextures) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    const fs::path teapot = kCorpus / "usd-wg-assets/full_assets/Teapot/Teapot.usd";
    const fs::path hdr = kCorpus / "OpenUSD/pxr/usdImaging/bin/usdrecord/testenv/SmallObjectTest/StinsonBeach.hdr";
    fs::path scene = tmp_.path() / "teapot.usda";
    std::ofstream(scene) << "#usda 1.0\n(\n    upAxis = \"Y\"\n    metersPerUnit = 1\n)\n"
                            "def \"Teapot\" (\n    references = @"
                         << teapot.string()
                         << "@\n"
                            "    variants = {\n        string modelVariant = \"Fancy\"\n    }\n)\n{\n}\n"
                            "def Camera \"Cam\"\n{\n    float2 clippingRange = (0.01, 100)\n"
                            "    float horizontalAperture = 36\n    float verticalAperture = 24\n"
                            "    double3 xformOp:translate = (0, 0.12, 0.9)\n"
                            "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n"
                            "def DomeLight \"Sky\"\n{\n    asset inputs:texture:file = @"
                         << hdr.string() << "@\n}\n";
    fs::path out = tmp_.path() / "teapot.exr";
    test::RunResult r =
        run("render '" + scene.string() + "' -o '" + out.string() + "' -r 48 32 --spp 2 --dicing-rate 4");
    expectFiniteRender(r, out);
    EXPECT_EQ(r.err.find(".jpg"), std::string::npos) << "both maps are read, without a warning: " << r.err;
    // The albedo AOV is the diffuse map (a constant colour, the displayColor fallback, or grey
    // would not vary) where the teapot covers the middle of the frame.
    test::ExrImage img = test::readExr(out);
    double sum = 0.0, sumSquares = 0.0;
    int n = 0;
    for (int y = 10; y < 20; ++y)
        for (int x = 19; x < 29; ++x) {
            ASSERT_EQ(img.at(x, y, "A"), 1.0f) << x << ", " << y;
            double g = img.at(x, y, "albedo.G");
            sum += g;
            sumSquares += g * g;
            ++n;
        }
    double mean = sum / n, deviation = std::sqrt(std::max(0.0, sumSquares / n - mean * mean));
    EXPECT_GT(mean, 0.3) << "porcelain is light";
    EXPECT_GT(deviation, 0.01) << "the flowers and trims of the map";
}

}  // namespace
}  // namespace fluence
