// Messages a person can read about a stage: a missing layer named by many prims is one warning
// (or one error) with the count; stage metadata USD would flag is a warning at its line; a layer
// in a format that needs a USD plugin Fluence lacks (Alembic, Draco) is a scene error (exit 3)
// that says which plugin, not a missing input (exit 4); a renderSettingsPrimPath naming no prim is
// a warning (an error under --strict).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

class SceneMessagesCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"scene_messages_cli"};
    const fs::path dir_ = tmp_.path();

    fs::path write(const std::string& name, const std::string& text) {
        fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p;
    }
    test::RunResult run(const std::string& args) { return test::runFluence(args, dir_); }
};

std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// `count` prims, each referencing `asset`.
std::string referencingPrims(int count, const std::string& asset) {
    std::string text = "#usda 1.0\n";
    for (int i = 0; i < count; ++i)
        text += "def Xform \"P" + std::to_string(i) + "\" (\n    references = @" + asset + "@\n)\n{\n}\n";
    return text;
}

TEST_F(SceneMessagesCli, MissingLayerNamedByManyPrimsIsReportedOnceWithTheCount) {
    const fs::path scene = write("many.usda", referencingPrims(548, "./gone.usda") + "def Sphere \"Ball\"\n{\n}\n");
    test::RunResult info = run("info " + scene.string());
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_EQ(occurrences(info.err, "gone.usda"), 2u) << info.err;  // the authored and the resolved path, once
    EXPECT_NE(info.err.find("many.usda:3:5: /P0: reference @./gone.usda@ ignored: cannot find '" +
                            (dir_ / "gone.usda").string() + "' (referenced by 548 prims)"),
              std::string::npos)
        << info.err;

    test::RunResult render =
        run("render " + scene.string() + " -o " + (dir_ / "many.exr").string() + " -r 8 8 --spp 1");
    EXPECT_EQ(render.exitCode, 4) << render.err;
    EXPECT_EQ(occurrences(render.err, "fluence: error:"), 2u) << render.err;
    EXPECT_NE(render.err.find("/P0.references: missing asset " + (dir_ / "gone.usda").string() +
                              " (authored as @./gone.usda@) (and 547 more references to it)"),
              std::string::npos)
        << render.err;
    EXPECT_NE(render.err.find("1 asset is missing"), std::string::npos) << render.err;
}

TEST_F(SceneMessagesCli, SublayersAndPrimsNamingOneMissingLayerAreCountedApart) {
    write("middle.usda", "#usda 1.0\n(\n    subLayers = [@./gone.usda@]\n)\n");
    const fs::path scene = write("mixed.usda", "#usda 1.0\n(\n    subLayers = [@./gone.usda@, @./middle.usda@]\n)\n" +
                                                   referencingPrims(2, "./gone.usda").substr(10));
    test::RunResult info = run("info " + scene.string());
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.err.find("(referenced by 2 prims and 2 layers)"), std::string::npos) << info.err;
}

TEST_F(SceneMessagesCli, StageMetadataUsdWouldFlagIsAWarningAtItsLine) {
    const fs::path scene = write("metadata.usda", R"(#usda 1.0
(
    upAxis = "invalid"
    framesPerSecond = 0
    timeCodesPerSecond = -24
    startTimeCode = 10
    endTimeCode = 1
)
def Sphere "Ball"
{
}
)");
    test::RunResult r = run("info " + scene.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(
        r.err.find("metadata.usda:3:5: upAxis \"invalid\" is neither \"Y\" nor \"Z\"; the stage is taken as Y up"),
        std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("metadata.usda:4:5: framesPerSecond 0 is not a positive number; ignored"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("metadata.usda:5:5: timeCodesPerSecond -24 is not a positive number; ignored"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("metadata.usda:6:5: startTimeCode 10 is after endTimeCode 1"), std::string::npos) << r.err;

    const fs::path good = write("good.usda",
                                "#usda 1.0\n(\n    upAxis = \"Z\"\n    framesPerSecond = 30\n    startTimeCode = 1\n"
                                "    endTimeCode = 1\n)\ndef Sphere \"Ball\"\n{\n}\n");
    r = run("info " + good.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* key : {"upAxis", "framesPerSecond", "TimeCode"})
        EXPECT_EQ(r.err.find(key), std::string::npos) << r.err;
}

TEST_F(SceneMessagesCli, ARenderSettingsPrimPathNamingNoPrimIsAWarningAndTheDefaultsAreUsed) {
    // arnold-usd's test_1868 names settings its layer does not hold: husk warns and renders.
    const fs::path scene = write("settings.usda", R"(#usda 1.0
(
    renderSettingsPrimPath = "/Render/Gone"
)
def Sphere "Ball"
{
}
)");
    const std::string out = " -o " + (dir_ / "settings.exr").string() + " -r 8 8 --spp 1";
    test::RunResult r = run("render " + scene.string() + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(
        occurrences(
            r.err,
            "renderSettingsPrimPath names /Render/Gone, which is not in the scene; rendering with default settings"),
        1u)
        << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "settings.exr"));
    test::RunResult info = run("info " + scene.string());
    EXPECT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.err.find("renderSettingsPrimPath names /Render/Gone"), std::string::npos) << info.err;

    // --strict refuses it, and settings named on the command line must exist.
    fs::remove(dir_ / "settings.exr");
    r = run("render " + scene.string() + out + " --strict");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("the stage's renderSettingsPrimPath names /Render/Gone, which is not in the scene"),
              std::string::npos)
        << r.err;
    r = run("render " + scene.string() + out + " -s /Render/Other");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("render settings /Render/Other do not exist in the scene"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "settings.exr"));
}

TEST_F(SceneMessagesCli, AlembicAndDracoLayersNeedTheirPlugins) {
    std::ofstream(dir_ / "cache.abc") << "Ogawa";  // present: still unreadable without the plugin
    const fs::path scene = write("arcs.usda", referencingPrims(1, "./cache.abc") + R"(def Xform "Compressed" (
    payload = @./mesh.drc@
)
{
}
)");
    test::RunResult render =
        run("render " + scene.string() + " -o " + (dir_ / "arcs.exr").string() + " -r 8 8 --spp 1");
    EXPECT_EQ(render.exitCode, 3) << render.err;
    EXPECT_NE(render.err.find("needs the Alembic plugin"), std::string::npos) << render.err;
    EXPECT_NE(render.err.find("needs the Draco plugin"), std::string::npos) << render.err;
    EXPECT_NE(render.err.find("2 layers need a file format plugin Fluence does not have"), std::string::npos)
        << render.err;
    EXPECT_EQ(render.err.find("missing asset"), std::string::npos) << render.err;

    test::RunResult allowed =
        run("render " + scene.string() + " -o " + (dir_ / "arcs.exr").string() + " -r 8 8 --spp 1 --allow-missing");
    EXPECT_EQ(allowed.exitCode, 0) << allowed.err;
    EXPECT_NE(allowed.err.find("needs the Alembic plugin"), std::string::npos) << allowed.err;

    // The root layer itself.
    test::RunResult root = run("info " + (dir_ / "cache.abc").string());
    EXPECT_EQ(root.exitCode, 3) << root.err;
    EXPECT_NE(root.err.find("cache.abc' needs the Alembic plugin"), std::string::npos) << root.err;
    EXPECT_EQ(run("cat " + (dir_ / "cache.abc").string()).exitCode, 3);
}

}  // namespace
}  // namespace fluence
