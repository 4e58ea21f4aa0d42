// Collection-based material bindings end to end (delegate/material_binding.h): arnold-usd's
// test_1524 binds its crowd agent's head, body and legs by four `material:binding:collection:*`
// relationships on /crowd, each an explicitOnly collection naming the meshes at their
// instance-proxy paths. Rendered, each part shows its own material's colour, as in Arnold's
// reference image (red head, green body, blue left leg, pink right leg); without the collection
// bindings every part was the default grey.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/support/cli.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

// The hue of a pixel by which channels dominate: each material is a pure mix of two channels.
enum class Hue { Red, Green, Azure, Rose, Other };

Hue hueOf(float r, float g, float b) {
    const float top = std::max({r, g, b});
    if (!(top > 0.02f)) return Hue::Other;
    auto low = [&](float c) { return c < 0.15f * top; };
    auto half = [&](float c) { return c > 0.25f * top && c < 0.75f * top; };
    if (r == top && low(g) && low(b)) return Hue::Red;
    if (g == top && low(r) && low(b)) return Hue::Green;
    if (b == top && half(g) && low(r)) return Hue::Azure;  // legL (0, 0.5, 1)
    if (r == top && half(b) && low(g)) return Hue::Rose;   // legR (1, 0, 0.5)
    return Hue::Other;
}

TEST(MaterialBindingCli, Test1524sCollectionBindingsGiveEachPartItsColour) {
    test::TempDir tmp("fluence_binding_cli");
    const std::string scene = FLUENCE_SOURCE_DIR "/tests/corpus/arnold-usd/testsuite/test_1524/data/test.usd";
    const test::RunResult r =
        test::runFluence("render '" + scene + "' -r 160 120 --spp 4 -o '" + tmp.file("crowd.exr") + "'", tmp.path());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("ignored, the next binding applies"), std::string::npos) << r.err;
    const test::ExrImage image = test::readExr(tmp.file("crowd.exr"));
    int count[5] = {0, 0, 0, 0, 0};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            ++count[int(hueOf(image.at(x, y, "R"), image.at(x, y, "G"), image.at(x, y, "B")))];
    // At 160 x 120 the figure is about 80 pixels tall: a head about 10 across, a body 8 x 30,
    // legs 2 to 3 pixels wide and 20 tall (Arnold's reference, scaled).
    EXPECT_GT(count[int(Hue::Red)], 40) << "head";
    EXPECT_GT(count[int(Hue::Green)], 120) << "body";
    EXPECT_GT(count[int(Hue::Azure)], 15) << "left leg";
    EXPECT_GT(count[int(Hue::Rose)], 15) << "right leg";
}

}  // namespace
}  // namespace fluence
