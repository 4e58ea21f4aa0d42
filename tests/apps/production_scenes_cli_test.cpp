// Production files that used to fail a render: a malformed prim (skipped with a warning, an
// error under --strict), attributes with only time samples read without a frame (the earliest
// sample, as Hydra), and missing assets the renderer never reads (audio, card textures, time
// samples of other frames).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

class ProductionScenesCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"production_scenes_cli"};

    std::string write(const std::string& name, const std::string& usda) {
        const std::string path = tmp_.file(name);
        std::ofstream(path) << usda;
        return path;
    }
    RunResult render(const std::string& scene, const std::string& output, const std::string& args = "") {
        return test::runFluence("render " + scene + " -r 16 16 --spp 2 -o " + tmp_.file(output) + " " + args,
                                tmp_.path());
    }
};

// Two quads whose face counts ask for 8 indices of the 6 given.
const std::string kBadMesh = R"(
def Mesh "Bad"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4, 4]
    int[] faceVertexIndices = [0, 1, 2, 3, 1, 4]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 0, 0)]
}
)";

TEST_F(ProductionScenesCli, AMalformedPrimIsSkippedWithAWarningUnlessStrict) {
    const std::string scene = write("bad_mesh.usda", test::furnaceUsda(0.5) + kBadMesh);
    RunResult r = render(scene, "lenient.exr");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("fluence: warning: /Bad: not rendered: "), std::string::npos) << r.err;
    EXPECT_NE(
        r.err.find("faceVertexCounts add up to 8 but faceVertexIndices has 6 entries (--strict makes this an error)"),
        std::string::npos)
        << r.err;
    EXPECT_TRUE(fs::exists(tmp_.file("lenient.exr")));

    r = render(scene, "strict.exr", "--strict");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("fluence: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/Bad: faceVertexCounts add up to 8"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("strict.exr")));
}

// The furnace camera with only time samples: before, "xformOpOrder names 'xformOp:translate',
// which has no value" failed the render (as in 22 arnold-usd test scenes).
TEST_F(ProductionScenesCli, WithoutAFrameTimeSampledAttributesTakeTheirEarliestSample) {
    std::string usda = test::furnaceUsda(0.5);
    const std::string authored = "double3 xformOp:translate = (0, -4, 0)";
    ASSERT_NE(usda.find(authored), std::string::npos);
    usda.replace(usda.find(authored), authored.size(),
                 "double3 xformOp:translate.timeSamples = { 10: (0, -40, 0), 1: (0, -4, 0) }");
    const std::string scene = write("animated_camera.usda", usda);
    RunResult r = render(scene, "none.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ASSERT_EQ(render(scene, "first.exr", "-f 1").exitCode, 0);
    ASSERT_EQ(render(scene, "last.exr", "-f 10").exitCode, 0);
    const std::vector<float> none = test::readExr(tmp_.file("none.exr")).pixels;
    EXPECT_EQ(none, test::readExr(tmp_.file("first.exr")).pixels) << "the earliest sample, at time 1";
    EXPECT_NE(none, test::readExr(tmp_.file("last.exr")).pixels);
}

TEST_F(ProductionScenesCli, MissingAssetsTheRenderNeverReadsDoNotFailIt) {
    std::string usda = test::furnaceUsda(0.5);
    usda.insert(usda.find("def Xform \"World\"\n{\n") + std::string("def Xform \"World\"\n{\n").size(),
                "    asset model:cardTextureXPos = @./no_such_card.png@\n");
    usda += "def SpatialAudio \"Music\"\n{\n    uniform asset filePath = @./no_such_music.wav@\n}\n";
    usda +=
        "def Xform \"Asset\" (\n    assetInfo = {\n        asset identifier = @./no_such_asset.usd@\n"
        "        asset[] payloadAssetDependencies = [@./no_such_dependency.png@]\n    }\n)\n{\n}\n";
    const std::string scene = write("audio.usda", usda);
    RunResult r = render(scene, "a.exr");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("/World.model:cardTextureXPos: asset not found"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/Music.filePath: asset not found"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("SpatialAudio"), std::string::npos) << "audio is not a prim type to warn about:\n" << r.err;
    EXPECT_EQ(r.err.find("no_such_asset.usd"), std::string::npos) << "assetInfo names the asset; nothing reads it:\n"
                                                                  << r.err;
    EXPECT_EQ(r.err.find("no_such_dependency.png"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(tmp_.file("a.exr")));
}

// The dome's texture is time-sampled: none at 1 and 9, a missing file at 5 (as arnold-usd's
// test_2477 names a missing IES profile at frames other than its reference frame). Only the
// frames rendered decide: each reads the sample held at its time (the earliest without a frame).
TEST_F(ProductionScenesCli, AMissingAssetOnlyOtherFramesReadDoesNotFailTheRender) {
    std::string usda = test::furnaceUsda(0.5);
    const std::string dome = "float inputs:intensity = 1\n";
    ASSERT_NE(usda.find(dome), std::string::npos);
    usda.insert(usda.find(dome) + dome.size(),
                "        asset inputs:texture:file.timeSamples = { 1: @@, 5: @./no_such_sky.exr@, 9: @@ }\n");
    const std::string scene = write("sky_sequence.usda", usda);
    for (const std::string frames : {"", "-f 3", "-f 9", "-f 2 -n 3"}) {
        RunResult r = render(scene, "sky.%04d.exr", frames);
        EXPECT_EQ(r.exitCode, 0) << frames << ":\n" << r.err;
        EXPECT_NE(r.err.find("/World/Dome.inputs:texture:file: asset not found"), std::string::npos) << r.err;
    }
    for (const std::string frames : {"-f 5", "-f 6", "-f 3 -n 3"}) {
        RunResult r = render(scene, "sky.%04d.exr", frames);
        EXPECT_EQ(r.exitCode, 4) << frames << ":\n" << r.err;
        EXPECT_NE(r.err.find("/World/Dome.inputs:texture:file: missing asset"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("no_such_sky.exr"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(tmp_.file("sky.0005.exr")));
}

}  // namespace
}  // namespace fluence
