// End-to-end tests of the integrators' parameters (apps/integrator_parameters.h): the options and
// the RenderSettings attributes reach the method (its line in the render summary reports them),
// the option wins over the attribute, and a bad value is a usage error (exit 2) or, in the scene,
// a scene error naming the RenderSettings prim (exit 3).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

const std::string kCornellBox = FLUENCE_SOURCE_DIR "/usd_samples/cornell_box.usda";
const std::string kSubsurface = FLUENCE_SOURCE_DIR "/usd_samples/subsurface/subsurface.usda";

class IntegratorParametersCli : public ::testing::Test {
protected:
    test::TempDir dir_;
    test::RunResult render(const std::string& scene, const std::string& args) {
        return test::runFluence(
            "render " + scene + " -o " + (dir_.path() / "out.exr").string() + " -r 16 12 --spp 1 -j 2 " + args,
            dir_.path());
    }
    // The Cornell box with a RenderSettings prim of its own, /Render/Tuned, holding `attributes`.
    std::string tunedScene(const std::string& attributes) {
        const fs::path path = dir_.path() / "tuned.usda";
        std::ofstream(path) << "#usda 1.0\n(\n    subLayers = [@" << kCornellBox
                            << "@]\n    renderSettingsPrimPath = \"/Render/Tuned\"\n)\n"
                               "over Scope \"Render\"\n{\n    def RenderSettings \"Tuned\"\n    {\n"
                               "        rel camera = </CornellBox/Camera>\n"
                            << attributes << "\n    }\n}\n";
        return path.string();
    }
    // Renders `scene` with `args`, which must succeed, and sets `count` to what `read` finds in its
    // summary, which must be a count (> 0). Call through ASSERT_NO_FATAL_FAILURE.
    void renderCounting(const std::string& scene, const std::string& args, long (*read)(const std::string&),
                        long& count) {
        const test::RunResult r = render(scene, args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        count = read(r.out);
        EXPECT_GT(count, 0) << r.out;
    }
};

// The count the render summary's line matching `line` (one group, the count) reports, -1 when there
// is none.
long summaryCount(const std::string& out, const char* line) {
    std::smatch m;
    return std::regex_search(out, m, std::regex(line)) ? std::stol(m[1]) : -1;
}
long patches(const std::string& out) { return summaryCount(out, "radiosity: (\\d+) patches"); }
long walkSteps(const std::string& out) { return summaryCount(out, "interiors +(\\d+) guided random-walk steps"); }

TEST_F(IntegratorParametersCli, RadiosityPatchSizeSetsThePatches) {
    long byDefault = 0, coarse = 0;
    ASSERT_NO_FATAL_FAILURE(renderCounting(kCornellBox, "--integrator radiosity", patches, byDefault));
    ASSERT_NO_FATAL_FAILURE(
        renderCounting(kCornellBox, "--integrator radiosity --radiosity-patch-size 1000000", patches, coarse));
    EXPECT_LT(coarse, byDefault) << "one patch per triangle when no edge is longer than the size";
}

TEST_F(IntegratorParametersCli, SppmPhotonsAndRadiusReachTheIntegrator) {
    const test::RunResult r = render(kCornellBox, "--integrator sppm --sppm-photons 1234 --sppm-radius 0.0625");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("photon maps of 1234 paths"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("radius 0.0625 ->"), std::string::npos) << r.out;
}

TEST_F(IntegratorParametersCli, SubsurfaceWalksReachThePathTracer) {
    // Three walks from each entry the camera sees take more than twice the steps of one (measured
    // 560 and 217: the entries of later bounces are not split).
    long one = 0, three = 0;
    ASSERT_NO_FATAL_FAILURE(renderCounting(kSubsurface, "--subsurface-walks 1", walkSteps, one));
    ASSERT_NO_FATAL_FAILURE(renderCounting(kSubsurface, "--subsurface-walks 3", walkSteps, three));
    EXPECT_GT(three, 2 * one);
}

TEST_F(IntegratorParametersCli, RenderSettingsAttributesReachTheIntegratorAndTheOptionWins) {
    const std::string scene = tunedScene(
        "        int fluence:sppm:photons = 2345\n        float fluence:sppm:radius = 0.125\n"
        "        float fluence:radiosity:patchSize = 1000000");
    const test::RunResult fromScene = render(scene, "--integrator sppm");
    ASSERT_EQ(fromScene.exitCode, 0) << fromScene.err;
    EXPECT_NE(fromScene.out.find("photon maps of 2345 paths"), std::string::npos) << fromScene.out;
    EXPECT_NE(fromScene.out.find("radius 0.125 ->"), std::string::npos) << fromScene.out;
    EXPECT_NE(fromScene.err.find("fluence:radiosity:patchSize: integrator 'sppm' has no such parameter"),
              std::string::npos)
        << fromScene.err;
    const test::RunResult overridden = render(scene, "--integrator sppm --sppm-photons 1234");
    ASSERT_EQ(overridden.exitCode, 0) << overridden.err;
    EXPECT_NE(overridden.out.find("photon maps of 1234 paths"), std::string::npos) << overridden.out;
}

TEST_F(IntegratorParametersCli, BadOptionValuesAreUsageErrors) {
    for (const char* args : {"--sppm-photons 0", "--sppm-photons 2.5", "--sppm-photons 100000000", "--sppm-radius -1",
                             "--radiosity-patch-size 0", "--radiosity-patch-size nan", "--sppm-radius wide",
                             "--subsurface-walks 0", "--subsurface-walks 1.5", "--subsurface-walks 65", "--walk-hero 2",
                             "--walk-hero 0.5", "--walks-after-diffuse 2", "--walks-after-diffuse 0.5"}) {
        SCOPED_TRACE(args);
        const test::RunResult r = render(kCornellBox, std::string("--integrator sppm ") + args);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        const std::string option = std::string(args).substr(0, std::string(args).find(' '));
        EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
    }
}

TEST_F(IntegratorParametersCli, BadAttributeValuesAreSceneErrorsNamingThePrim) {
    const test::RunResult r = render(tunedScene("        int fluence:sppm:photons = 0"), "--integrator sppm");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("render settings /Render/Tuned: fluence:sppm:photons must be a whole number from 1"),
              std::string::npos)
        << r.err;
}

TEST_F(IntegratorParametersCli, HelpListsTheParameters) {
    const test::RunResult r = test::runFluence("--help", dir_.path());
    ASSERT_EQ(r.exitCode, 0);
    for (const char* text : {"--sppm-photons N", "fluence:sppm:photons", "--sppm-radius X", "fluence:sppm:radius",
                             "--radiosity-patch-size X", "fluence:radiosity:patchSize", "--subsurface-walks N",
                             "fluence:path:subsurfaceWalks", "--walk-hero N", "fluence:path:walkHero",
                             "--walks-after-diffuse N", "fluence:path:walksAfterDiffuse"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace fluence
