// `fluence render` of a MaterialX look whose base_color is a mix of two constant colours
// (times a constant): the image is the one rendered with that colour authored as a constant,
// bit for bit, and differs from the one rendered with either colour alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"

namespace fluence {
namespace {

namespace fs = std::filesystem;

// A sphere under a dome, bound to /World/Looks/M, which `looks` defines.
std::string sphereWith(const std::string& looks) {
    return "#usda 1.0\n(\n    upAxis = \"Z\"\n)\n\ndef Xform \"World\"\n{\n"
           "    def Mesh \"Sphere\" (\n        prepend apiSchemas = [\"MaterialBindingAPI\"]\n    )\n    {\n"
           "        uniform token subdivisionScheme = \"none\"\n" +
           test::usdSphereMesh(24, 12) + "        rel material:binding = </World/Looks/M>\n    }\n" + looks +
           "    def DomeLight \"Dome\"\n    {\n        float inputs:intensity = 1\n    }\n"
           "    def Camera \"Camera\"\n    {\n        float focalLength = 50\n"
           "        float horizontalAperture = 36\n        float verticalAperture = 36\n"
           "        double3 xformOp:translate = (0, -4, 0)\n        float3 xformOp:rotateXYZ = (90, 0, 0)\n"
           "        uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\"]\n    }\n}\n";
}

// A Standard Surface material M whose base_color is authored as `colour`.
std::string constantLook(const std::string& colour) {
    return "    def Scope \"Looks\"\n    {\n        def Material \"M\"\n        {\n"
           "            token outputs:mtlx:surface.connect = </World/Looks/M/S.outputs:out>\n"
           "            def Shader \"S\"\n            {\n"
           "                uniform token info:id = \"ND_standard_surface_surfaceshader\"\n"
           "                color3f inputs:base_color = " +
           colour +
           "\n"
           "                float inputs:specular = 0\n"
           "                token outputs:out\n            }\n        }\n    }\n";
}

class MaterialXNodesCli : public ::testing::Test {
protected:
    test::ExrImage render(const std::string& name, const std::string& usda) {
        const fs::path scene = dir.path() / (name + ".usda"), out = dir.path() / (name + ".exr");
        std::ofstream(scene) << usda;
        const test::RunResult r =
            test::runFluence("render '" + scene.string() + "' -o '" + out.string() + "' -r 32 32 --spp 4", dir.path());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
        return test::readExr(out);
    }
    test::TempDir dir;
};

bool sameBeauty(const test::ExrImage& a, const test::ExrImage& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (const char* c : {"R", "G", "B", "A"})
                if (a.at(x, y, c) != b.at(x, y, c)) return false;
    return true;
}

TEST_F(MaterialXNodesCli, AMixOfConstantColoursRendersAsTheAuthoredMix) {
    // mix(fg, bg, 0.25) * 0.5 = ((1, 0, 0.5) * 0.25 + (0, 1, 0.5) * 0.75) * 0.5 = (0.125, 0.375, 0.25)
    std::ofstream(dir.path() / "look.mtlx") << R"(<?xml version="1.0"?>
<materialx version="1.38">
  <nodegraph name="NG">
    <mix name="blend" type="color3">
      <input name="fg" type="color3" value="1, 0, 0.5" />
      <input name="bg" type="color3" value="0, 1, 0.5" />
      <input name="mix" type="float" value="0.25" />
    </mix>
    <multiply name="half" type="color3">
      <input name="in1" type="color3" nodename="blend" />
      <input name="in2" type="float" value="0.5" />
    </multiply>
    <output name="base" type="color3" nodename="half" />
  </nodegraph>
  <standard_surface name="S" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="NG" output="base" />
    <input name="specular" type="float" value="0" />
  </standard_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="S" />
  </surfacematerial>
</materialx>
)";
    const std::string referenced =
        "    def Scope \"Looks\" (\n        references = @./look.mtlx@</MaterialX/Materials>\n    )\n    {\n    }\n";
    const test::ExrImage mixed = render("mixed", sphereWith(referenced));
    const test::ExrImage authored = render("authored", sphereWith(constantLook("(0.125, 0.375, 0.25)")));
    EXPECT_TRUE(sameBeauty(mixed, authored)) << "the mix renders as the authored constant";
    const test::ExrImage foreground = render("foreground", sphereWith(constantLook("(0.5, 0, 0.25)")));
    EXPECT_FALSE(sameBeauty(mixed, foreground)) << "the colour shows in the image";
}

}  // namespace
}  // namespace fluence
