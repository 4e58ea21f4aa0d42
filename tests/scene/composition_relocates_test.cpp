// Conformance: relocates (USD's `relocates` layer metadata, and prim metadata in older files). A
// relocation moves a prim that an arc brings in to a new path: the target composes from the
// source's arcs plus its own local opinions, opinions at the source are ignored, the source's
// name leaves its parent, and paths into the moved namespace follow it. Invalid and colliding
// relocations are warnings. Layers under tests/scene/composition/relocates/.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "tests/scene/composition_helpers.h"

namespace fluence::usd {
namespace {

using namespace test;
using Names = std::vector<std::string>;

TEST(CompositionRelocates, APrimMovesOutOfAReferencedNamespace) {
    auto stage = open("relocates/root.usda");
    const PrimSpec& arm = at(*stage, "/World/Arm");
    EXPECT_EQ(arm.specifier, Specifier::Def);
    EXPECT_EQ(arm.typeName, "Xform");       // from rig.usda's /Rig/Arm
    EXPECT_EQ(number(arm, "length"), 1.0);  // the `over` at the source is ignored
    EXPECT_EQ(number(arm, "extra"), 5.0);   // local opinions at the target apply
    EXPECT_EQ(arm.location.str(), locate("relocates/rig.usda", "def Xform \"Arm\""));
    EXPECT_EQ(stage->prim("/World/Char/Arm"), nullptr);
    // The source's name leaves its parent (even though root.usda still has an `over` for it);
    // targets join theirs, relocated names first, in name order.
    EXPECT_EQ(childNames(at(*stage, "/World/Char")), (Names{"Limb"}));
    EXPECT_EQ(childNames(at(*stage, "/World")), (Names{"Arm", "Hand", "WrappedLeg", "Char", "Wrapped"}));
}

TEST(CompositionRelocates, OpinionsAtTheSourceAreReported) {
    auto stage = open("relocates/root.usda");
    ASSERT_EQ(stage->warnings().size(), 1u) << allWarnings(*stage);
    const CompositionWarning& w = stage->warnings()[0];
    EXPECT_EQ(w.message, "opinions at </World/Char/Arm> are ignored: relocates move that prim to </World/Arm>");
    EXPECT_EQ(w.location.str(), locate("relocates/root.usda", "over \"Arm\"\n        {\n            double length"));
    EXPECT_EQ(w.primPath, "/World/Arm");
}

TEST(CompositionRelocates, RenamesRemovalsAndChains) {
    auto stage = open("relocates/root.usda");
    // A rename under the same parent keeps its place.
    EXPECT_EQ(number(at(*stage, "/World/Char/Limb"), "length"), 2.0);
    EXPECT_EQ(stage->prim("/World/Char/Leg"), nullptr);
    // An empty target removes the prim.
    EXPECT_EQ(stage->prim("/World/Char/Prop"), nullptr);
    // A relocation from inside a relocated prim: /World/Arm/Hand (itself from /World/Char/Arm/Hand).
    EXPECT_EQ(number(at(*stage, "/World/Hand"), "size"), 1.0);
    EXPECT_TRUE(at(*stage, "/World/Arm").children.empty());
}

TEST(CompositionRelocates, PathsIntoTheMovedNamespaceFollowIt) {
    auto stage = open("relocates/root.usda");
    // rig.usda's </Rig/Arm/Hand>: referenced to /World/Char/Arm/Hand, relocated twice.
    EXPECT_EQ(at(*stage, "/World/Arm").relationship("grip")->targets, (Names{"/World/Hand"}));
}

TEST(CompositionRelocates, ARelocationInsideAReferencedAssetComesAlong) {
    auto stage = open("relocates/root.usda");
    // relocating_asset.usda moves its /Outer/Inner/Arm to /Outer/Arm.
    EXPECT_EQ(number(at(*stage, "/World/Wrapped/Arm"), "length"), 1.0);
    EXPECT_EQ(at(*stage, "/World/Wrapped/Arm").relationship("grip")->targets, (Names{"/World/Wrapped/Arm/Hand"}));
    EXPECT_EQ(number(at(*stage, "/World/Wrapped/Arm/Hand"), "size"), 1.0);
    // ... and the stage relocates from that asset's namespace in turn.
    EXPECT_EQ(number(at(*stage, "/World/WrappedLeg"), "length"), 2.0);
    EXPECT_EQ(childNames(at(*stage, "/World/Wrapped/Inner")), (Names{"Prop"}));
}

TEST(CompositionRelocates, PrimMetadataRelocatesOfOlderFiles) {
    auto stage = open("relocates/legacy.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    EXPECT_EQ(number(at(*stage, "/World/Arm"), "length"), 1.0);
    EXPECT_EQ(childNames(at(*stage, "/World")), (Names{"Arm", "Char"}));
    EXPECT_EQ(childNames(at(*stage, "/World/Char")), (Names{"Leg", "Prop"}));
    EXPECT_EQ(findMetadata(at(*stage, "/World").metadata, "relocates"), nullptr);  // consumed
}

TEST(CompositionRelocates, InvalidAndCollidingRelocationsAreWarnings) {
    auto stage = open("relocates/invalid.usda");
    const std::string where = locate("relocates/invalid.usda", "relocates");
    const std::vector<std::string> expected = {
        "relocate </World> -> </Elsewhere> ignored: a root prim cannot be relocated",
        "relocate </World/Char/Arm> -> </World/Char/Arm/Hand/Deeper> ignored: the target cannot be a descendant of its "
        "source",
        "relocate </World/Char/Hat> -> </World/Char> ignored: the target cannot be an ancestor of its source",
        "relocate </World/Char/Prop> -> </World/Char/Prop> ignored: the target is the source itself",
        "relocate </World/Other/Arm/Hand> -> </World/OtherHand> ignored: the source lies below </World/Other/Arm>, "
        "which "
        "is itself relocated",
        "relocate </World/Other/Leg> -> </World/Same> ignored: another relocation moves a prim to the same target",
        "relocate </World/Other/Prop> -> </World/Same> ignored: another relocation moves a prim to the same target",
        "relocate </World/Char/Leg> -> </World/Char/Ghost> ignored: the target is the source of relocate "
        "</World/Char/Ghost>",
        "relocate </World/Char/Ghost> -> </World/Ghost> ignored: the source is the target of relocate "
        "</World/Char/Leg>",
        "relocate </World/Char/Hand> -> </World/Other/Arm/Elbow> ignored: the target lies below </World/Other/Arm>, "
        "which is itself relocated",
    };
    ASSERT_EQ(stage->warnings().size(), expected.size()) << allWarnings(*stage);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(stage->warnings()[i].message, expected[i]);
        EXPECT_EQ(stage->warnings()[i].location.str(), where);
    }
    // The one valid relocation applies; the rejected ones leave their prims in place.
    EXPECT_EQ(number(at(*stage, "/World/OtherArm"), "length"), 1.0);
    EXPECT_EQ(childNames(at(*stage, "/World/Other")), (Names{"Leg", "Prop"}));
    EXPECT_EQ(childNames(at(*stage, "/World/Char")), (Names{"Arm", "Leg", "Prop"}));
    EXPECT_EQ(childNames(at(*stage, "/World")), (Names{"OtherArm", "Char", "Other"}));
}

TEST(CompositionRelocates, ARelocationThatNeedsItselfIsACycle) {
    // Composing /P needs /Q/y/p, so /Q/y, which is relocated from /P/x, so /P.
    Stage stage(parseUsdaString(R"(#usda 1.0
(
    relocates = {
        </Q/y/p>: </P>,
        </P/x>: </Q/y>
    }
)

def "Q"
{
}
)",
                                "cycle.usda"));
    EXPECT_FALSE(warningsWith(stage, "relocation cycle").empty()) << allWarnings(stage);
    EXPECT_NE(stage.prim("/Q"), nullptr);
}

}  // namespace
}  // namespace fluence::usd
