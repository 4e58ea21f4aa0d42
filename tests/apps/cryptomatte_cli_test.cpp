// End-to-end: Cryptomatte layers from `--cryptomatte` and from RenderVars (apps/cryptomatte_layers.h),
// read back from the EXR with OpenImageIO. The scene, through an orthographic camera 8 x 4 units
// wide on 32 x 16 pixels (a pixel is 0.25 units): two cubes with two materials, /World/Right in front
// of /World/Left and overlapping it, and one instanced prototype (a cube, Blue) placed twice.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>

#include "output/cryptomatte.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

using test::RunResult;

const char* const kScene = R"usda(#usda 1.0
(
    defaultPrim = "World"
    upAxis = "Y"
)

def Xform "World"
{
    def Camera "Camera"
    {
        token projection = "orthographic"
        float horizontalAperture = 80
        float verticalAperture = 40
        float2 clippingRange = (0.1, 100)
        double3 xformOp:translate = (0, 0, 10)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }

    def DistantLight "Sun"
    {
        float inputs:intensity = 2
    }

    def Scope "Looks"
    {
        def Material "Red"
        {
            token outputs:surface.connect = </World/Looks/Red/Shader.outputs:surface>
            def Shader "Shader"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0.8, 0.1, 0.1)
                token outputs:surface
            }
        }
        def Material "Blue"
        {
            token outputs:surface.connect = </World/Looks/Blue/Shader.outputs:surface>
            def Shader "Shader"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0.1, 0.1, 0.8)
                token outputs:surface
            }
        }
    }

    def Cube "Left" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        double size = 1.6
        rel material:binding = </World/Looks/Red>
        double3 xformOp:translate = (-2.4, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }

    def Cube "Right" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        double size = 1.6
        rel material:binding = </World/Looks/Blue>
        double3 xformOp:translate = (-1, 0, 0.5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }

    def Xform "InstA" (
        instanceable = true
        prepend references = </Prototype>
    )
    {
        double3 xformOp:translate = (1, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }

    def Xform "InstB" (
        instanceable = true
        prepend references = </Prototype>
    )
    {
        double3 xformOp:translate = (3, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}

class Xform "Prototype"
{
    def Cube "Box" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        double size = 1.6
        rel material:binding = </World/Looks/Blue>
    }
}
)usda";

constexpr int kSpp = 64;
// Pixels on the middle row (y in [-0.25, 0]) wholly inside one object, and the pixel x in [-2, -1.75]
// where /World/Right's edge (x = -1.8) crosses /World/Left: 0.8 of it Left, 0.2 Right.
constexpr int kRow = 8, kLeft = 5, kRight = 12, kInstA = 20, kInstB = 28, kEdge = 8;

class CryptomatteCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_cryptomatte_cli"};

    std::string scene(const std::string& extra = "") {
        const std::string path = tmp_.file("scene.usda");
        std::ofstream(path) << kScene << extra;
        return path;
    }
    RunResult render(const std::string& scenePath, const std::string& output, const std::string& options) {
        return test::runFluence("render " + scenePath + " -o " + tmp_.file(output) + " -r 32 16 --spp " +
                                    std::to_string(kSpp) + " " + options,
                                tmp_.path());
    }
};

// The manifest of layer `typeName` (name -> 8 hex digits), read from the header under its key.
std::map<std::string, std::string> manifest(const test::ExrImage& img, const std::string& typeName) {
    const std::string prefix = "cryptomatte/" + output::cryptomatteKey(typeName) + "/";
    EXPECT_EQ(img.spec.get_string_attribute(prefix + "name"), typeName);
    EXPECT_EQ(img.spec.get_string_attribute(prefix + "hash"), "MurmurHash3_32");
    EXPECT_EQ(img.spec.get_string_attribute(prefix + "conversion"), "uint32_to_float32");
    const std::string json = img.spec.get_string_attribute(prefix + "manifest");
    std::map<std::string, std::string> entries;
    const std::regex entry("\"([^\"]*)\":\"([0-9a-f]{8})\"");
    for (auto it = std::sregex_iterator(json.begin(), json.end(), entry); it != std::sregex_iterator(); ++it)
        entries[(*it)[1].str()] = (*it)[2].str();
    return entries;
}

std::uint32_t idAt(const test::ExrImage& img, int x, const std::string& channel) {
    return std::bit_cast<std::uint32_t>(img.at(x, kRow, channel));
}

TEST_F(CryptomatteCli, ObjectAndMaterialLayersNameWhatEachPixelSees) {
    RunResult r = render(scene(), "out.exr", "--cryptomatte object,material");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("out.exr"));
    for (const std::string layer : {"CryptoObject", "CryptoMaterial"})
        for (const char* group : {"00", "01", "02"})  // depth 6
            for (const char* c : {".R", ".G", ".B", ".A"})
                ASSERT_GE(img.channel(layer + group + c), 0) << layer << group << c;
    EXPECT_LT(img.channel("CryptoObject03.R"), 0);
    EXPECT_EQ(img.spec.get_string_attribute("compression"), "zip");
    const std::string data = img.spec.get_string_attribute("fluence/dataChannels");
    EXPECT_NE(data.find("CryptoObject00.R"), std::string::npos);

    const auto objects = manifest(img, "CryptoObject"), materials = manifest(img, "CryptoMaterial");
    for (const char* name : {"/World/Left", "/World/Right", "/World/InstA", "/World/InstB"}) {
        ASSERT_TRUE(objects.contains(name)) << name;
        EXPECT_EQ(objects.at(name), output::cryptomatteHex(output::cryptomatteId(name)));
    }
    for (const char* name : {"/World/Looks/Red", "/World/Looks/Blue"}) ASSERT_TRUE(materials.contains(name)) << name;

    // Inside each object: rank 0 is it, with coverage 1, and nothing else.
    const std::pair<int, const char*> inside[] = {
        {kLeft, "/World/Left"}, {kRight, "/World/Right"}, {kInstA, "/World/InstA"}, {kInstB, "/World/InstB"}};
    for (const auto& [x, name] : inside) {
        EXPECT_EQ(idAt(img, x, "CryptoObject00.R"), output::cryptomatteId(name)) << name;
        EXPECT_EQ(img.at(x, kRow, "CryptoObject00.G"), 1.0f) << name;
        EXPECT_EQ(img.at(x, kRow, "CryptoObject00.A"), 0.0f) << name;
    }
    // The instances: different objects, one material.
    EXPECT_NE(idAt(img, kInstA, "CryptoObject00.R"), idAt(img, kInstB, "CryptoObject00.R"));
    EXPECT_EQ(idAt(img, kInstA, "CryptoMaterial00.R"), output::cryptomatteId("/World/Looks/Blue"));
    EXPECT_EQ(idAt(img, kInstB, "CryptoMaterial00.R"), output::cryptomatteId("/World/Looks/Blue"));
    EXPECT_EQ(idAt(img, kLeft, "CryptoMaterial00.R"), output::cryptomatteId("/World/Looks/Red"));
    // Background: no id.
    EXPECT_EQ(img.at(0, 0, "CryptoObject00.R"), 0.0f);
    EXPECT_EQ(img.at(0, 0, "CryptoObject00.G"), 0.0f);

    // The edge pixel: every sample sees Left or Right, so the two coverages sum to 1 (in units of
    // 1/spp); Right's is a binomial estimate of 0.2 (4 standard deviations allowed).
    for (const std::string layer : {"CryptoObject", "CryptoMaterial"}) {
        const float first = img.at(kEdge, kRow, layer + "00.G"), second = img.at(kEdge, kRow, layer + "00.A");
        EXPECT_NEAR(first + second, 1.0f, 0.5f / kSpp) << layer;
        EXPECT_EQ(img.at(kEdge, kRow, layer + "01.G"), 0.0f) << layer;
    }
    EXPECT_EQ(idAt(img, kEdge, "CryptoObject00.R"), output::cryptomatteId("/World/Left"));
    EXPECT_EQ(idAt(img, kEdge, "CryptoObject00.B"), output::cryptomatteId("/World/Right"));
    EXPECT_NEAR(img.at(kEdge, kRow, "CryptoObject00.A"), 0.2f, 4.0f * std::sqrt(0.2f * 0.8f / kSpp));
}

TEST_F(CryptomatteCli, TheImageIsTheSameAtAnyThreadCount) {
    const std::string path = scene();
    ASSERT_EQ(render(path, "one.exr", "--cryptomatte object,material -j 1").exitCode, 0);
    ASSERT_EQ(render(path, "two.exr", "--cryptomatte object,material -j 2").exitCode, 0);
    const test::ExrImage one = test::readExr(tmp_.file("one.exr")), two = test::readExr(tmp_.file("two.exr"));
    ASSERT_EQ(one.channels, two.channels);
    for (std::size_t i = 0; i < one.pixels.size(); ++i)
        ASSERT_EQ(std::bit_cast<std::uint32_t>(one.pixels[i]), std::bit_cast<std::uint32_t>(two.pixels[i]))
            << "value " << i;
    const std::string key = "cryptomatte/" + output::cryptomatteKey("CryptoObject") + "/manifest";
    EXPECT_EQ(one.spec.get_string_attribute(key), two.spec.get_string_attribute(key));
}

// RenderVars with sourceType "raw" and sourceName CryptoObject / CryptoMaterial are layers named
// after their prims; --cryptomatte-depth sets the ranks.
TEST_F(CryptomatteCli, RenderVarsAddLayersNamedAfterTheirPrims) {
    const std::string settings = R"usda(
def Scope "Render"
{
    def RenderSettings "Settings"
    {
        rel products = </Render/Product>
    }
    def RenderProduct "Product"
    {
        rel orderedVars = [</Render/Vars/objects>, </Render/Vars/looks>]
    }
    def Scope "Vars"
    {
        def RenderVar "objects"
        {
            uniform string sourceName = "CryptoObject"
            uniform token sourceType = "raw"
        }
        def RenderVar "looks"
        {
            uniform string sourceName = "CryptoMaterial"
            uniform token sourceType = "raw"
        }
    }
}
)usda";
    RunResult r = render(scene(settings) + " -s /Render/Settings", "vars.exr", "--cryptomatte-depth 3");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("vars.exr"));
    EXPECT_GE(img.channel("objects01.A"), 0);
    EXPECT_LT(img.channel("objects02.R"), 0);
    EXPECT_GE(img.channel("looks00.R"), 0);
    EXPECT_LT(img.channel("CryptoObject00.R"), 0);
    EXPECT_TRUE(manifest(img, "objects").contains("/World/InstB"));
    EXPECT_TRUE(manifest(img, "looks").contains("/World/Looks/Red"));
    EXPECT_EQ(idAt(img, kRight, "looks00.R"), output::cryptomatteId("/World/Looks/Blue"));
}

// Tiles rendered apart and assembled give the one-piece render's Cryptomatte channels, and the
// assembled manifest names what every tile saw (the left tile sees the cubes, the right the instances).
TEST_F(CryptomatteCli, AssembledTilesMatchTheRenderInOnePiece) {
    const std::string path = scene();
    ASSERT_EQ(render(path, "whole.exr", "--cryptomatte object").exitCode, 0);
    std::string tiles;
    for (int i = 0; i < 2; ++i) {
        RunResult r =
            render(path, "tile" + std::to_string(i) + ".exr",
                   "--cryptomatte object --tile-count 2 1 --tile-suffix '' --tile-index " + std::to_string(i));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        tiles += " " + tmp_.file("tile" + std::to_string(i) + ".exr");
    }
    RunResult r = test::runFluence("assemble -o " + tmp_.file("assembled.exr") + tiles, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage whole = test::readExr(tmp_.file("whole.exr")),
                         assembled = test::readExr(tmp_.file("assembled.exr"));
    ASSERT_EQ(assembled.channels, whole.channels);
    EXPECT_TRUE(assembled.pixels == whole.pixels);
    const auto names = manifest(assembled, "CryptoObject");
    EXPECT_EQ(names, manifest(whole, "CryptoObject"));
    EXPECT_EQ(names.size(), 4u);
}

TEST_F(CryptomatteCli, BadOptionsAreUsageErrors) {
    const std::string path = scene();
    RunResult r = render(path, "bad.exr", "--cryptomatte object,asset");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("'asset' is not a layer"), std::string::npos) << r.err;
    EXPECT_EQ(render(path, "bad.exr", "--cryptomatte object --cryptomatte-depth 0").exitCode, 2);
}

TEST_F(CryptomatteCli, WithoutCryptomatteThereAreNoLayers) {
    ASSERT_EQ(render(scene(), "plain.exr", "").exitCode, 0);
    const test::ExrImage img = test::readExr(tmp_.file("plain.exr"));
    for (const std::string& c : img.channels) EXPECT_EQ(c.find("Crypto"), std::string::npos) << c;
}

}  // namespace
}  // namespace fluence
