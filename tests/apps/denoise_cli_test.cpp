// End-to-end: `fluence render --denoise` writes the denoised beauty as RGB and keeps the noisy one
// (noisy.R/G/B, bit-identical to a render without --denoise); `fluence denoise` on a render with
// --denoise-buffers, or on tiles assembled by `fluence assemble`, gives the same image (so tiles
// leave no seam); an image without the buffers is refused, naming what is missing; a render
// product whose vars write only a half-float beauty is denoised too, its noisy copy half as well.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/exr_values.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

const std::string kCornellBox = (fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda").string();
const std::string kOptions = " -r 24 18 --spp 8 --lpe 'direct=C<RD>L' ";

class DenoiseCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_denoise_cli"};
    RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
};

TEST_F(DenoiseCli, RenderDenoiseKeepsTheNoisyBeauty) {
    RunResult r = run("render " + kCornellBox + kOptions + "-o " + tmp_.file("noisy.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run("render " + kCornellBox + kOptions + "--denoise-layers -o " + tmp_.file("denoised.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage noisy = test::readExr(tmp_.file("noisy.exr")),
                         denoised = test::readExr(tmp_.file("denoised.exr"));
    for (const char* name : {"half0.R", "half1.B", "variance.G", "noisy.R", "direct.R", "direct_noisy.R"})
        EXPECT_GE(denoised.channel(name), 0) << name;
    EXPECT_EQ(test::channelValues(denoised, {"noisy.R", "noisy.G", "noisy.B"}),
              test::channelValues(noisy, {"R", "G", "B"}));
    EXPECT_EQ(test::channelValues(denoised, {"direct_noisy.R"}), test::channelValues(noisy, {"direct.R"}));
    EXPECT_NE(test::channelValues(denoised, {"R", "G", "B"}), test::channelValues(noisy, {"R", "G", "B"}));
    EXPECT_NE(test::channelValues(denoised, {"direct.R"}), test::channelValues(noisy, {"direct.R"}));
}

TEST_F(DenoiseCli, DenoiseCommandOnBuffersAndOnAssembledTilesIsTheRendersDenoise) {
    RunResult r = run("render " + kCornellBox + kOptions + "--denoise -o " + tmp_.file("whole.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run("render " + kCornellBox + kOptions + "--denoise-buffers -o " + tmp_.file("buffers.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run("denoise " + tmp_.file("buffers.exr") + " -j 1 -o " + tmp_.file("later.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string tiles;
    for (int i = 0; i < 2; ++i) {
        r = run("render " + kCornellBox + kOptions + "--denoise --tile-count 1 2 --tile-index " + std::to_string(i) +
                " -o " + tmp_.file("part.exr"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.err.find("a tile is not denoised"), std::string::npos) << r.err;
        tiles += " " + tmp_.file("part_tile" + std::to_string(i) + ".exr");
    }
    ASSERT_EQ(run("assemble -o " + tmp_.file("assembled.exr") + tiles).exitCode, 0);
    r = run("denoise " + tmp_.file("assembled.exr") + " -o " + tmp_.file("assembled_denoised.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::vector<std::string> rgb{"R", "G", "B", "noisy.R", "noisy.G", "noisy.B"};
    const std::vector<float> whole = test::channelValues(test::readExr(tmp_.file("whole.exr")), rgb);
    EXPECT_EQ(test::channelValues(test::readExr(tmp_.file("later.exr")), rgb), whole);
    EXPECT_EQ(test::channelValues(test::readExr(tmp_.file("assembled_denoised.exr")), rgb), whole)
        << "seams between tiles";
}

TEST_F(DenoiseCli, ProductWithOnlyAHalfBeautyIsDenoisedAndKeepsItsNoisyBeautyBitForBit) {
    // The Cornell box under a render product of one var, the beauty as color3h: no albedo, N or Z
    // of its own (render --denoise adds them), and a noisy copy that must be the half values a
    // render without --denoise writes (a float copy would hold the unrounded ones).
    const std::string scene = tmp_.file("half_beauty.usda");
    std::ofstream(scene) << "#usda 1.0\n(\n    subLayers = [@" << kCornellBox << R"(@]
    renderSettingsPrimPath = "/Render/Settings"
)
over "Render"
{
    over "Settings"
    {
        rel products = </Render/Product>
    }
    def RenderProduct "Product"
    {
        rel orderedVars = </Render/Vars/Beauty>
    }
    def Scope "Vars"
    {
        def RenderVar "Beauty"
        {
            string sourceName = "Ci"
            token dataType = "color3h"
        }
    }
}
)";
    RunResult r = run("render " + scene + kOptions + "-o " + tmp_.file("plain.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run("render " + scene + kOptions + "--denoise -o " + tmp_.file("denoised.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("not denoised"), std::string::npos) << r.err;
    const test::ExrImage plain = test::readExr(tmp_.file("plain.exr")),
                         denoised = test::readExr(tmp_.file("denoised.exr"));
    ASSERT_LT(plain.channel("albedo.R"), 0) << "the product was meant to write the beauty alone";
    EXPECT_EQ(denoised.spec.channelformat(denoised.channel("noisy.R")), OIIO::TypeDesc::HALF);
    EXPECT_EQ(test::channelValues(denoised, {"noisy.R", "noisy.G", "noisy.B"}),
              test::channelValues(plain, {"R", "G", "B"}));
    EXPECT_NE(test::channelValues(denoised, {"R", "G", "B"}), test::channelValues(plain, {"R", "G", "B"}));
}

TEST_F(DenoiseCli, ImageWithoutTheBuffersIsRefused) {
    ASSERT_EQ(run("render " + kCornellBox + " -r 8 8 --spp 2 -o " + tmp_.file("plain.exr")).exitCode, 0);
    RunResult r = run("denoise " + tmp_.file("plain.exr") + " -o " + tmp_.file("out.exr"));
    EXPECT_EQ(r.exitCode, 4);
    EXPECT_NE(r.err.find("half0.R"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--denoise"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp_.file("out.exr")));
    EXPECT_EQ(run("denoise " + tmp_.file("nope.exr") + " -o " + tmp_.file("out.exr")).exitCode, 4);
    EXPECT_EQ(run("denoise " + tmp_.file("plain.exr")).exitCode, 2) << "no -o";
}

}  // namespace
}  // namespace fluence
