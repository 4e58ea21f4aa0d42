// End-to-end: the classes of light paths a scene can produce, as `fluence info` lists them and
// `fluence render` warns of those its integrator misses; and the integrator a scene's
// RenderSettings choose (fluence:integrator), the sampler (fluence:sampler, --sampler) and the dome
// light sampling (fluence:domeLightSampling, --dome-sampling).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

const std::string kCornellBox = (fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda").string();
const std::string kPointLight = (fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/lights/sphere_point.usda").string();

// The line of `text` that begins with `start` ("" when there is none).
std::string lineStarting(const std::string& text, const std::string& start) {
    const std::size_t at = text.starts_with(start) ? 0 : text.find("\n" + start);
    if (at == std::string::npos) return "";
    const std::size_t begin = at == 0 ? 0 : at + 1;
    return text.substr(begin, text.find('\n', begin) - begin);
}

// A token of the render settings that a command-line option overrides, as the EXR header names
// what was used: `attribute` = `setting` is read, `option override` wins over it, a scene without it
// takes `fallback`, the option alone is read; a bad setting is a scene error naming the prim (exit
// 3), a bad option value a usage error (exit 2).
struct OverriddenSetting {
    std::string attribute, option, header, setting, override, fallback, badSetting, settingError, badOption,
        optionError;
};

class PathClassCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_path_class_cli"};

    RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
    // A tiny render of `scene` into the temporary directory, with `extra` options.
    RunResult render(const std::string& scene, const std::string& extra = "") {
        return run("render " + scene + " -o " + tmp_.file("out.exr") + " -r 8 8 --spp 1 " + extra);
    }
    // The furnace scene with a RenderSettings prim /Render/Settings holding `attributes`.
    std::string sceneWithSettings(const std::string& attributes) {
        const std::string path = tmp_.file("settings.usda");
        std::ofstream(path) << test::furnaceUsda(0.5)
                            << "def Scope \"Render\"\n{\n    def RenderSettings \"Settings\"\n    {\n        "
                            << attributes << "\n    }\n}\n";
        return path + " -s /Render/Settings";
    }
    void expectTheOptionOverridesTheSetting(const OverriddenSetting& s);
};

TEST_F(PathClassCli, InfoListsTheScenesClassesAndWhatEachIntegratorMisses) {
    RunResult r = run("info " + kCornellBox);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineStarting(r.out, "path classes"), "path classes  LE, LDE, LD(D|S)*DE") << r.out;
    EXPECT_TRUE(lineStarting(r.out, "  path ").ends_with(" covers them all")) << r.out;
    EXPECT_TRUE(lineStarting(r.out, "  naive ").ends_with(" covers them all")) << r.out;

    r = run("info " + kPointLight);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(lineStarting(r.out, "path classes"), "path classes  LE, LDE, LD(D|S)*DE, delta lights") << r.out;
    EXPECT_TRUE(lineStarting(r.out, "  path ").ends_with(" covers them all")) << r.out;
    EXPECT_TRUE(lineStarting(r.out, "  naive ").ends_with(" misses delta lights")) << r.out;
}

TEST_F(PathClassCli, RenderWarnsOfTheClassesItsIntegratorMisses) {
    RunResult r = render(kPointLight, "--integrator naive");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("integrator 'naive' misses: delta lights (light that this scene has)"), std::string::npos)
        << r.err;

    r = render(kCornellBox, "--integrator path");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("misses"), std::string::npos) << r.err;
}

TEST_F(PathClassCli, RenderSettingsChooseTheIntegratorUnlessTheCommandLineDoes) {
    const std::string scene = sceneWithSettings("uniform token fluence:integrator = \"naive\"");
    RunResult r = render(scene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("integrator naive,"), std::string::npos) << r.out;

    r = render(scene, "--integrator path");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("integrator path,"), std::string::npos) << r.out;

    r = render(sceneWithSettings(""));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("integrator path,"), std::string::npos) << "the default: " << r.out;
}

void PathClassCli::expectTheOptionOverridesTheSetting(const OverriddenSetting& s) {
    const auto used = [&](const std::string& scene, const std::string& extra) {
        const RunResult r = render(scene, extra);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return test::readExr(tmp_.file("out.exr")).spec.get_string_attribute(s.header);
    };
    const std::string withSetting = sceneWithSettings("uniform token " + s.attribute + " = \"" + s.setting + "\"");
    EXPECT_EQ(used(withSetting, ""), s.setting);
    EXPECT_EQ(used(withSetting, s.option + " " + s.override), s.override);
    EXPECT_EQ(used(sceneWithSettings(""), ""), s.fallback) << "the default";
    EXPECT_EQ(used(kCornellBox, s.option + " " + s.setting), s.setting);

    RunResult r = render(sceneWithSettings("uniform token " + s.attribute + " = \"" + s.badSetting + "\""));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find(s.settingError), std::string::npos) << r.err;
    r = render(kCornellBox, s.option + " " + s.badOption);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(s.optionError), std::string::npos) << r.err;
}

TEST_F(PathClassCli, RenderSettingsChooseTheSamplerUnlessTheCommandLineDoes) {
    expectTheOptionOverridesTheSetting(
        {"fluence:sampler", "--sampler", "fluence/sampler", "independent", "sobol", "sobol", "halton",
         "/Render/Settings: fluence:sampler 'halton' is not a sampler (available: sobol, independent)", "halton",
         "unknown sampler 'halton' (available: sobol, independent)"});
}

TEST_F(PathClassCli, RenderSettingsChooseTheDomeLightSamplingUnlessTheCommandLineDoes) {
    expectTheOptionOverridesTheSetting({"fluence:domeLightSampling", "--dome-sampling", "fluence/domeLightSampling",
                                        "always", "auto", "auto", "never",
                                        "/Render/Settings: fluence:domeLightSampling 'never' is not a dome light "
                                        "sampling (available: auto or always)",
                                        "sometimes", "--dome-sampling must be auto or always, not 'sometimes'"});
}

TEST_F(PathClassCli, AnUnknownIntegratorInRenderSettingsIsASceneError) {
    RunResult r = render(sceneWithSettings("uniform token fluence:integrator = \"nope\""));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("/Render/Settings"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("'nope'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("available: path"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fluence
