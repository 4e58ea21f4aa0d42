// Conformance: time codes per second across layers (USD's SdfLayer::GetTimeCodesPerSecond and
// Pcp's layer-offset scaling). A sublayer, reference or payload whose layer runs at another rate
// than the layer that brings it in is scaled by (that layer's rate / its own rate) before its
// authored offset applies; the rate is timeCodesPerSecond, else framesPerSecond, else 24. Layers
// under tests/scene/composition/time_codes/.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "tests/scene/composition_helpers.h"

namespace fluence::usd {
namespace {

using namespace test;
using Samples = std::vector<std::pair<double, double>>;

TEST(CompositionTimeCodes, SublayersAtAnotherRateAreScaledToTheRoot) {
    auto stage = open("time_codes/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& world = at(*stage, "/World");
    // rate48.usda: timeCodesPerSecond 48 (its framesPerSecond 12 does not count): t * 24 / 48.
    EXPECT_EQ(samples(world, "rate48"), (Samples{{0, 0}, {24, 1}}));
    EXPECT_EQ(Stage::resolve(attribute(world, "rate48"), 12.0)->asDouble(), 0.5);
    // rate96.usda under rate48.usda (offset 8, in rate48's time codes): (96 * 48 / 96 + 8) * 24 / 48.
    EXPECT_EQ(samples(world, "rate96"), (Samples{{28, 1}}));
    // fps12.usda: only framesPerSecond 12, so t * 24 / 12, then its offset 10.
    EXPECT_EQ(samples(world, "fps12"), (Samples{{22, 1}}));
}

TEST(CompositionTimeCodes, ReferencesAndPayloadsScaleBeforeTheirOffset) {
    auto stage = open("time_codes/root.usda");
    // asset48.usda (48 per second) referenced with offset 5, scale 2: (t * 24 / 48) * 2 + 5.
    EXPECT_EQ(samples(at(*stage, "/World/Referenced"), "spin"), (Samples{{53, 1}, {101, 2}}));
    EXPECT_EQ(samples(at(*stage, "/World/Payloaded"), "spin"), (Samples{{24, 1}, {48, 2}}));
    // An internal reference stays in its layer stack: nothing to scale.
    EXPECT_EQ(samples(at(*stage, "/World/Internal"), "local"), (Samples{{48, 1}}));
}

TEST(CompositionTimeCodes, StartAndEndTimeCodesAreTheRootLayersUnscaled) {
    auto stage = open("time_codes/root.usda");
    EXPECT_EQ(stage->startTimeCode(), 12.0);  // rate48.usda's 100 and 200 are not the stage's
    EXPECT_EQ(stage->endTimeCode(), 48.0);
}

TEST(CompositionTimeCodes, TheReferencingLayersRateCountsToo) {
    // A root layer at 48 time codes per second: a 24-per-second asset's samples double, a
    // 48-per-second asset's stay.
    Stage stage(parseUsdaString(R"(#usda 1.0
(
    timeCodesPerSecond = 48
)

def "Slow" (
    references = @./asset24.usda@
)
{
}

def "Same" (
    references = @./asset48.usda@
)
{
}
)",
                                layer("time_codes/inline.usda")));
    EXPECT_TRUE(stage.warnings().empty()) << allWarnings(stage);
    EXPECT_EQ(samples(at(stage, "/Slow"), "spin"), (Samples{{48, 1}}));
    EXPECT_EQ(samples(at(stage, "/Same"), "spin"), (Samples{{48, 1}, {96, 2}}));
}

}  // namespace
}  // namespace fluence::usd
