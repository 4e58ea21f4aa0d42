// Light groups (delegate/light_groups.h): `fluence:lightGroup` on a light, on an emissive mesh or an
// ancestor of it, or on its Material, becomes the label its event carries in light path
// expressions, in place of the prim's name. Shown exactly: a scene whose lights and emissive meshes
// carry groups and the same scene without them, rendered with the same seed, give bit-identical
// LPE layers when one names the groups and the other the prims the groups hold.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// A floor lit by two sphere lights (K1, K2) and a rect light (F), and two emissive quads: one under
// an Xform, one whose Material emits. With `groups`: K1 and K2 in group "key", F in "fill", the
// Xform's quad in "screens" (authored on the Xform), the other in "panels" (on its Material).
std::string scene(bool groups) {
    auto group = [&](const char* name) {
        return groups ? std::string("        string fluence:lightGroup = \"") + name + "\"\n" : std::string();
    };
    auto quad = [](const char* name, const char* material, double x) {
        return std::string("    def Mesh \"") + name + "\"\n    {\n" +
               "        int[] faceVertexCounts = [4]\n        int[] faceVertexIndices = [0, 1, 2, 3]\n" +
               "        point3f[] points = [(" + std::to_string(x - 0.3) + ", 0.2, -1), (" + std::to_string(x + 0.3) +
               ", 0.2, -1), (" + std::to_string(x + 0.3) + ", 0.8, -1), (" + std::to_string(x - 0.3) + ", 0.8, -1)]\n" +
               "        rel material:binding = </Looks/" + material + ">\n    }\n";
    };
    return std::string("#usda 1.0\n(\n    upAxis = \"Y\"\n)\n") +
           "def Camera \"Cam\"\n{\n    double3 xformOp:translate = (0, 1, 4)\n"
           "    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n"
           "def Scope \"Looks\"\n{\n"
           "    def Material \"Floor\"\n    {\n"
           "        token outputs:surface.connect = </Looks/Floor/S.outputs:surface>\n"
           "        def Shader \"S\"\n        {\n            uniform token info:id = \"UsdPreviewSurface\"\n"
           "            color3f inputs:diffuseColor = (0.7, 0.7, 0.7)\n            token outputs:surface\n"
           "        }\n    }\n" +
           "    def Material \"Glow\"\n    {\n" + group("panels") +
           "        token outputs:surface.connect = </Looks/Glow/S.outputs:surface>\n"
           "        def Shader \"S\"\n        {\n            uniform token info:id = \"UsdPreviewSurface\"\n"
           "            color3f inputs:emissiveColor = (2, 1, 0.5)\n            token outputs:surface\n"
           "        }\n    }\n}\n" +
           "def Mesh \"Floor\"\n{\n    int[] faceVertexCounts = [4]\n    int[] faceVertexIndices = [0, 1, 2, 3]\n"
           "    point3f[] points = [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)]\n"
           "    rel material:binding = </Looks/Floor>\n}\n"
           "def Xform \"Screens\"\n{\n" +
           group("screens") + quad("A", "Glow", -1.0) + "}\n" + quad("Panel", "Glow", 1.0) +
           "def SphereLight \"K1\"\n{\n    float inputs:radius = 0.1\n    float inputs:intensity = 20\n" +
           group("key") +
           "    double3 xformOp:translate = (-1, 2, 0)\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n"
           "def SphereLight \"K2\"\n{\n    float inputs:radius = 0.1\n    float inputs:intensity = 20\n" +
           group("key") +
           "    double3 xformOp:translate = (1, 2, 0)\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n}\n"
           "def RectLight \"F\"\n{\n    float inputs:intensity = 3\n" +
           group("fill") +
           "    double3 xformOp:translate = (0, 3, 1)\n    float3 xformOp:rotateXYZ = (-90, 0, 0)\n"
           "    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\"]\n}\n";
}

class LightGroupCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_light_group_cli"};

    test::ExrImage render(bool groups, const std::string& lpes) {
        const std::string usda = tmp_.file(groups ? "groups.usda" : "names.usda");
        std::ofstream(usda) << scene(groups);
        const std::string out = tmp_.file(groups ? "groups.exr" : "names.exr");
        test::RunResult r =
            test::runFluence("render " + usda + " -o " + out + " -r 24 16 --spp 8 " + lpes, tmp_.path());
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return test::readExr(out);
    }
};

TEST_F(LightGroupCli, AGroupLabelsItsLightsAndEmissiveMeshesInPlaceOfTheirNames) {
    const test::ExrImage grouped = render(true,
                                          "--lpe \"key=C.*<L'key'>\" --lpe \"fill=C.*<L'fill'>\""
                                          " --lpe \"screens=C.*<O'screens'>\" --lpe \"panels=C.*<O'panels'>\""
                                          " --lpe \"byName=C.*<L'K1'>\"");
    const test::ExrImage named = render(false,
                                        "--lpe \"key=C.*<L.['K1' 'K2']>\" --lpe \"fill=C.*<L'F'>\""
                                        " --lpe \"screens=C.*<O'A'>\" --lpe \"panels=C.*<O'Panel'>\""
                                        " --lpe \"byName=C.*<L'K1'>\"");
    ASSERT_EQ(grouped.pixels.size(), named.pixels.size());
    for (const char* layer : {"key", "fill", "screens", "panels"}) {
        double sum = 0.0;
        for (int y = 0; y < grouped.height; ++y)
            for (int x = 0; x < grouped.width; ++x)
                for (const char* c : {".R", ".G", ".B"}) {
                    const std::string channel = std::string(layer) + c;
                    ASSERT_EQ(grouped.at(x, y, channel), named.at(x, y, channel)) << channel << " at " << x << "," << y;
                    sum += grouped.at(x, y, channel);
                }
        EXPECT_GT(sum, 0.0) << layer << " gathered no light";
    }
    // In a group, a light no longer answers to its own name; without groups it does.
    double grouped1 = 0.0, named1 = 0.0;
    for (int y = 0; y < grouped.height; ++y)
        for (int x = 0; x < grouped.width; ++x) {
            grouped1 += grouped.at(x, y, "byName.R");
            named1 += named.at(x, y, "byName.R");
        }
    EXPECT_EQ(grouped1, 0.0);
    EXPECT_GT(named1, 0.0);
}

TEST_F(LightGroupCli, AGroupOfAnotherTypeIsWarnedAboutAndLeftOut) {
    const std::string usda = tmp_.file("bad.usda");
    std::string text = scene(false);
    const std::string light = "def RectLight \"F\"\n{\n";
    text.replace(text.find(light), light.size(), light + "    int fluence:lightGroup = 3\n");
    std::ofstream(usda) << text;
    test::RunResult r =
        test::runFluence("render " + usda + " -o " + tmp_.file("bad.exr") + " -r 8 8 --spp 1", tmp_.path());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("/F"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("fluence:lightGroup"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fluence
