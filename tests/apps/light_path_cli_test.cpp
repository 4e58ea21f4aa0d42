// End-to-end: light path expression AOVs from `--lpe NAME=EXPR` and from USD RenderVars with
// sourceType "lpe", written as EXR layers (apps/light_path_aovs.h); and the errors a user gets
// for a bad name, a bad expression, or an integrator that does not write them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

const std::string kCornellBox = (fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda").string();

class LightPathCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_light_path_cli"};

    RunResult render(const std::string& scene, const std::string& extra) {
        return test::runFluence("render " + scene + " -o " + tmp_.file("out.exr") + " -r 16 12 --spp 4 " + extra,
                                tmp_.path());
    }
    // The furnace scene with render settings whose product has `vars` (RenderVar prims under /Render/Vars).
    std::string sceneWithVars(const std::string& varPrims, const std::string& varTargets) {
        const std::string path = tmp_.file("vars.usda");
        std::ofstream(path)
            << test::furnaceUsda(0.5) << "def Scope \"Render\"\n{\n"
            << "    def RenderSettings \"Settings\"\n    {\n        rel products = </Render/Product>\n    }\n"
            << "    def RenderProduct \"Product\"\n    {\n        rel orderedVars = [" << varTargets << "]\n    }\n"
            << "    def Scope \"Vars\"\n    {\n"
            << varPrims << "    }\n}\n";
        return path + " -s /Render/Settings";
    }
};

std::string lpeVar(const std::string& name, const std::string& expression) {
    return "        def RenderVar \"" + name + "\"\n        {\n            uniform string sourceName = \"" +
           expression + "\"\n            uniform token sourceType = \"lpe\"\n        }\n";
}

// Every pixel's layers sum to its beauty (they split the paths between them).
void expectLayersSumToBeauty(const test::ExrImage& img, const std::vector<std::string>& layers) {
    for (const std::string& layer : layers)
        for (const char* c : {".R", ".G", ".B"}) ASSERT_GE(img.channel(layer + c), 0) << layer << c << " is missing";
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (const char* c : {"R", "G", "B"}) {
                double sum = 0.0;
                for (const std::string& layer : layers) sum += img.at(x, y, layer + "." + c);
                const double beauty = img.at(x, y, c);
                ASSERT_NEAR(sum, beauty, 1e-5 * beauty + 1e-7) << x << "," << y << " " << c;
            }
}

TEST_F(LightPathCli, LpeOptionsBecomeLayersThatSumToTheBeauty) {
    for (const char* integrator : {"path", "bdpt", "sppm"}) {
        RunResult r = render(kCornellBox, std::string("--integrator ") + integrator +
                                              " --lpe 'direct=C<RD>[LO]' --lpe 'indirect=C<RD>.+[LO]'"
                                              " --lpe 'seen=C[LO]'");
        ASSERT_EQ(r.exitCode, 0) << integrator << ": " << r.err;
        expectLayersSumToBeauty(test::readExr(tmp_.file("out.exr")), {"direct", "indirect", "seen"});
    }
}

TEST_F(LightPathCli, LpeRenderVarsBecomeLayersAndTheCommandLineReplacesOne) {
    const std::string scene = sceneWithVars(lpeVar("diffuse", "C<RD>.*L") + lpeVar("other", "C([^D].*)?L"),
                                            "</Render/Vars/diffuse>, </Render/Vars/other>");
    RunResult r = render(scene, "");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    expectLayersSumToBeauty(test::readExr(tmp_.file("out.exr")), {"diffuse", "other"});

    r = render(scene, "--lpe 'other=C.*L'");  // now `other` holds every path: the same as the beauty
    ASSERT_EQ(r.exitCode, 0) << r.err;
    expectLayersSumToBeauty(test::readExr(tmp_.file("out.exr")), {"other"});
}

TEST_F(LightPathCli, BadLpeOptionsAreUsageErrors) {
    RunResult r = render(kCornellBox, "--lpe diffuse");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("NAME=EXPRESSION"), std::string::npos) << r.err;

    r = render(kCornellBox, "--lpe 'diffuse=C<RD'");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("column"), std::string::npos) << r.err;

    r = render(kCornellBox, "--lpe 'N=C.*L'");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("taken by the image's own channels"), std::string::npos) << r.err;

    r = render(kCornellBox, "--integrator whitted --lpe 'all=C.*L'");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("does not write light path expression AOVs"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("out.exr")));
}

// sppm's photons carry expressions of at most 64 automaton states: a longer one is refused by name.
TEST_F(LightPathCli, SppmRefusesAnExpressionItsPhotonsCannotCarry) {
    RunResult r = render(kCornellBox, "--integrator sppm --lpe 'long=C.{70}L' --lpe 'all=C.*L'");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--lpe long: integrator 'sppm' cannot write it"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("C.{70}L"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("out.exr")));

    r = render(sceneWithVars(lpeVar("long", "C.{70}L"), "</Render/Vars/long>"), "--integrator sppm");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("lpe RenderVar long"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("out.exr")));
}

TEST_F(LightPathCli, BadLpeRenderVarsAreSceneErrorsNamingThePrim) {
    RunResult r = render(sceneWithVars(lpeVar("broken", "C(RD"), "</Render/Vars/broken>"), "");
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("RenderVar /Render/Vars/broken"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("column"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("out.exr")));
}

TEST_F(LightPathCli, AnIntegratorWithoutLayersWarnsAndLeavesTheRenderVarsOut) {
    RunResult r = render(sceneWithVars(lpeVar("all", "C.*L"), "</Render/Vars/all>"), "--integrator direct");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("integrator 'direct' does not write light path expression AOVs"), std::string::npos) << r.err;
    EXPECT_LT(test::readExr(tmp_.file("out.exr")).channel("all.R"), 0);
}

}  // namespace
}  // namespace fluence
