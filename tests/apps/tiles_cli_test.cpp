// End-to-end: an image rendered as tiles (--tile-count, --tile-index) and merged by
// `fluence assemble` is bit-identical to the image rendered in one piece, with adaptive sampling
// and light path expression layers too; tiles that do not make one image are refused and leave
// nothing behind.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

const std::string kCornellBox = (fs::path(FLUENCE_SOURCE_DIR) / "usd_samples/cornell_box.usda").string();
const std::string kOptions = " -r 21 15 --spp 8 --target-error 0.05 --min-spp 4 --lpe 'direct=C<RD>L' ";

class TilesCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_tiles_cli"};
    RunResult run(const std::string& args) { return test::runFluence(args, tmp_.path()); }
};

TEST_F(TilesCli, AssembledTilesAreTheImageRenderedInOnePiece) {
    RunResult r = run("render " + kCornellBox + kOptions + "-o " + tmp_.file("whole.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string tiles;
    for (int i = 0; i < 6; ++i) {
        r = run("render " + kCornellBox + kOptions + "--tile-count 3 2 --tile-index " + std::to_string(i) + " -o " +
                tmp_.file("part.exr"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const std::string tile = tmp_.file("part_tile" + std::to_string(i) + ".exr");
        ASSERT_TRUE(fs::exists(tile)) << tile;
        tiles += " " + tile;
    }
    r = run("assemble -o " + tmp_.file("assembled.exr") + tiles);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::ExrImage whole = test::readExr(tmp_.file("whole.exr")),
                         assembled = test::readExr(tmp_.file("assembled.exr"));
    ASSERT_EQ(assembled.width, whole.width);
    ASSERT_EQ(assembled.height, whole.height);
    ASSERT_EQ(assembled.channels, whole.channels);
    EXPECT_GE(whole.channel("direct.R"), 0);
    EXPECT_TRUE(assembled.pixels == whole.pixels) << "tiles differ from the render in one piece";
}

TEST_F(TilesCli, TilesThatDoNotMakeOneImageAreRefused) {
    for (int i : {0, 1})
        ASSERT_EQ(run("render " + kCornellBox + " -r 8 8 --spp 1 --tile-count 2 1 --tile-index " + std::to_string(i) +
                      " -o " + tmp_.file("t.exr"))
                      .exitCode,
                  0);
    RunResult r = run("assemble -o " + tmp_.file("out.exr") + " " + tmp_.file("t_tile0.exr"));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("a tile is missing"), std::string::npos) << r.err;
    r = run("assemble -o " + tmp_.file("out.exr") + " " + tmp_.file("t_tile0.exr") + " " + tmp_.file("t_tile0.exr"));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("overlaps"), std::string::npos) << r.err;
    r = run("assemble -o " + tmp_.file("out.exr") + " " + tmp_.file("t_tile0.exr") + " " + tmp_.file("nope.exr"));
    EXPECT_EQ(r.exitCode, 4);
    EXPECT_FALSE(fs::exists(tmp_.file("out.exr")));

    EXPECT_EQ(run("render " + kCornellBox + " --tile-count 2 2 --tile-index 4").exitCode, 2);
    EXPECT_EQ(run("assemble " + tmp_.file("t_tile0.exr")).exitCode, 2) << "no -o";
}

}  // namespace
}  // namespace fluence
