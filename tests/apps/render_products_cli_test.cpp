// End-to-end: every RenderProduct and RenderVar of the render settings (apps/render_products.h):
// several products from one render and from separate ones, pixel types from dataType, primvar
// vars at known pixels, the camera matrices in the headers, lossless compression of data
// channels, data windows, filters, and the scene error of a var Fluence cannot produce.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

// An 8x8 view, from (0, 0, 10) down -Z with a 20 mm square aperture at 50 mm (half-width 0.2 at
// unit distance: the image spans x, y in [-2, 2] at z = 0), of two quads covering z = 0: the left
// one red and the right one blue by a uniform displayColor, with a vertex st = ((x + 3) / 6,
// (y + 3) / 6) and a constant float primvar k = 0.25.
const char* kScene = R"usda(#usda 1.0
(
    upAxis = "Y"
)

def Xform "World"
{
    def Mesh "Quads"
    {
        uniform token subdivisionScheme = "none"
        point3f[] points = [(-3, -3, 0), (0, -3, 0), (3, -3, 0), (-3, 3, 0), (0, 3, 0), (3, 3, 0)]
        int[] faceVertexCounts = [4, 4]
        int[] faceVertexIndices = [0, 1, 4, 3, 1, 2, 5, 4]
        color3f[] primvars:displayColor = [(1, 0, 0), (0, 0, 1)] (interpolation = "uniform")
        texCoord2f[] primvars:st = [(0, 0), (0.5, 0), (1, 0), (0, 1), (0.5, 1), (1, 1)] (interpolation = "vertex")
        float primvars:k = 0.25 (interpolation = "constant")
    }
    def DomeLight "Dome"
    {
        float inputs:intensity = 1
    }
    def Camera "Camera"
    {
        float focalLength = 50
        float horizontalAperture = 20
        float verticalAperture = 20
        double3 xformOp:translate = (0, 0, 10)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
)usda";

std::string var(const std::string& name, const std::string& sourceName, const std::string& sourceType,
                const std::string& dataType, const std::string& extra = "") {
    return "        def RenderVar \"" + name + "\"\n        {\n            uniform string sourceName = \"" +
           sourceName + "\"\n            uniform token sourceType = \"" + sourceType +
           "\"\n            uniform token dataType = \"" + dataType + "\"\n" + extra + "        }\n";
}

class RenderProductsCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_render_products_cli"};

    // The scene with /Render/Settings over `products` (RenderProduct prims) and `vars` (RenderVar
    // prims under /Render/Vars); returns the scene argument.
    std::string scene(const std::string& productTargets, const std::string& products, const std::string& vars) {
        const std::string path = tmp_.file("scene.usda");
        std::ofstream(path) << kScene << "def Scope \"Render\"\n{\n    def RenderSettings \"Settings\"\n    {\n"
                            << "        rel camera = </World/Camera>\n        int2 resolution = (8, 8)\n"
                            << "        rel products = [" << productTargets << "]\n    }\n"
                            << products << "    def Scope \"Vars\"\n    {\n"
                            << vars << "    }\n}\n";
        return path + " -s /Render/Settings";
    }
    std::string product(const std::string& name, const std::string& file, const std::string& varTargets,
                        const std::string& extra = "") {
        return "    def RenderProduct \"" + name + "\"\n    {\n        token productName = \"" + tmp_.file(file) +
               "\"\n" + "        rel orderedVars = [" + varTargets + "]\n" + extra + "    }\n";
    }
    RunResult render(const std::string& sceneArgs, const std::string& extra = "") {
        return test::runFluence("render " + sceneArgs + " --spp 4 " + extra, tmp_.path());
    }
};

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

OIIO::TypeDesc channelType(const OIIO::ImageSpec& spec, const std::string& name) {
    for (int c = 0; c < spec.nchannels; ++c)
        if (spec.channelnames[std::size_t(c)] == name) return spec.channelformat(c);
    return OIIO::TypeUnknown;
}

// An m44f attribute's 16 values (Imath order), or empty.
std::vector<float> matrix(const OIIO::ImageSpec& spec, const std::string& name) {
    const OIIO::ParamValue* p = spec.find_attribute(name, OIIO::TypeMatrix44);
    if (!p) return {};
    const float* v = static_cast<const float*>(p->data());
    return std::vector<float>(v, v + 16);
}

TEST_F(RenderProductsCli, EveryProductIsWrittenAndProductsOfOneCameraShareOneRender) {
    const std::string vars = var("depth", "depth", "raw", "float") + var("normal", "N", "raw", "normal3f");
    const std::string args =
        scene("</Render/A>, </Render/B>, </Render/C>",
              product("A", "a.exr", "</Render/Vars/depth>") + product("B", "b.exr", "</Render/Vars/normal>") +
                  product("C", "c.exr", "</Render/Vars/depth>", "        int2 resolution = (4, 4)\n"),
              vars);
    RunResult r = render(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(count(r.out, "fluence: rendered"), 2) << r.out;  // A and B share one render; C has its own
    const test::ExrImage a = test::readExr(tmp_.file("a.exr")), b = test::readExr(tmp_.file("b.exr")),
                         c = test::readExr(tmp_.file("c.exr"));
    EXPECT_EQ(a.channels, (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
    EXPECT_EQ(b.channels, (std::vector<std::string>{"R", "G", "B", "A", "normal.X", "normal.Y", "normal.Z"}));
    EXPECT_EQ(c.width, 4);
    EXPECT_EQ(a.width, 8);
    // The same render: the same beauty, bit for bit.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) ASSERT_EQ(a.at(x, y, "R"), b.at(x, y, "R"));
    EXPECT_NEAR(a.at(3, 3, "Z"), 10.0f, 1e-4f);
    EXPECT_NEAR(b.at(3, 3, "normal.Z"), 1.0f, 1e-5f);
}

TEST_F(RenderProductsCli, DataTypesSetThePixelTypes) {
    const std::string vars = var("depth", "depth", "raw", "half") + var("count", "sampleCount", "raw", "int") +
                             var("albedo", "albedo", "raw", "color3h") + var("normal", "N", "raw", "normal3f");
    RunResult r = render(
        scene("</Render/P>",
              product("P", "p.exr",
                      "</Render/Vars/depth>, </Render/Vars/count>, </Render/Vars/albedo>, </Render/Vars/normal>"),
              vars));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto in = OIIO::ImageInput::open(tmp_.file("p.exr"));
    ASSERT_TRUE(in);
    const OIIO::ImageSpec spec = in->spec();
    EXPECT_EQ(channelType(spec, "Z"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(channelType(spec, "count"), OIIO::TypeDesc::UINT);
    EXPECT_EQ(channelType(spec, "albedo.G"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(channelType(spec, "normal.X"), OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(channelType(spec, "R"), OIIO::TypeDesc::FLOAT);
    // The sample counts, as integers.
    const int channel = spec.channelindex("count");
    std::vector<std::uint32_t> counts(64);
    ASSERT_TRUE(in->read_image(0, 0, channel, channel + 1, OIIO::TypeDesc::UINT, counts.data()));
    for (std::uint32_t n : counts) EXPECT_EQ(n, 4u);
}

TEST_F(RenderProductsCli, AssembledTilesKeepThePixelTypesAndValues) {
    const std::string vars = var("depth", "depth", "raw", "half") + var("count", "sampleCount", "raw", "int");
    const std::string args =
        scene("</Render/P>", product("P", "p.exr", "</Render/Vars/depth>, </Render/Vars/count>"), vars);
    ASSERT_EQ(render(args).exitCode, 0);
    std::string tiles;
    for (int i = 0; i < 4; ++i) {
        RunResult r = render(args, "--tile-count 2 2 --tile-index " + std::to_string(i));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        tiles += " " + tmp_.file("p_tile" + std::to_string(i) + ".exr");
    }
    RunResult r = test::runFluence("assemble -o " + tmp_.file("assembled.exr") + tiles, tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto whole = OIIO::ImageInput::open(tmp_.file("p.exr")),
         assembled = OIIO::ImageInput::open(tmp_.file("assembled.exr"));
    ASSERT_TRUE(whole && assembled);
    EXPECT_EQ(channelType(assembled->spec(), "Z"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(channelType(assembled->spec(), "count"), OIIO::TypeDesc::UINT);
    EXPECT_EQ(channelType(assembled->spec(), "R"), OIIO::TypeDesc::FLOAT);
    const test::ExrImage a = test::readExr(tmp_.file("p.exr")), b = test::readExr(tmp_.file("assembled.exr"));
    EXPECT_EQ(a.channels, b.channels);
    EXPECT_EQ(a.pixels, b.pixels);
}

TEST_F(RenderProductsCli, PrimvarVarsReadTheAuthoredValuesAtTheFirstHit) {
    const std::string vars =
        var("st", "primvars:st", "primvar", "float2") + var("colour", "displayColor", "primvar", "color3f") +
        var("k", "primvars:k", "primvar", "float") +
        var("nearest", "primvars:st", "primvar", "float2", "            uniform token fluence:filter = \"closest\"\n");
    RunResult r = render(scene(
        "</Render/P>",
        product("P", "p.exr", "</Render/Vars/st>, </Render/Vars/colour>, </Render/Vars/k>, </Render/Vars/nearest>"),
        vars));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("p.exr"));
    // Pixel (x, y) spans world x in [-2 + x/2, -1.5 + x/2] and y in [1.5 - y/2, 2 - y/2]: its mean st
    // lies within half a pixel (0.5 / 6 / 2) of its centre's.
    const float halfPixel = 0.5f / 6.0f / 2.0f;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const float wx = -2.0f + 0.5f * (float(x) + 0.5f), wy = 2.0f - 0.5f * (float(y) + 0.5f);
            ASSERT_NEAR(img.at(x, y, "st.X"), (wx + 3.0f) / 6.0f, halfPixel) << x << "," << y;
            ASSERT_NEAR(img.at(x, y, "st.Y"), (wy + 3.0f) / 6.0f, halfPixel) << x << "," << y;
            ASSERT_NEAR(img.at(x, y, "nearest.X"), (wx + 3.0f) / 6.0f, halfPixel) << x << "," << y;
            ASSERT_EQ(img.at(x, y, "k"), 0.25f);
            // Uniform: the left four columns red, the right four blue.
            ASSERT_EQ(img.at(x, y, "colour.R"), x < 4 ? 1.0f : 0.0f) << x << "," << y;
            ASSERT_EQ(img.at(x, y, "colour.B"), x < 4 ? 0.0f : 1.0f) << x << "," << y;
        }
}

TEST_F(RenderProductsCli, FirstHitVarsAreTheSameAtAnyThreadCount) {
    const std::string vars =
        var("st", "primvars:st", "primvar", "float2") +
        var("far", "depth", "raw", "float", "            uniform token fluence:filter = \"max\"\n");
    const std::string args = scene("</Render/P>", product("P", "p.exr", "</Render/Vars/st>, </Render/Vars/far>"), vars);
    RunResult r = render(args, "-j 1 -o " + tmp_.file("one.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = render(args, "-j 2 -o " + tmp_.file("two.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage one = test::readExr(tmp_.file("one.exr")), two = test::readExr(tmp_.file("two.exr"));
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    for (std::size_t i = 0; i < one.pixels.size(); ++i) ASSERT_EQ(one.pixels[i], two.pixels[i]) << i;
}

TEST_F(RenderProductsCli, HeadersHoldTheCameraMatricesAndTheColourSpace) {
    RunResult r = render(
        scene("</Render/P>", product("P", "p.exr", "</Render/Vars/depth>"), var("depth", "depth", "raw", "float")));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("p.exr"));
    // World to camera (OpenEXR: +z is the viewing direction) for row vectors: z' = 10 - z.
    const std::vector<float> expected{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 10, 1};
    const std::vector<float> toCamera = matrix(img.spec, "worldToCamera");
    ASSERT_EQ(toCamera.size(), 16u);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(toCamera[std::size_t(i)], expected[std::size_t(i)], 1e-6f) << i;
    // World to NDC: the image spans [-2, 2] at z = 0, (0, 0) its top-left corner.
    const std::vector<float> toNdc = matrix(img.spec, "worldToNDC");
    ASSERT_EQ(toNdc.size(), 16u);
    auto project = [&](float x, float y, float z) {
        float out[4];
        for (int j = 0; j < 4; ++j)
            out[j] = x * toNdc[std::size_t(j)] + y * toNdc[std::size_t(4 + j)] + z * toNdc[std::size_t(8 + j)] +
                     toNdc[std::size_t(12 + j)];
        return std::pair<float, float>{out[0] / out[3], out[1] / out[3]};
    };
    const auto centre = project(0, 0, 0), topRight = project(2, 2, 0), lowLeft = project(-1, -1, 5);
    EXPECT_NEAR(centre.first, 0.5f, 1e-6f);
    EXPECT_NEAR(centre.second, 0.5f, 1e-6f);
    EXPECT_NEAR(topRight.first, 1.0f, 1e-6f);
    EXPECT_NEAR(topRight.second, 0.0f, 1e-6f);
    EXPECT_NEAR(lowLeft.first, 0.0f, 1e-6f);  // at distance 5 the image spans [-1, 1]
    EXPECT_NEAR(lowLeft.second, 1.0f, 1e-6f);
    EXPECT_EQ(img.spec.get_string_attribute("colorInteropID"), "lin_rec709_scene");
    EXPECT_EQ(img.spec.get_string_attribute("fluence/dataChannels"), "Z");
}

TEST_F(RenderProductsCli, DataChannelsAreCompressedLosslessly) {
    const std::string lossy = "        token driver:parameters:OpenEXR:compression = \"dwaa\"\n";
    const std::string vars = var("depth", "depth", "raw", "float") + var("beauty", "C", "raw", "color3f");
    RunResult r = render(scene("</Render/Data>, </Render/Colour>",
                               product("Data", "data.exr", "</Render/Vars/depth>", lossy) +
                                   product("Colour", "colour.exr", "</Render/Vars/beauty>", lossy),
                               vars));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(test::readExr(tmp_.file("data.exr")).spec.get_string_attribute("compression"), "zip");
    EXPECT_NE(r.err.find("/Render/Data: lossy compression 'dwaa'"), std::string::npos) << r.err;
    const test::ExrImage colour = test::readExr(tmp_.file("colour.exr"));
    EXPECT_EQ(colour.spec.get_string_attribute("compression").substr(0, 4), "dwaa");
    EXPECT_EQ(colour.channels, (std::vector<std::string>{"R", "G", "B"}));  // the var writes R: no implicit beauty
}

TEST_F(RenderProductsCli, DataWindowIsTheExrDataWindow) {
    const std::string window = "        float4 dataWindowNDC = (0, 0.5, 0.5, 1)\n";  // the top-left quarter
    RunResult r = render(scene("</Render/P>", product("P", "p.exr", "</Render/Vars/depth>", window),
                               var("depth", "depth", "raw", "float")));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("p.exr"));
    EXPECT_EQ(img.spec.x, 0);
    EXPECT_EQ(img.spec.y, 0);
    EXPECT_EQ(img.spec.width, 4);
    EXPECT_EQ(img.spec.height, 4);
    EXPECT_EQ(img.spec.full_width, 8);
    EXPECT_EQ(img.spec.full_height, 8);
}

TEST_F(RenderProductsCli, FiltersPickTheSamplesValue) {
    // The farthest hit's depth (a plane facing the camera: 10 everywhere), and an unknown filter
    // warned about and replaced by box.
    const std::string vars =
        var("far", "depth", "raw", "float", "            uniform token fluence:filter = \"max\"\n") +
        var("odd", "N", "raw", "normal3f", "            uniform token fluence:filter = \"median\"\n");
    RunResult r = render(scene("</Render/P>", product("P", "p.exr", "</Render/Vars/far>, </Render/Vars/odd>"), vars));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("/Render/Vars/odd: fluence:filter 'median' is not supported"), std::string::npos) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("p.exr"));
    EXPECT_NEAR(img.at(2, 2, "far"), 10.0f, 1e-4f);
    EXPECT_NEAR(img.at(2, 2, "odd.Z"), 1.0f, 1e-5f);
}

TEST_F(RenderProductsCli, AOneComponentSourceFillsEveryChannelOfAWiderDataType) {
    // arnold-usd's tests declare depth as color3f: depth (10 everywhere, as above) is written to
    // each channel, from the film (the default min filter) and from the first-hit AOVs (max).
    const std::string vars =
        var("zc", "depth", "raw", "color3f") +
        var("zfar", "depth", "raw", "float2", "            uniform token fluence:filter = \"max\"\n");
    RunResult r = render(scene("</Render/P>", product("P", "p.exr", "</Render/Vars/zc>, </Render/Vars/zfar>"), vars));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(
        r.err.find(
            "/Render/Vars/zc: dataType color3f has 3 components; source 'depth' gives 1, which is written to each"),
        std::string::npos)
        << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("p.exr"));
    for (const char* channel : {"zc.R", "zc.G", "zc.B", "zfar.X", "zfar.Y"})
        EXPECT_NEAR(img.at(2, 2, channel), 10.0f, 1e-4f) << channel;
}

TEST_F(RenderProductsCli, AVarFluenceCannotProduceIsASceneErrorNamingIt) {
    RunResult r = render(
        scene("</Render/P>", product("P", "p.exr", "</Render/Vars/curv>"), var("curv", "curvature", "raw", "float3")));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("RenderVar /Render/Vars/curv: raw sourceName 'curvature'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("p.exr")));

    r = render(scene("</Render/P>", product("P", "p.exr", "</Render/Vars/n>"), var("n", "N", "raw", "float")));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("RenderVar /Render/Vars/n: dataType float has 1 component;"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fluence
