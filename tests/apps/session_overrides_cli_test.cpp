// End-to-end: the husk-style scene controls of `fluence render`: --set attribute overrides
// (apps/attribute_overrides.h), --purpose and the render settings' includedPurposes,
// --complexity, and --allow-missing (a missing asset is otherwise an error, exit 4, with nothing
// written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "apps/attribute_overrides.h"
#include "apps/cli_options.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

class SceneControlsCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_scene_controls"};

    // The furnace (a grey sphere filling the middle of the frame under a dome of radiance 1), with
    // `edit` applied to its text.
    std::string scene(const std::string& name, const std::function<void(std::string&)>& edit = {}) {
        std::string usda = test::furnaceUsda(0.5);
        if (edit) edit(usda);
        const std::string path = tmp_.file(name);
        std::ofstream(path) << usda;
        return path;
    }
    RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
    test::ExrImage render(const std::string& scenePath, const std::string& args, const std::string& out = "out.exr") {
        RunResult r = run("render " + scenePath + " -r 16 16 --spp 4 -o " + tmp_.file(out) + " " + args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return test::readExr(tmp_.file(out));
    }
};

void insertAfter(std::string& text, const std::string& anchor, const std::string& added) {
    const std::size_t at = text.find(anchor);
    ASSERT_NE(at, std::string::npos) << anchor;
    text.insert(at + anchor.size(), added);
}

TEST(AttributeOverride, ParsesPathAttributeValueAndAnOptionalType) {
    app::AttributeOverride o = app::parseAttributeOverride("/World/Key.inputs:intensity=5");
    EXPECT_EQ(o.primPath, "/World/Key");
    EXPECT_EQ(o.attribute, "inputs:intensity");
    EXPECT_EQ(o.value, "5");
    EXPECT_EQ(o.typeName, "");
    o = app::parseAttributeOverride("string /A/B.label=a=b.c");
    EXPECT_EQ(o.typeName, "string");
    EXPECT_EQ(o.primPath, "/A/B");
    EXPECT_EQ(o.attribute, "label");
    EXPECT_EQ(o.value, "a=b.c");
    for (const char* bad : {"World.x=1", "/World=1", "/World.x", "float", "/.x=1", "/World.=1"})
        EXPECT_THROW(app::parseAttributeOverride(bad), app::UsageError) << bad;
}

TEST_F(SceneControlsCli, SetOverridesAnAuthoredAttributeAsASessionLayerWould) {
    const std::string path = scene("furnace.usda");
    test::ExrImage lit = render(path, "");
    EXPECT_NEAR(lit.at(0, 0, "R"), 1.0f, 1e-5f) << "the dome seen past the sphere";
    test::ExrImage dark = render(path, "--set /World/Dome.inputs:intensity=0", "dark.exr");
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) ASSERT_EQ(dark.at(x, y, "R"), 0.0f) << x << " " << y;
    // An attribute the dome does not author, with its type: exposure 1 doubles the radiance.
    test::ExrImage brighter = render(path, "--set 'float /World/Dome.inputs:exposure=1'", "bright.exr");
    EXPECT_NEAR(brighter.at(0, 0, "R"), 2.0f, 1e-5f);
}

TEST_F(SceneControlsCli, SetRefusesWhatItCannotApply) {
    const std::string path = scene("furnace.usda");
    RunResult r = run("render " + path + " -r 8 8 --spp 1 -o " + tmp_.file("a.exr") +
                      " --set /World/Dome.inputs:intensity=bright");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("is not a float value"), std::string::npos) << r.err;
    r = run("render " + path + " -r 8 8 --spp 1 -o " + tmp_.file("a.exr") + " --set /World/Nothing.x=1");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("/World/Nothing: --set"), std::string::npos) << r.err;
    r = run("render " + path + " -r 8 8 --spp 1 -o " + tmp_.file("a.exr") + " --set /World/Dome.inputs:exposure=1");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("has no attribute 'inputs:exposure'; give its type"), std::string::npos) << r.err;
    r = run("render " + path + " -r 8 8 --spp 1 -o " + tmp_.file("a.exr") +
            " --set 'flaot /World/Dome.inputs:exposure=1'");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("a.exr")));
}

TEST_F(SceneControlsCli, PurposesFollowTheCommandLineElseTheRenderSettings) {
    const std::string guide = scene("guide.usda", [](std::string& usda) {
        insertAfter(usda, "        uniform token subdivisionScheme = \"none\"\n",
                    "        uniform token purpose = \"guide\"\n");
    });
    EXPECT_EQ(render(guide, "").at(8, 8, "A"), 0.0f) << "guides are left out by default";
    EXPECT_EQ(render(guide, "--purpose default,guide", "g.exr").at(8, 8, "A"), 1.0f);
    EXPECT_EQ(render(guide, "--purpose geometry,render", "r.exr").at(8, 8, "A"), 0.0f);

    const std::string proxy = scene("proxy.usda", [](std::string& usda) {
        insertAfter(usda, "        uniform token subdivisionScheme = \"none\"\n",
                    "        uniform token purpose = \"proxy\"\n");
        usda +=
            "def Scope \"Render\"\n{\n    def RenderSettings \"Settings\"\n    {\n"
            "        uniform token[] includedPurposes = [\"default\", \"proxy\"]\n    }\n}\n";
    });
    EXPECT_EQ(render(proxy, "").at(8, 8, "A"), 0.0f) << "no settings chosen: USD's default purposes";
    EXPECT_EQ(render(proxy, "-s /Render/Settings", "s.exr").at(8, 8, "A"), 1.0f) << "the settings include proxies";
    EXPECT_EQ(render(proxy, "-s /Render/Settings --purpose default", "c.exr").at(8, 8, "A"), 0.0f) << "--purpose wins";

    RunResult r = run("render " + guide + " -r 8 8 --spp 1 -o " + tmp_.file("bad.exr") + " --purpose default,ghost");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown purpose 'ghost'"), std::string::npos) << r.err;
}

// The triangle count the render log reports.
long trianglesOf(const RunResult& r) {
    std::smatch m;
    const std::regex count("([0-9]+) triangles");
    return std::regex_search(r.out, m, count) ? std::stol(m[1]) : -1;
}

TEST_F(SceneControlsCli, ComplexityRefinesSubdivisionSurfacesAsHuskDoes) {
    const std::string cage = scene("cage.usda");
    const std::string subdivided = scene("subdivided.usda", [](std::string& usda) {
        const std::string none = "        uniform token subdivisionScheme = \"none\"\n";
        usda.erase(usda.find(none), none.size());  // catmullClark, USD's fallback
    });
    auto triangles = [&](const std::string& path, const std::string& args) {
        RunResult r = run("render " + path + " -r 16 16 --spp 1 -o " + tmp_.file("t.exr") + " " + args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return trianglesOf(r);
    };
    const long cageTriangles = triangles(cage, "");
    ASSERT_GT(cageTriangles, 0);
    EXPECT_EQ(triangles(subdivided, "--complexity lowest"), cageTriangles);
    const long low = triangles(subdivided, "--complexity low"), medium = triangles(subdivided, "--complexity medium");
    EXPECT_GT(low, cageTriangles);
    EXPECT_GT(medium, low);
    EXPECT_EQ(triangles(subdivided, "--complexity medium --subdiv-level 1"), low) << "--subdiv-level wins";
    RunResult r = run("render " + subdivided + " -o " + tmp_.file("x.exr") + " --complexity extreme");
    EXPECT_EQ(r.exitCode, 2);
}

TEST_F(SceneControlsCli, AMissingAssetIsAnErrorUnlessAllowed) {
    const std::string path = scene("missing.usda", [](std::string& usda) {
        insertAfter(usda, "        float inputs:intensity = 1\n",
                    "        asset inputs:texture:file = @./no_such_sky.exr@\n");
        usda += "def \"Extra\" (\n    references = @./no_such_layer.usda@\n)\n{\n}\n";
    });
    RunResult r = run("render " + path + " -r 8 8 --spp 1 -o " + tmp_.file("m.exr"));
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("/World/Dome.inputs:texture:file: missing asset"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no_such_sky.exr"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no_such_layer.usda"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("2 assets are missing; --allow-missing"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("m.exr")));

    r = run("render " + path + " -r 8 8 --spp 1 --allow-missing -o " + tmp_.file("m.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("asset not found:"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(tmp_.file("m.exr")));
    r = run("info " + path);
    EXPECT_EQ(r.exitCode, 0) << "info reports, it does not refuse: " << r.err;
}

// An allowed missing texture is reported once where the asset is authored and once where the
// material takes its fallback, and the render core does not try the file again (which used to add a
// third warning, with OpenImageIO's message spread over two lines).
TEST_F(SceneControlsCli, AnAllowedMissingTextureIsNamedWhereAuthoredAndWhereItsFallbackIsUsed) {
    const std::string path = tmp_.file("texture.usda");
    std::ofstream(path) << test::texturedQuadUsda("no_such_texture.png");
    RunResult r = run("render " + path + " -r 8 8 --spp 1 --allow-missing -o " + tmp_.file("t.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::size_t mentions = 0;
    for (std::size_t at = r.err.find("no_such_texture.png"); at != std::string::npos;
         at = r.err.find("no_such_texture.png", at + 1))
        ++mentions;
    EXPECT_EQ(mentions, 3u) << "the asset line names it twice (resolved and authored), the fallback line once:\n"
                            << r.err;
    EXPECT_NE(r.err.find("/World/Mat/Tex.inputs:file: asset not found"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("/World/Mat/Tex: texture file"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("cannot read texture"), std::string::npos) << r.err;
}

TEST_F(SceneControlsCli, AMissingVolumeFileLeavesTheVolumeOutWhenAllowed) {
    const std::string path = scene("volume.usda", [](std::string& usda) {
        usda +=
            "def Volume \"Smoke\"\n{\n    rel field:density = </Smoke/Density>\n"
            "    def OpenVDBAsset \"Density\"\n    {\n        asset filePath = @./no_such_smoke.vdb@\n"
            "        token fieldName = \"density\"\n    }\n}\n";
    });
    RunResult r = run("render " + path + " -r 8 8 --spp 1 -o " + tmp_.file("v.exr"));
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("no_such_smoke.vdb"), std::string::npos) << r.err;
    r = run("render " + path + " -r 8 8 --spp 1 --allow-missing -o " + tmp_.file("v.exr"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("/Smoke: field 'density': OpenVDB file"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the volume is not rendered (--allow-missing)"), std::string::npos) << r.err;
}

TEST_F(SceneControlsCli, VerbosityZeroSilencesProgressAndAAsksForAlfredLines) {
    const std::string path = scene("furnace.usda");
    RunResult r = run("render " + path + " -r 8 8 --spp 2 -V a -o " + tmp_.file("p.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("ALF_PROGRESS 100%"), std::string::npos) << r.out;
    r = run("render " + path + " -r 8 8 --spp 2 -V0 -o " + tmp_.file("p.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("ALF_PROGRESS"), std::string::npos) << r.out;
    EXPECT_EQ(run("render " + path + " -V x").exitCode, 2);
}

}  // namespace
}  // namespace fluence
