// Conformance: payload load rules (USD's UsdStageLoadRules): load all, load none, and per-prim
// rules where the most specific one wins and the prims above a loaded prim load too. Layers under
// tests/scene/composition/payloads/.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/stage.h"
#include "tests/scene/composition_helpers.h"

namespace fluence::usd {
namespace {

using namespace test;

// Whether the prim at `path` composed with its payload: part.usda gives it `size`, inner.usda
// gives its Inner `depth`.
bool loaded(const Stage& stage, const std::string& path) {
    const PrimSpec* prim = stage.prim(path);
    return prim && (prim->attribute("size") || prim->attribute("depth"));
}

bool markedUnloaded(const Stage& stage, const std::string& path) {
    const PrimSpec* prim = stage.prim(path);
    return prim && findMetadata(prim->metadata, "fluence:unloadedPayload");
}

std::unique_ptr<Stage> openWith(const LoadRules& rules) {
    StageOptions options;
    options.loadRules = rules;
    return open("payloads/rules.usda", options);
}

TEST(CompositionLoadRules, LoadAllIsTheDefault) {
    auto stage = open("payloads/rules.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    for (const char* path :
         {"/World/A", "/World/A/Inner", "/World/Group/C", "/World/Group/C/Inner", "/World/Group/D"}) {
        EXPECT_TRUE(loaded(*stage, path)) << path;
        EXPECT_FALSE(markedUnloaded(*stage, path)) << path;
    }
}

TEST(CompositionLoadRules, LoadNoneLeavesEveryPayloadOutAndMarksThePrims) {
    auto stage = openWith(LoadRules::loadNone());
    for (const char* path : {"/World/A", "/World/Group/C", "/World/Group/D"}) {
        EXPECT_FALSE(loaded(*stage, path)) << path;
        EXPECT_TRUE(markedUnloaded(*stage, path)) << path;
        EXPECT_TRUE(at(*stage, path).children.empty()) << path;
    }
    EXPECT_FALSE(markedUnloaded(*stage, "/World/Group"));  // no payload of its own
    EXPECT_EQ(stage->layerFiles(), (std::vector<std::string>{layer("payloads/rules.usda")}));
}

TEST(CompositionLoadRules, ALoadRuleUnderLoadNone) {
    LoadRules rules = LoadRules::loadNone();
    rules.load("/World/Group/C");
    auto stage = openWith(rules);
    EXPECT_TRUE(loaded(*stage, "/World/Group/C"));
    EXPECT_TRUE(loaded(*stage, "/World/Group/C/Inner"));  // descendants too
    EXPECT_FALSE(loaded(*stage, "/World/Group/D"));
    EXPECT_FALSE(loaded(*stage, "/World/A"));
}

TEST(CompositionLoadRules, TheMostSpecificRuleWins) {
    LoadRules rules;
    rules.unload("/World/Group");
    rules.load("/World/Group/D");
    rules.unload("/World/A/Inner");
    auto stage = openWith(rules);
    EXPECT_FALSE(loaded(*stage, "/World/Group/C"));
    EXPECT_TRUE(loaded(*stage, "/World/Group/D"));
    EXPECT_TRUE(loaded(*stage, "/World/Group/D/Inner"));
    EXPECT_TRUE(loaded(*stage, "/World/A"));
    EXPECT_FALSE(loaded(*stage, "/World/A/Inner"));
    EXPECT_TRUE(markedUnloaded(*stage, "/World/A/Inner"));  // its own, nested payload
}

TEST(CompositionLoadRules, ThePrimsAboveALoadedPrimLoad) {
    // Loading /World/A/Inner needs /World/A's payload, which brings Inner into being.
    LoadRules rules = LoadRules::loadNone();
    rules.load("/World/A/Inner");
    auto stage = openWith(rules);
    EXPECT_TRUE(loaded(*stage, "/World/A"));
    EXPECT_TRUE(loaded(*stage, "/World/A/Inner"));
    EXPECT_FALSE(loaded(*stage, "/World/Group/C"));
}

TEST(CompositionLoadRules, RulesLikeUsdStageLoadRules) {
    LoadRules rules;
    EXPECT_TRUE(rules.isLoaded("/A"));
    rules.unload("/A");
    EXPECT_FALSE(rules.isLoaded("/A"));
    EXPECT_FALSE(rules.isLoaded("/A/B"));
    EXPECT_TRUE(rules.isLoaded("/Other"));
    rules.load("/A/B/C");
    EXPECT_TRUE(rules.isLoaded("/A/B/C/D"));
    EXPECT_TRUE(rules.isLoaded("/A/B"));  // on the way to /A/B/C
    EXPECT_TRUE(rules.isLoaded("/A"));
    EXPECT_FALSE(rules.isLoaded("/A/X"));
    rules.unload("/A/B/C/D");
    EXPECT_FALSE(rules.isLoaded("/A/B/C/D"));
    EXPECT_TRUE(rules.isLoaded("/A/B/C"));
    rules.unload("/A");  // replaces the rules below it, as UsdStageLoadRules::Unload does
    EXPECT_FALSE(rules.isLoaded("/A/B/C"));
    rules.unload("/A/B");
    rules.load("/A/B/C");
    EXPECT_TRUE(rules.isLoaded("/A/B"));
    EXPECT_FALSE(rules.isLoaded("/A"));  // the rule on /A/B stands between /A and /A/B/C
    rules.load("/");
    EXPECT_TRUE(rules.isLoaded("/A/B/C"));
    EXPECT_TRUE(rules.isLoaded("/A"));
}

}  // namespace
}  // namespace fluence::usd
