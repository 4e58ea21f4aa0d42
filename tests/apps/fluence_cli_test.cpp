// End-to-end tests: run the `fluence` binary on USD files and read back what it writes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::ExrImage;
using test::readExr;
using test::RunResult;

class FluenceCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_cli"};
    const fs::path dir_ = tmp_.path();

    fs::path write(const std::string& name, const std::string& text) {
        fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p;
    }
    RunResult run(const std::string& args) { return test::runFluence(args, dir_); }
};

// Mean of the named channels over the pixels `select` accepts, with its standard error (pixels
// are independent estimates).
test::MeanEstimate channelMean(const ExrImage& img, std::initializer_list<const char*> channels,
                               const std::function<bool(int, int)>& select) {
    test::MeanEstimate e;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (select(x, y))
                for (const char* c : channels) e.add(img.at(x, y, c));
    return e;
}

TEST_F(FluenceCli, WhiteFurnaceSphereVanishes) {
    fs::path scene = write("furnace.usda", test::furnaceUsda(1.0));
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "f.exr").string() + " -r 48 48 --spp 16");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    test::MeanEstimate e = channelMean(readExr(dir_ / "f.exr"), {"R", "G", "B"}, [](int, int) { return true; });
    EXPECT_NEAR(e.mean(), 1.0, 0.01) << "image mean";
    EXPECT_NEAR(e.mean(), 1.0, 5 * e.standardError() + 1e-6) << "within 5 standard errors";
}

TEST_F(FluenceCli, FurnaceSphereOfAlbedoHalfAveragesHalf) {
    fs::path scene = write("furnace.usda", test::furnaceUsda(0.5));
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "f.exr").string() + " -r 48 48 --spp 16");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ExrImage img = readExr(dir_ / "f.exr");
    test::MeanEstimate e = channelMean(img, {"G"}, [&](int x, int y) { return img.at(x, y, "A") == 1.0f; });
    ASSERT_GT(e.count(), 500);
    EXPECT_NEAR(e.mean(), 0.5, 5 * e.standardError() + 1e-6);
    EXPECT_NEAR(e.mean(), 0.5, 0.005);
}

// Native instances and a PointInstancer render as the same scene with every instance a copy.
TEST_F(FluenceCli, InstancedSceneRendersAsItsFlattenedCopy) {
    const std::string instanced = R"(#usda 1.0
def Camera "Cam"
{
    double3 xformOp:translate = (0, 0.5, 6)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def DomeLight "Sky"
{
}
class Xform "_Prop"
{
    def Sphere "Ball"
    {
        double radius = 0.5
        color3f[] primvars:displayColor = [(0.9, 0.3, 0.2)]
    }
    def Cube "Plinth"
    {
        double size = 0.6
        double3 xformOp:translate = (0, -0.7, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
def Xform "Left" (
    instanceable = true
    references = </_Prop>
)
{
    double3 xformOp:translate = (-1.2, 0, 0)
    double3 xformOp:rotateXYZ = (0, 40, 10)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
}
def Xform "Right" (
    instanceable = true
    references = </_Prop>
)
{
    double3 xformOp:translate = (1.2, 0, 0)
    double3 xformOp:scale = (-1, 1.3, 1)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
}
def PointInstancer "Pebbles"
{
    int[] protoIndices = [0, 0, 0]
    point3f[] positions = [(-0.6, 1.4, 0), (0, 1.5, 0.3), (0.6, 1.4, 0)]
    quath[] orientations = [(1, 0, 0, 0), (0.92388, 0.38268, 0, 0), (0.7071, 0, 0.7071, 0)]
    float3[] scales = [(1, 1, 1), (1.5, 0.5, 1), (0.7, 0.7, 0.7)]
    rel prototypes = </Pebbles/Cube>
    def Cube "Cube"
    {
        double size = 0.4
    }
}
)";
    // The same placements written out: the instances as plain references, the PointInstancer
    // as three transformed cubes (position * orientation * scale).
    std::string flattened = instanced;
    for (std::size_t at; (at = flattened.find("    instanceable = true\n")) != std::string::npos;)
        flattened.erase(at, std::strlen("    instanceable = true\n"));
    flattened = flattened.substr(0, flattened.find("def PointInstancer")) + R"(
def Cube "P0"
{
    double size = 0.4
    double3 xformOp:translate = (-0.6, 1.4, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Cube "P1"
{
    double size = 0.4
    double3 xformOp:translate = (0, 1.5, 0.3)
    double3 xformOp:rotateXYZ = (45, 0, 0)
    double3 xformOp:scale = (1.5, 0.5, 1)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ", "xformOp:scale"]
}
def Cube "P2"
{
    double size = 0.4
    double3 xformOp:translate = (0.6, 1.4, 0)
    double3 xformOp:rotateXYZ = (0, 90, 0)
    double3 xformOp:scale = (0.7, 0.7, 0.7)
    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ", "xformOp:scale"]
}
)";
    RunResult a = run("render " + write("instanced.usda", instanced).string() + " -o " + (dir_ / "a.exr").string() +
                      " -r 64 48 --spp 16 --seed 1");
    RunResult b = run("render " + write("flattened.usda", flattened).string() + " -o " + (dir_ / "b.exr").string() +
                      " -r 64 48 --spp 16 --seed 2");
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_NE(a.out.find("instancing   5 instances"), std::string::npos) << a.out;
    EXPECT_EQ(b.out.find("instancing"), std::string::npos) << b.out;

    // Independent seeds: per-pixel differences are noise of mean zero unless the scenes differ.
    ExrImage one = readExr(dir_ / "a.exr"), two = readExr(dir_ / "b.exr");
    test::MeanEstimate difference, coverage;
    for (int y = 0; y < one.height; ++y)
        for (int x = 0; x < one.width; ++x) {
            for (const char* c : {"R", "G", "B"}) difference.add(one.at(x, y, c) - two.at(x, y, c));
            coverage.add(one.at(x, y, "A") - two.at(x, y, "A"));
        }
    EXPECT_NEAR(difference.mean(), 0.0, 5 * difference.standardError());
    EXPECT_NEAR(coverage.mean(), 0.0, 5 * coverage.standardError()) << "silhouettes (alpha) must match";
}

// The sample scenes a user renders first: each renders a finite, non-black image without a warning.
TEST_F(FluenceCli, EverySampleSceneRendersCleanly) {
    const std::vector<std::pair<std::string, std::string>> samples = {
        {"cornell_box.usda", ""},
        {"layered_room/shot.usda", ""},
        {"instancing/garden.usda", ""},
        {"subdivision/creased_cubes.usda", ""},
        {"material_ball/material_ball.usda", ""},
        {"material_ball/material_ball.usda", " --variant /World:shading=standardSurface"},
        {"material_ball/furnace.usda", ""},
        {"lights/rect_texture.usda", ""},
        {"lights/disk.usda", ""},
        {"lights/sphere.usda", ""},
        {"lights/sphere_point.usda", ""},
        {"lights/cylinder.usda", ""},
        {"lights/distant.usda", ""},
        {"lights/dome.usda", ""},
        {"lights/emissive_mesh.usda", ""},
        {"lights/spotlight.usda", ""},
        {"lights/color_temperature.usda", ""},
        {"smoke/smoke.usda", ""},
        {"subsurface/subsurface.usda", ""},
    };
    for (const auto& [sample, options] : samples) {
        fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples" / sample;
        fs::path out = dir_ / "sample.exr";
        RunResult r = run("render " + scene.string() + " -o " + out.string() + " -r 48 32 --spp 4" + options);
        ASSERT_EQ(r.exitCode, 0) << sample << "\n" << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << sample << "\n" << r.err;
        test::MeanEstimate e = channelMean(readExr(out), {"R", "G", "B"}, [](int, int) { return true; });
        EXPECT_TRUE(std::isfinite(e.mean()) && e.mean() > 0.0) << sample;
    }
}

TEST_F(FluenceCli, SameSeedGivesBitIdenticalImagesAtAnyThreadCount) {
    // Surfaces only, and media: volumes, subsurface walks and interiors draw every number from the
    // sample's own stream too; under either sampler.
    for (const char* sampler : {"sobol", "independent"})
        for (const char* sample : {"usd_samples/cornell_box.usda", "usd_samples/subsurface/subsurface.usda"}) {
            const std::string render = "render " + (fs::path(FLUENCE_SOURCE_DIR) / sample).string() +
                                       " -r 40 40 --spp 4 --seed 7 --sampler " + sampler + " -o ";
            ASSERT_EQ(run(render + (dir_ / "one.exr").string() + " -j 1").exitCode, 0);
            ASSERT_EQ(run(render + (dir_ / "two.exr").string() + " -j 2").exitCode, 0);
            ExrImage one = readExr(dir_ / "one.exr"), two = readExr(dir_ / "two.exr");
            ASSERT_EQ(one.pixels.size(), two.pixels.size()) << sample;
            EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)))
                << sample << " " << sampler;
        }
}

TEST_F(FluenceCli, CornellBoxWritesBeautyAndAovsWithColourMetadata) {
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "c.exr").string() + " --preview " +
                      (dir_ / "c.png").string() + " -r 64 64 --spp 8");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("64 x 64, 8 spp"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
    ExrImage img = readExr(dir_ / "c.exr");
    for (const char* c :
         {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z", "sampleCount"})
        EXPECT_GE(img.channel(c), 0) << c;
    for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v));
    EXPECT_EQ(img.spec.get_string_attribute("colorSpace"), "lin_rec709");
    const OIIO::ParamValue* chroma = img.spec.find_attribute("chromaticities");
    ASSERT_NE(chroma, nullptr);
    const float* xy = static_cast<const float*>(chroma->data());
    EXPECT_FLOAT_EQ(xy[0], 0.64f);
    EXPECT_FLOAT_EQ(xy[7], 0.329f);
    EXPECT_FLOAT_EQ(img.at(32, 32, "sampleCount"), 8.0f);
    // The light, seen directly at the top centre of the frame, reads its radiance (17, 12, 4).
    float maxR = 0;
    for (int x = 0; x < 64; ++x)
        for (int y = 0; y < 16; ++y) maxR = std::max(maxR, img.at(x, y, "R"));
    EXPECT_FLOAT_EQ(maxR, 17.0f);
    EXPECT_TRUE(fs::exists(dir_ / "c.png"));
}

TEST_F(FluenceCli, ProgressForFarmsWhenNotATerminal) {
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "c.exr").string() + " -r 16 16 --spp 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("ALF_PROGRESS 100%"), std::string::npos) << r.out;
}

TEST_F(FluenceCli, TimeLimitStopsBetweenPassesWithEqualSamplesEverywhere) {
    // A sample count that would take hours, cut short by a one-second limit: the render ends,
    // and every pixel holds the same number of samples.
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "t.exr").string() +
                      " -r 32 32 --spp 100000000 --time-limit 1");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    ExrImage img = readExr(dir_ / "t.exr");
    float count = img.at(0, 0, "sampleCount");
    EXPECT_GE(count, 1.0f);
    EXPECT_LT(count, 100000000.0f);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) ASSERT_EQ(img.at(x, y, "sampleCount"), count);
    EXPECT_NE(r.out.find(std::to_string(int(count)) + " spp"), std::string::npos) << r.out;
}

TEST_F(FluenceCli, MissingSceneFileExitsWithMissingInput) {
    RunResult r = run("render " + (dir_ / "nope.usda").string() + " -o " + (dir_ / "x.exr").string());
    EXPECT_EQ(r.exitCode, 4);
    EXPECT_NE(r.err.find("scene file not found"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
}

TEST_F(FluenceCli, SyntaxErrorReportsFileLineAndColumn) {
    fs::path scene =
        write("bad.usda", "#usda 1.0\n\ndef Xform \"World\"\n{\n    double3 xformOp:translate = (1, 2\n}\n");
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "x.exr").string());
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find(scene.string() + ":6:1"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
}

TEST_F(FluenceCli, MissingCameraIsASceneError) {
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "x.exr").string() + " -c /NoSuchCamera");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("camera /NoSuchCamera does not exist"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
}

TEST_F(FluenceCli, AMissingVdbFileIsAMissingInputNamingThePrimAndFile) {
    fs::path scene =
        write("smoke.usda",
              "#usda 1.0\ndef Camera \"Cam\"\n{\n}\ndef Volume \"Smoke\"\n{\n"
              "    rel field:density = </Smoke/Density>\n"
              "    def OpenVDBAsset \"Density\"\n    {\n"
              "        asset filePath = @./nowhere.vdb@\n        token fieldName = \"density\"\n    }\n}\n");
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "x.exr").string() + " --spp 1 -r 8 8");
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("/Smoke/Density.filePath: missing asset"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nowhere.vdb"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.exr"));
}

TEST_F(FluenceCli, AStageWithoutACameraIsFramedByADefaultOne) {
    fs::path noCamera = write("nocam.usda", "#usda 1.0\ndef Xform \"World\"\n{\n}\n");
    RunResult r = run("render " + noCamera.string() + " -o " + (dir_ / "x.exr").string() + " --spp 1 -r 8 8");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("the stage has no camera; framing the whole scene"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "x.exr"));
}

// A malformed prim is an error under --strict (without it: tests/apps/production_scenes_cli_test.cpp).
TEST_F(FluenceCli, SemanticErrorNamesThePrim) {
    fs::path scene =
        write("badmesh.usda",
              "#usda 1.0\ndef Mesh \"Tri\"\n{\n    int[] faceVertexCounts = [3]\n"
              "    int[] faceVertexIndices = [0, 1, 7]\n    point3f[] points = [(0,0,0), (1,0,0), (0,1,0)]\n}\n"
              "def Camera \"Cam\"\n{\n}\n");
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "x.exr").string() + " --strict");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("/Tri"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("faceVertexIndices[2] = 7"), std::string::npos) << r.err;
}

// `fluence info` lists the malformed prims a render leaves out; with --strict it exits 3, as
// `render --strict` would, and without it 0.
TEST_F(FluenceCli, InfoListsMalformedPrimsAndStrictRefusesThem) {
    fs::path scene =
        write("malformed.usda",
              "#usda 1.0\ndef Mesh \"Tri\"\n{\n    int[] faceVertexCounts = [3]\n"
              "    int[] faceVertexIndices = [0, 1, 7]\n    point3f[] points = [(0,0,0), (1,0,0), (0,1,0)]\n}\n"
              "def Xform \"Rig\"\n{\n    int visibility = 3\n}\n"
              "def Camera \"Cam\"\n{\n    string focalLength = \"long\"\n}\n");
    RunResult r = run("info " + scene.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("malformed prims (3)\n  /Cam  "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n  /Rig  " + scene.string() + ":"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n  /Tri  " + scene.string() + ":"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("faceVertexIndices[2] = 7"), std::string::npos) << r.out;
    r = run("info " + scene.string() + " --strict");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.out.find("malformed prims (3)"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("3 malformed prims"), std::string::npos) << r.err;
    write("fine.usda", "#usda 1.0\ndef Camera \"Cam\"\n{\n}\n");
    EXPECT_EQ(run("info " + (dir_ / "fine.usda").string() + " --strict").exitCode, 0);
}

TEST_F(FluenceCli, UnwritableOutputFailsAndLeavesNothing) {
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "no/such/dir/x.exr").string() + " -r 8 8 --spp 1");
    EXPECT_EQ(r.exitCode, 5);
    EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
}

TEST_F(FluenceCli, UsageErrors) {
    EXPECT_EQ(run("render").exitCode, 2);
    RunResult r = run("render scene.usda --bogus");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown option '--bogus'"), std::string::npos);
    r = run("render scene.usda --integrator nope");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("available: path"), std::string::npos) << r.err;
    EXPECT_EQ(run("render scene.usda --spp zero").exitCode, 2);
    EXPECT_EQ(run("render scene.usda --target-error -0.1").exitCode, 2);
    EXPECT_EQ(run("render scene.usda --min-spp 1").exitCode, 2);
    r = run("render scene.usda --subsurface dipole");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("randomwalk, randomwalk_guided or diffusion"), std::string::npos) << r.err;
    EXPECT_EQ(run("frobnicate").exitCode, 2);
}

TEST_F(FluenceCli, AutomaticIntegratorSaysWhichAndWhy) {
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r =
        run("render " + scene.string() + " -o " + (dir_ / "auto.exr").string() + " -r 16 16 --spp 1 --integrator auto");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("integrator auto: path, the cheapest method that covers"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("integrator path"), std::string::npos) << r.out;
}

TEST_F(FluenceCli, TargetErrorSamplesAdaptivelyAndSaysSo) {
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda";
    RunResult r = run("render " + scene.string() + " -o " + (dir_ / "adaptive.exr").string() +
                      " -r 24 24 --spp 64 --min-spp 4 --target-error 0.05");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("adaptive     target error 0.05"), std::string::npos) << r.out;
    ExrImage image = readExr(dir_ / "adaptive.exr");
    test::MeanEstimate counts = channelMean(image, {"sampleCount"}, [](int, int) { return true; });
    EXPECT_GE(counts.mean(), 4.0);
    EXPECT_LT(counts.mean(), 64.0) << "the light's pixels, noiseless, stop at the minimum";
}

TEST_F(FluenceCli, SubsurfaceOptionOverridesEveryMaterialsMethod) {
    // The sample's materials name no method, so they take the guided walk: --subsurface
    // randomwalk_guided changes nothing, the classic walk or diffusion changes the subsurface
    // objects' pixels.
    fs::path scene = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/subsurface/subsurface.usda";
    auto render = [&](const std::string& name, const std::string& options) {
        EXPECT_EQ(
            run("render " + scene.string() + " -o " + (dir_ / name).string() + " -r 32 24 --spp 2" + options).exitCode,
            0);
        return readExr(dir_ / name);
    };
    ExrImage byDefault = render("default.exr", ""), walked = render("walk.exr", " --subsurface randomwalk"),
             diffused = render("diffusion.exr", " --subsurface diffusion"),
             guided = render("guided.exr", " --subsurface randomwalk_guided");
    ASSERT_EQ(byDefault.pixels.size(), guided.pixels.size());
    EXPECT_EQ(0, std::memcmp(byDefault.pixels.data(), guided.pixels.data(), byDefault.pixels.size() * sizeof(float)));
    ASSERT_EQ(byDefault.pixels.size(), diffused.pixels.size());
    EXPECT_NE(0, std::memcmp(byDefault.pixels.data(), diffused.pixels.data(), byDefault.pixels.size() * sizeof(float)));
    ASSERT_EQ(byDefault.pixels.size(), walked.pixels.size());
    EXPECT_NE(0, std::memcmp(byDefault.pixels.data(), walked.pixels.data(), byDefault.pixels.size() * sizeof(float)));
}

TEST_F(FluenceCli, HelpAndVersion) {
    RunResult help = run("--help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("usage: fluence render"), std::string::npos);
    EXPECT_NE(help.out.find("exit codes"), std::string::npos);
    RunResult version = run("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.out.rfind("fluence ", 0), 0u);
}

// Payload load rules from the command line: --no-payloads, --load and --unload decide which
// payloads `info` composes (marking the prims left unloaded) and `render` draws.
TEST_F(FluenceCli, PayloadLoadRules) {
    write("ball.usda",
          "#usda 1.0\n(\n    defaultPrim = \"Ball\"\n)\n\ndef Xform \"Ball\"\n{\n"
          "    def Sphere \"Geom\"\n    {\n        double radius = 0.8\n    }\n}\n");
    fs::path scene = write("payloads.usda", R"(#usda 1.0
def Camera "Cam"
{
    double3 xformOp:translate = (0, 0, 10)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def DomeLight "Sky"
{
}
def Xform "World"
{
    def "Left" (
        payload = @./ball.usda@
    )
    {
        double3 xformOp:translate = (-1.2, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def "Right" (
        payload = @./ball.usda@
    )
    {
        double3 xformOp:translate = (1.2, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
)");
    auto info = [&](const std::string& flags) {
        RunResult r = run("info " + scene.string() + flags);
        EXPECT_EQ(r.exitCode, 0) << flags << "\n" << r.err;
        return r.out;
    };
    const std::string unloaded = "  (payload not loaded)";
    std::string all = info("");
    EXPECT_NE(all.find("Left  Xform\n"), std::string::npos) << all;
    EXPECT_NE(all.find("Geom  Sphere"), std::string::npos) << all;
    EXPECT_EQ(all.find(unloaded), std::string::npos) << all;
    std::string none = info(" --no-payloads");
    EXPECT_NE(none.find("Left" + unloaded + "\n"), std::string::npos) << none;
    EXPECT_NE(none.find("Right" + unloaded + "\n"), std::string::npos) << none;
    EXPECT_EQ(none.find("ball.usda"), std::string::npos) << none;  // not even read
    std::string one = info(" --load /World/Right --no-payloads");  // the nearest rule wins, in any order
    EXPECT_NE(one.find("Left" + unloaded + "\n"), std::string::npos) << one;
    EXPECT_NE(one.find("Right  Xform\n"), std::string::npos) << one;
    std::string left = info(" --unload /World/Left");
    EXPECT_NE(left.find("Left" + unloaded + "\n"), std::string::npos) << left;
    EXPECT_NE(left.find("Right  Xform\n"), std::string::npos) << left;

    // Rendered: with Left unloaded, nothing covers the left half of the frame.
    auto coverage = [&](const std::string& flags, bool leftHalf) {
        fs::path out = dir_ / "payloads.exr";
        RunResult r = run("render " + scene.string() + " -o " + out.string() + " -r 64 48 --spp 2" + flags);
        EXPECT_EQ(r.exitCode, 0) << flags << "\n" << r.err;
        ExrImage img = readExr(out);
        return channelMean(img, {"A"}, [&](int x, int) { return (x < img.width / 2) == leftHalf; }).mean();
    };
    EXPECT_GT(coverage("", true), 0.05);
    EXPECT_EQ(coverage(" --unload /World/Left", true), 0.0);
    EXPECT_GT(coverage(" --unload /World/Left", false), 0.05);

    RunResult bad = run("render " + scene.string() + " --load World");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--load needs an absolute prim path"), std::string::npos) << bad.err;
    RunResult help = run("--help");
    for (const char* flag : {"--load PATH", "--unload PATH", "--no-payloads"})
        EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

}  // namespace
}  // namespace fluence
