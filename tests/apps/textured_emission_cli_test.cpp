// End-to-end: a quad whose UsdPreviewSurface emissiveColor is a UsdUVTexture renders its texture
// (no longer its constant value), and a missing emission texture is an error naming the file
// (exit 4, as every missing asset), with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <tuple>

#include "core/rgb.h"
#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"
#include "tests/support/usd_scenes.h"
#include "tests/texture/image_writer.h"

namespace fluence {
namespace {

class TexturedEmissionCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_textured_emission_cli"};

    // The textured quad (tests/support/usd_scenes.h) with its texture on emissiveColor instead of
    // diffuseColor, a black diffuse and no sphere light: all the light is the texture's.
    std::string emissiveQuad(const std::string& texture) {
        std::string usda = test::texturedQuadUsda(texture);
        auto replace = [&](const std::string& from, const std::string& to) {
            const std::size_t at = usda.find(from);
            EXPECT_NE(at, std::string::npos) << from;
            if (at != std::string::npos) usda.replace(at, from.size(), to);
        };
        replace("color3f inputs:diffuseColor.connect",
                "color3f inputs:diffuseColor = (0, 0, 0)\n"
                "            color3f inputs:emissiveColor.connect");
        replace("def SphereLight \"L\"", "def Xform \"L\"");  // its shape would hide the quad
        const std::string path = tmp_.file("screen.usda");
        std::ofstream(path) << usda;
        return path;
    }
};

TEST_F(TexturedEmissionCli, AnEmissiveQuadShowsItsTexture) {
    // Top-left red, top-right green, bottom-left blue, bottom-right white (linear).
    test::writeImage<float>(tmp_.file("quadrants.exr"), 2, 2, 3, OIIO::TypeDesc::FLOAT,
                            {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
    const std::string scene = emissiveQuad("./quadrants.exr");
    test::RunResult r = test::runFluence("render " + scene + " -r 16 16 --spp 4 -o " + tmp_.file("q.exr"), tmp_.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("not rendered yet"), std::string::npos) << r.err;
    const test::ExrImage img = test::readExr(tmp_.file("q.exr"));
    auto rgb = [&](int x, int y) { return RGB(img.at(x, y, "R"), img.at(x, y, "G"), img.at(x, y, "B")); };
    // Pixel centres inside each quadrant: each channel within 0.15 of the texel (bilinear filtering
    // over the pixel's footprint blends in a little of the neighbouring texels of this 2 x 2 image).
    for (const auto& [x, y, expected] : {std::tuple{4, 4, RGB(1, 0, 0)}, std::tuple{11, 4, RGB(0, 1, 0)},
                                         std::tuple{4, 11, RGB(0, 0, 1)}, std::tuple{11, 11, RGB(1, 1, 1)}})
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb(x, y)[c], expected[c], 0.15f) << x << ", " << y << " channel " << c;
}

TEST_F(TexturedEmissionCli, AMissingEmissionTextureIsAnErrorNamingTheFile) {
    const std::string scene = emissiveQuad("./no_such_screen.png");
    test::RunResult r = test::runFluence("render " + scene + " -r 8 8 --spp 1 -o " + tmp_.file("m.exr"), tmp_.path());
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("/World/Mat/Tex.inputs:file: missing asset"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no_such_screen.png"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(tmp_.file("m.exr")));
}

}  // namespace
}  // namespace fluence
