// `fluence cat` end to end: a layer (text or crate) to stdout or a file, the flattened stage of a
// scene with sublayers, references, a payload, variants and instances composing again to the same
// scene (`fluence info` reports the same prims, instances, lights, materials and assets), and the
// documented exit codes with nothing left behind when the output cannot be written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/usda_parser.h"
#include "scene/usda_writer.h"
#include "tests/support/cli.h"
#include "tests/support/shared_data.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = FLUENCE_SOURCE_DIR "/usd_samples";
const fs::path kCorpus = test::sharedPath("usd_corpus");

// `fluence info` output without what names the files read: the "scene" line and the "layers"
// list, and the reader's notes about Fluence's own composition metadata (fluence:*), which a
// flattened layer carries as authored metadata.
std::string composedReport(const std::string& info) {
    std::istringstream lines(info);
    std::string line, report;
    bool inLayers = false;
    while (std::getline(lines, line)) {
        if (line.starts_with("layers (")) inLayers = true;
        if (inLayers && line.empty()) inLayers = false;
        const bool fluenceMetadataNote = line.find("unregistered metadata field 'fluence:") != std::string::npos;
        const bool warningCount = line.ends_with(" warnings") || line.ends_with(" warning");
        if (inLayers || line.starts_with("scene ") || fluenceMetadataNote || warningCount) continue;
        report += line + "\n";
    }
    return report;
}

class CatCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_cat"};
    const fs::path dir_ = tmp_.path();

    test::RunResult run(const std::string& args) { return test::runFluence(args, dir_); }

    // Flattens `scene` with `stageOptions`, and checks that `fluence info` reports the same scene
    // for the flattened layer as for the original.
    void expectFlattenComposesTheSame(const fs::path& scene, const std::string& stageOptions) {
        const fs::path flat = dir_ / "flat.usda";
        test::RunResult cat = run("cat --flatten " + scene.string() + " " + stageOptions + " -o " + flat.string());
        ASSERT_EQ(cat.exitCode, 0) << cat.err;
        const std::string text = test::slurp(flat);
        for (const char* arc : {"references = ", "payload = ", "subLayers = ", "variantSet \"", "inherits = "})
            EXPECT_EQ(text.find(arc), std::string::npos) << arc << " left in the flattened layer of " << scene;
        test::RunResult original = run("info " + scene.string() + " " + stageOptions);
        ASSERT_EQ(original.exitCode, 0) << original.err;
        test::RunResult flattened = run("info " + flat.string());
        ASSERT_EQ(flattened.exitCode, 0) << flattened.err;
        EXPECT_EQ(composedReport(flattened.out + flattened.err), composedReport(original.out + original.err)) << scene;
    }
};

TEST_F(CatCli, WritesALayerToStdoutAsItIsAuthored) {
    const fs::path shot = kSamples / "layered_room/shot.usda";
    test::RunResult r = run("cat " + shot.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, usd::writeUsda(*usd::parseUsdaFile(shot.string())));
    EXPECT_NE(r.out.find("subLayers = ["), std::string::npos) << "not flattened: the arcs stay";
}

TEST_F(CatCli, WritesACorpusLayerToAFileAtomically) {
    FLUENCE_REQUIRE_SHARED(kCorpus);
    const fs::path teapot = kCorpus / "usd-wg-assets/full_assets/Teapot/Teapot.usd";
    const fs::path out = dir_ / "teapot.usda";
    test::RunResult toFile = run("cat " + teapot.string() + " -o " + out.string());
    ASSERT_EQ(toFile.exitCode, 0) << toFile.err;
    EXPECT_TRUE(toFile.out.empty());
    test::RunResult toStdout = run("cat " + teapot.string());
    ASSERT_EQ(toStdout.exitCode, 0) << toStdout.err;
    EXPECT_EQ(test::slurp(out), toStdout.out);
    EXPECT_EQ(usd::writeUsda(*usd::parseUsdaFile(out.string())), toStdout.out) << "the text reads back the same";
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST_F(CatCli, WritesACrateLayerAsText) {
    const fs::path crate = kCorpus / "usd-wg-assets/full_assets/OpenChessSet/assets/Pawn/Pawn_geom.usd";
    FLUENCE_REQUIRE_SHARED(crate);
    test::RunResult r = run("cat " + crate.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_TRUE(r.out.starts_with("#usda 1.0\n"));
    EXPECT_EQ(usd::writeUsda(*usd::parseUsdaString(r.out, "pawn.usda")), r.out);
}

TEST_F(CatCli, FlattenedSceneComposesToTheSamePrims) {
    expectFlattenComposesTheSame(kSamples / "layered_room/shot.usda", "");
}

TEST_F(CatCli, FlattenAppliesVariantSelectionsAndLoadRules) {
    expectFlattenComposesTheSame(kSamples / "layered_room/shot.usda", "--variant /World/ShortBox:finish=red");
    expectFlattenComposesTheSame(kSamples / "layered_room/shot.usda", "--no-payloads");
}

TEST_F(CatCli, FlattenKeepsNativeInstancesInstanced) {
    expectFlattenComposesTheSame(kSamples / "instancing/garden.usda", "");
    EXPECT_NE(run("info " + (dir_ / "flat.usda").string()).out.find("instance of prototype 1"), std::string::npos);
}

TEST_F(CatCli, MissingFileExits4) {
    test::RunResult r = run("cat " + (dir_ / "missing.usda").string());
    EXPECT_EQ(r.exitCode, 4);
    EXPECT_NE(r.err.find("missing.usda"), std::string::npos) << r.err;
    EXPECT_EQ(run("cat --flatten " + (dir_ / "missing.usda").string()).exitCode, 4);
}

TEST_F(CatCli, SyntaxErrorExits3WithItsPlace) {
    const fs::path bad = dir_ / "bad.usda";
    std::ofstream(bad) << "#usda 1.0\ndef \"A\" {\n    float x = \n}\n";
    test::RunResult r = run("cat " + bad.string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("bad.usda:4:1: expected a value"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
}

TEST_F(CatCli, UnwritableOutputExits5AndLeavesNothing) {
    const fs::path scene = kSamples / "cornell_box.usda";
    const fs::path noFolder = dir_ / "no/such/folder/out.usda";
    test::RunResult r = run("cat " + scene.string() + " -o " + noFolder.string());
    EXPECT_EQ(r.exitCode, 5);
    EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(noFolder));
    EXPECT_FALSE(fs::exists(dir_ / "no"));

    const fs::path folder = dir_ / "a_folder";
    fs::create_directory(folder);
    EXPECT_EQ(run("cat " + scene.string() + " -o " + folder.string()).exitCode, 5);
    EXPECT_TRUE(fs::is_directory(folder));
    EXPECT_TRUE(fs::is_empty(folder));
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST_F(CatCli, UsageErrorsExit2) {
    const std::string scene = (kSamples / "cornell_box.usda").string();
    test::RunResult r = run("cat " + scene + " --variant /A:set=x");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--flatten"), std::string::npos) << r.err;
    EXPECT_EQ(run("cat").exitCode, 2);
    EXPECT_EQ(run("cat " + scene + " -o").exitCode, 2);
    EXPECT_EQ(run("cat " + scene + " --bogus").exitCode, 2);
    EXPECT_EQ(run("cat " + scene + " -s /Render").exitCode, 2);
    EXPECT_EQ(run("cat " + scene + " " + scene).exitCode, 2);
}

}  // namespace
}  // namespace fluence
