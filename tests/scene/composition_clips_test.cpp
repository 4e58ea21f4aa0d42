// Conformance: value clips (USD's `clips` metadata, UsdClipsAPI and the "Value Clips" chapter).
// Each composed attribute's time samples are checked against USD's clip semantics: which clip is
// active when, the stage-to-clip time curve with its jumps, the manifest, gaps, templates, layer
// offsets and strength. Layers under tests/scene/composition/clips/.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "tests/scene/composition_helpers.h"

namespace fluence::usd {
namespace {

using namespace test;

// USD's UsdTimeCode::SafeStep(): the left side of a jump is held this much before it.
constexpr double kSafeStep = std::numeric_limits<double>::epsilon() * 1e6 * 10.0 * 2.0;
constexpr double kBlock = std::numeric_limits<double>::quiet_NaN();

// (time, value) of a scalar attribute's time samples, a value block as kBlock.
std::vector<std::pair<double, double>> clipSamples(const PrimSpec& prim, const std::string& name) {
    std::vector<std::pair<double, double>> out;
    for (const auto& [time, value] : attribute(prim, name).timeSamples)
        out.emplace_back(time, value.isBlocked() ? kBlock : *value.asDouble());
    return out;
}

void expectSamples(const PrimSpec& prim, const std::string& name,
                   const std::vector<std::pair<double, double>>& expected) {
    auto actual = clipSamples(prim, name);
    ASSERT_EQ(actual.size(), expected.size()) << prim.path << "." << name;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_DOUBLE_EQ(actual[i].first, expected[i].first) << name << " sample " << i;
        if (std::isnan(expected[i].second))
            EXPECT_TRUE(std::isnan(actual[i].second)) << name << " sample " << i << " is not a value block";
        else
            EXPECT_NEAR(actual[i].second, expected[i].second, 1e-6) << name << " sample " << i;
    }
}

std::optional<double> valueAt(const PrimSpec& prim, const std::string& name, double time) {
    auto value = Stage::resolve(attribute(prim, name), time);
    return value ? value->asDouble() : std::nullopt;
}

TEST(CompositionClips, ActiveClipsAndTheTimeCurveWithAJump) {
    auto stage = open("clips/root.usda");
    const PrimSpec& anim = at(*stage, "/World/Anim");
    // clip1 is active before 10, clip2 from 10; times [(0, 0), (10, 10), (10, 0), (20, 10)] jumps
    // back to clip time 0 at stage time 10. Samples: every `times` stage time (the jump's left side a
    // safe step early), each clip's activation time and its samples mapped to stage time.
    expectSamples(anim, "a", {{0, 0}, {10 - kSafeStep, 10 - kSafeStep}, {10, 100}, {20, 110}});
    EXPECT_NEAR(*valueAt(anim, "a", 5), 5, 1e-6);
    EXPECT_EQ(valueAt(anim, "a", 15), 105.0);
    EXPECT_EQ(valueAt(anim, "a", 25), 110.0);
    // Clips never give defaults; the clip layer's own default (555) is ignored.
    EXPECT_EQ(valueAt(anim, "a", kDefaultTime), std::nullopt);
}

TEST(CompositionClips, DescendantsReadTheClipsThroughPrimPath) {
    auto stage = open("clips/root.usda");
    // /World/Anim/Child.b is /Model/Child.b in the clips. clip2 has no samples for it and the
    // manifest no default: a value block while clip2 is active.
    const PrimSpec& child = at(*stage, "/World/Anim/Child");
    expectSamples(child, "b", {{0, 100}, {10 - kSafeStep, 100}, {10, kBlock}, {20, kBlock}});
    EXPECT_EQ(valueAt(child, "b", 5), 100.0);
    EXPECT_EQ(valueAt(child, "b", 12), std::nullopt);
}

TEST(CompositionClips, TheManifestDeclaresWhatClipsHold) {
    auto stage = open("clips/root.usda");
    const PrimSpec& anim = at(*stage, "/World/Anim");
    // `c` is in no clip: the manifest's default 42 at every sample time.
    expectSamples(anim, "c", {{0, 42}, {10 - kSafeStep, 42}, {10, 42}, {20, 42}});
    EXPECT_EQ(number(anim, "c"), -1.0);  // the default time still reads base.usda's default
    // Samples of attributes the manifest leaves out, or declares uniform, are not used.
    EXPECT_TRUE(attribute(anim, "undeclared").timeSamples.empty());
    EXPECT_TRUE(attribute(anim, "u").timeSamples.empty());
    EXPECT_EQ(valueAt(anim, "u", 0), 7.0);
    EXPECT_EQ(findMetadata(anim.metadata, "clips"), nullptr);  // consumed, as USD's flatten does
}

TEST(CompositionClips, ClipsAreWeakerThanTheirLayerAndStrongerThanReferences) {
    auto stage = open("clips/root.usda");
    const PrimSpec& anim = at(*stage, "/World/Anim");
    // A default in the anchoring layer wins over the clips at every time.
    EXPECT_TRUE(attribute(anim, "localWins").timeSamples.empty());
    EXPECT_EQ(valueAt(anim, "localWins", 5), 1.0);
    // The clips win over base.usda's samples (a reference) and weak.usda's (a weaker sublayer).
    EXPECT_EQ(valueAt(anim, "a", 0), 0.0);
    EXPECT_EQ(valueAt(anim, "c", 0), 42.0);
}

TEST(CompositionClips, LayerOffsetsMoveActiveAndTimes) {
    auto stage = open("clips/root.usda");
    // shifted.usda (offset 100) authors the clip set: stage times 0 and 10 become 100 and 110.
    expectSamples(at(*stage, "/World/Shifted"), "a", {{100, 0}, {110, 10}});
}

TEST(CompositionClips, TemplateClipsUseTheFilesThatExist) {
    auto stage = open("clips/root.usda");
    // sim.#.usda from 1 to 4: sim.1, sim.2 and sim.4 exist. sim.2 has no samples for x: a block
    // while it is active (from 2 to 4).
    const PrimSpec& gaps = at(*stage, "/World/Gaps");
    expectSamples(gaps, "x", {{1, 1}, {2, kBlock}, {4, 4}});
    EXPECT_EQ(valueAt(gaps, "x", 3), std::nullopt);
    // interpolateMissingClipValues: sim.2 is bridged by its neighbours.
    const PrimSpec& bridged = at(*stage, "/World/Bridged");
    expectSamples(bridged, "x", {{1, 1}, {4, 4}});
    EXPECT_EQ(valueAt(bridged, "x", 2), 2.0);
    EXPECT_EQ(valueAt(bridged, "x", 3), 3.0);
}

TEST(CompositionClips, TemplateActiveOffsetShiftsActivation) {
    auto stage = open("clips/root.usda");
    // templateActiveOffset 0.5: active [(1.5, 0), (2.5, 1), (4.5, 2)], times [(0.5, 0.5), (1, 1),
    // (2, 2), (4, 4), (4.5, 4.5)].
    expectSamples(at(*stage, "/World/Offset"), "x",
                  {{0.5, 1}, {1, 1}, {1.5, 1}, {2, 1}, {2.5, kBlock}, {4, kBlock}, {4.5, 4}});
}

TEST(CompositionClips, AMissingClipFileIsAWarningNamingIt) {
    auto stage = open("clips/root.usda");
    ASSERT_EQ(stage->warnings().size(), 1u) << allWarnings(*stage);
    const CompositionWarning& w = stage->warnings()[0];
    EXPECT_EQ(w.message, "clip @./no_such_clip.usda@ ignored: cannot find '" + layer("clips/no_such_clip.usda") + "'");
    EXPECT_EQ(w.location.str(), locate("clips/root.usda",
                                       "clips = {\n            dictionary default = {\n"
                                       "                asset[] assetPaths = [@./clip1.usda@, @./no"));
    EXPECT_EQ(w.primPath, "/World/Missing");
    // The missing clip gives no samples; the other one still does.
    expectSamples(at(*stage, "/World/Missing"), "a", {{0, 0}, {10, kBlock}});
    // Clip layers are layers of the stage; the missing one is an unresolved asset.
    std::vector<std::string> files = stage->layerFiles();
    EXPECT_NE(std::find(files.begin(), files.end(), layer("clips/sim.4.usda")), files.end());
    std::vector<AssetReference> assets = stage->assetReferences();
    ASSERT_FALSE(assets.empty());
    EXPECT_EQ(assets.back().property, "clips");
    EXPECT_EQ(assets.back().resolved, layer("clips/no_such_clip.usda"));
}

// Several clip sets: on one prim, `clipSets` (in the layer stack that authors them) orders them,
// name order by default; a prim's own sets are stronger than its ancestors'.
TEST(CompositionClips, ClipSetOrder) {
    Stage stage(parseUsdaString(R"(#usda 1.0
def "ByName" (
    clips = {
        dictionary two = {
            asset[] assetPaths = [@./clip2.usda@]
            double2[] active = [(0, 0)]
            string primPath = "/Model"
        }
        dictionary one = {
            asset[] assetPaths = [@./clip1.usda@]
            double2[] active = [(0, 0)]
            string primPath = "/Model"
        }
    }
)
{
    double a
}

def "Listed" (
    clips = {
        dictionary two = {
            asset[] assetPaths = [@./clip2.usda@]
            double2[] active = [(0, 0)]
            string primPath = "/Model"
        }
        dictionary one = {
            asset[] assetPaths = [@./clip1.usda@]
            double2[] active = [(0, 0)]
            string primPath = "/Model"
        }
    }
    clipSets = ["two", "one"]
)
{
    double a
}

def "Parent" (
    clips = {
        dictionary default = {
            asset[] assetPaths = [@./clip1.usda@]
            double2[] active = [(0, 0)]
            string primPath = "/Model"
        }
    }
)
{
    def "Child" (
        clips = {
            dictionary own = {
                asset[] assetPaths = [@./clip1.usda@]
                double2[] active = [(50, 0)]
                double2[] times = [(50, 0)]
                string primPath = "/Model/Child"
            }
        }
    )
    {
        double b
    }
}
)",
                                layer("clips/inline.usda")));
    EXPECT_TRUE(stage.warnings().empty()) << allWarnings(stage);
    expectSamples(at(stage, "/ByName"), "a", {{0, 0}, {10, 10}});     // "one" (clip1) before "two"
    expectSamples(at(stage, "/Listed"), "a", {{0, 100}, {10, 110}});  // clipSets puts "two" first
    expectSamples(at(stage, "/Parent/Child"), "b", {{50, 100}});      // its own set, not /Parent's
}

}  // namespace
}  // namespace fluence::usd
