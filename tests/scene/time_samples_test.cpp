// Value resolution at USD's two special time codes: UsdTimeCode::Default() (kDefaultTime: the
// default value only, as UsdAttribute::Get) and UsdTimeCode::EarliestTime() (kEarliestTime: the
// first time sample, else the default; what Hydra renders at without a frame).
#include <gtest/gtest.h>

#include <optional>
#include <vector>

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
    EXPECT_EQ(at(stage, "samplesOnly", kEarliestTime), -30.0)
        << "the sample at -3, the earliest, not the first authored";
    EXPECT_EQ(at(stage, "both", kEarliestTime), 20.0) << "samples win over the default at a numeric time";
    EXPECT_EQ(at(stage, "defaultOnly", kEarliestTime), 9.0);
    EXPECT_EQ(at(stage, "samplesOnly", 0.5), -30.0 + (0.5 + 3.0) / 7.0 * 70.0)
        << "a numeric time interpolates as before";
}

TEST(TimeSamples, SamplesAtInfiniteTimesHoldTheFiniteNeighbour) {
    Stage stage(
        parseUsdaString("#usda 1.0\ndef Xform \"X\"\n{\n"
                        "    double x.timeSamples = {-inf: 1, 4: 40, 6: 60, inf: 100}\n}\n",
                        "t.usda"));
    EXPECT_EQ(at(stage, "x", kEarliestTime), 40.0) << "the earliest time is finite: between -inf and 4";
    EXPECT_EQ(at(stage, "x", 0.0), 40.0) << "between -inf and 4";
    EXPECT_EQ(at(stage, "x", 5.0), 50.0);
    EXPECT_EQ(at(stage, "x", 1e300), 60.0) << "between 6 and inf";
}

TEST(TimeSamples, FloatingPointTypesInterpolateAndIntegersAreHeld) {
    // Sdf interpolates every floating-point type linearly (point3f[] too, whose name holds "int")
    // and holds integers and bools.
    Stage stage(
        parseUsdaString("#usda 1.0\ndef Xform \"X\"\n{\n"
                        "    point3f[] p.timeSamples = {0: [(0, 0, 0), (1, 2, 3)], 2: [(2, 0, 0), (3, 2, 5)]}\n"
                        "    int[] i.timeSamples = {0: [0, 10], 2: [2, 20]}\n"
                        "    uint u.timeSamples = {0: 0, 2: 2}\n"
                        "    int64 l.timeSamples = {0: 0, 2: 2}\n"
                        "    bool b.timeSamples = {0: 0, 2: 1}\n"
                        "    color3f c.timeSamples = {0: (0, 0, 0), 2: (1, 1, 1)}\n}\n",
                        "t.usda"));
    auto numbers = [&](const char* name) {
        const NumberArray n = Stage::resolve(*stage.prim("/X")->attribute(name), 1.0)->numbers;
        return std::vector<double>(n.begin(), n.end());
    };
    EXPECT_EQ(numbers("p"), (std::vector<double>{1, 0, 0, 2, 2, 4}));
    EXPECT_EQ(numbers("c"), (std::vector<double>{0.5, 0.5, 0.5}));
    EXPECT_EQ(numbers("i"), (std::vector<double>{0, 10}));
    for (const char* held : {"u", "l", "b"}) EXPECT_EQ(numbers(held), (std::vector<double>{0})) << held;
}

}  // namespace
}  // namespace fluence::usd
