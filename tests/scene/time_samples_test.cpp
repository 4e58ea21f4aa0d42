// Value resolution at USD's two special time codes: UsdTimeCode::Default() (kDefaultTime: the
// default value only, as UsdAttribute::Get) and UsdTimeCode::EarliestTime() (kEarliestTime: the
// first time sample, else the default; what Hydra renders at without a frame).
#include <gtest/gtest.h>

#include <optional>

#include "scene/stage.h"
#include "scene/usda_parser.h"

namespace fluence::usd {
namespace {

const char* kLayer = R"(#usda 1.0
def Xform "X"
{
    double samplesOnly.timeSamples = {
        4: 40,
        -3: -30,
    }
    double both = 7
    double both.timeSamples = {
        2: 20,
        5: 50,
    }
    double defaultOnly = 9
}
)";

std::optional<double> at(const Stage& stage, const char* name, double time) {
    const AttributeSpec* a = stage.prim("/X")->attribute(name);
    std::optional<Value> v = a ? Stage::resolve(*a, time) : std::nullopt;
    return v ? v->asDouble() : std::nullopt;
}

TEST(TimeSamples, TheDefaultTimeReadsOnlyTheDefaultValue) {
    Stage stage(parseUsdaString(kLayer, "t.usda"));
    EXPECT_EQ(at(stage, "samplesOnly", kDefaultTime), std::nullopt) << "OpenUSD: no default, no value";
    EXPECT_EQ(at(stage, "both", kDefaultTime), 7.0);
    EXPECT_EQ(at(stage, "defaultOnly", kDefaultTime), 9.0);
}

TEST(TimeSamples, TheEarliestTimeReadsTheFirstSampleElseTheDefault) {
    Stage stage(parseUsdaString(kLayer, "t.usda"));
    EXPECT_EQ(at(stage, "samplesOnly", kEarliestTime), -30.0) << "the sample at -3, the earliest, not the first authored";
    EXPECT_EQ(at(stage, "both", kEarliestTime), 20.0) << "samples win over the default at a numeric time";
    EXPECT_EQ(at(stage, "defaultOnly", kEarliestTime), 9.0);
    EXPECT_EQ(at(stage, "samplesOnly", 0.5), -30.0 + (0.5 + 3.0) / 7.0 * 70.0) << "a numeric time interpolates as before";
}

TEST(TimeSamples, SamplesAtInfiniteTimesHoldTheFiniteNeighbour) {
    Stage stage(parseUsdaString("#usda 1.0\ndef Xform \"X\"\n{\n"
                                "    double x.timeSamples = {-inf: 1, 4: 40, 6: 60, inf: 100}\n}\n",
                                "t.usda"));
    EXPECT_EQ(at(stage, "x", kEarliestTime), 40.0) << "the earliest time is finite: between -inf and 4";
    EXPECT_EQ(at(stage, "x", 0.0), 40.0) << "between -inf and 4";
    EXPECT_EQ(at(stage, "x", 5.0), 50.0);
    EXPECT_EQ(at(stage, "x", 1e300), 60.0) << "between 6 and inf";
}

}  // namespace
}  // namespace fluence::usd
