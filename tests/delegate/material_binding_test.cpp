// Material binding resolution (delegate/material_binding.h): direct and collection-based bindings,
// their strength and purpose, as UsdShadeMaterialBindingAPI's "Material Resolution" rules say. Each
// expected material below is worked out from those rules in the comment beside it, not read from
// the code.
#include <gtest/gtest.h>

#include <algorithm>

#include "delegate/material_binding.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

// Materials named after their colours; they shade nothing (only their paths are bound here).
const std::string kLooks = R"(
def Scope "Looks"
{
    def Material "Red" {}
    def Material "Green" {}
    def Material "Blue" {}
    def Material "Gold" {}
    def Material "White" {}
    def Material "Final" {}
}
)";

const std::string kWorld = R"(
def Xform "World" (
    prepend apiSchemas = ["MaterialBindingAPI", "CollectionAPI:metal", "CollectionAPI:plastic", "CollectionAPI:glass", "CollectionAPI:exact"]
)
{
    rel material:binding = </Looks/Green>
    rel material:binding:collection:plastic = [</World.collection:plastic>, </Looks/Blue>]
    rel material:binding:collection:metal = [</World.collection:metal>, </Looks/Gold>]
    rel material:binding:collection:glass = [</Looks/White>, </World.collection:glass>] (
        bindMaterialAs = "strongerThanDescendants"
    )
    rel material:binding:collection:exact = [</World.collection:exact>, </Looks/Red>]
    rel collection:metal:includes = [</World/Chair/Back>, </World/Lamp>]
    rel collection:plastic:includes = [</World/Chair/Back/Brace/Rivet>, </World/Table>]
    rel collection:plastic:excludes = [</World/Table/Leg>]
    rel collection:glass:includes = [</World/Lamp/Shade>]
    uniform token collection:exact:expansionRule = "explicitOnly"
    uniform bool collection:exact:includeRoot = true
    rel collection:exact:includes = [</World/Shelf>]

    def Xform "Chair"
    {
        def Xform "Back"
        {
            def Xform "Brace"
            {
                def Mesh "Rivet" {}
            }
        }
        def Mesh "Seat" {}
    }
    def Xform "Table"
    {
        def Mesh "Top" {}
        def Mesh "Leg" {}
    }
    def Xform "Lamp"
    {
        rel material:binding = </Looks/Red>
        def Mesh "Base" {}
        def Mesh "Shade"
        {
            rel material:binding = </Looks/Blue>
        }
    }
    def Xform "Shelf"
    {
        def Mesh "Book" {}
    }
    def Xform "Box"
    {
        rel material:binding = </Looks/Gold> (bindMaterialAs = "strongerThanDescendants")
        def Mesh "Lid"
        {
            rel material:binding = </Looks/Red>
        }
    }
    def Xform "Crate"
    {
        rel material:binding:full = </Looks/Final>
        def Mesh "Slat"
        {
            rel material:binding = </Looks/Red>
        }
    }
}
def Xform "Yard" (prepend apiSchemas = ["CollectionAPI:all"])
{
    rel material:binding:collection:all = [</Yard.collection:all>, </Looks/White>]
    uniform bool collection:all:includeRoot = true
    def Xform "Shed"
    {
        def Mesh "Door"
        {
            rel material:binding = </Looks/Red>
        }
    }
}
)";

std::string bound(const usd::Stage& stage, const std::string& path) {
    const usd::PrimSpec* prim = stage.prim(path);
    EXPECT_NE(prim, nullptr) << path;
    return prim ? boundMaterialPath(stage, *prim) : "?";
}

TEST(MaterialBinding, EachPrimResolvesToTheMaterialTheRulesGive) {
    const auto stage = testing::stageFrom(kLooks + kWorld);
    // Collection bindings of one prim in native property order (glass, metal, plastic): metal holds
    // Back and so Rivet below it; it is ordered before plastic, which names Rivet itself, and the
    // depth at which a collection names a prim does not matter (rule 6).
    EXPECT_EQ(bound(*stage, "/World/Chair/Back/Brace/Rivet"), "/Looks/Gold");
    // No collection holds the seat: World's direct binding.
    EXPECT_EQ(bound(*stage, "/World/Chair/Seat"), "/Looks/Green");
    // At one prim a collection binding is stronger than the direct binding (rule 4).
    EXPECT_EQ(bound(*stage, "/World/Table/Top"), "/Looks/Blue");
    // An excluded prim: the next binding, World's direct one.
    EXPECT_EQ(bound(*stage, "/World/Table/Leg"), "/Looks/Green");
    // Weaker-than-descendants (the default): Lamp's own direct binding beats World's metal
    // collection, which holds Lamp and Base.
    EXPECT_EQ(bound(*stage, "/World/Lamp/Base"), "/Looks/Red");
    EXPECT_EQ(bound(*stage, "/World/Lamp"), "/Looks/Red");
    // Stronger-than-descendants collection on an ancestor beats the prim's own direct binding;
    // its targets may come in either order.
    EXPECT_EQ(bound(*stage, "/World/Lamp/Shade"), "/Looks/White");
    // explicitOnly holds Shelf itself (includeRoot is ignored under explicitOnly), not Book.
    EXPECT_EQ(bound(*stage, "/World/Shelf"), "/Looks/Red");
    EXPECT_EQ(bound(*stage, "/World/Shelf/Book"), "/Looks/Green");
    // A stronger-than-descendants direct binding on an ancestor beats the prim's own.
    EXPECT_EQ(bound(*stage, "/World/Box/Lid"), "/Looks/Gold");
    // The full-purpose pass comes first: the crate's material:binding:full beats the slat's own
    // all-purpose binding (rule 3).
    EXPECT_EQ(bound(*stage, "/World/Crate/Slat"), "/Looks/Final");
    // includeRoot with expandPrims holds everything: but the door's own direct binding is closer.
    EXPECT_EQ(bound(*stage, "/Yard/Shed"), "/Looks/White");
    EXPECT_EQ(bound(*stage, "/Yard/Shed/Door"), "/Looks/Red");
}

TEST(MaterialBinding, UnusableBindingsWarnWithTheirPrimAndTheNextBindingApplies) {
    const std::string scene = kLooks + R"(
def Xform "Bad" (prepend apiSchemas = ["CollectionAPI:real"])
{
    rel material:binding = </Looks/Blue>
    rel material:binding:collection:a = [</Nowhere.collection:x>, </Looks/Red>]
    rel material:binding:collection:b = [</Looks/Red>]
    rel material:binding:collection:c = [</Bad.collection:undefined>, </Looks/Red>]
    rel material:binding:collection:d = [</Bad.collection:real>, </Looks/Gold>]
    rel collection:real:includes = [</Bad/Other>]
    def Mesh "Quad"
    {
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    }
    def Mesh "Two"
    {
        rel material:binding = [</Looks/Red>, </Looks/Gold>]
    }
}
)";
    const testing::Populated p = testing::populate(scene);
    EXPECT_EQ(bound(*p.stage, "/Bad/Quad"), "/Looks/Blue");
    // A direct binding with two targets binds nothing: the parent's applies.
    EXPECT_EQ(bound(*p.stage, "/Bad/Two"), "/Looks/Blue");
    auto warned = [&](const std::string& path, const std::string& text) {
        return std::any_of(p.warnings.begin(), p.warnings.end(), [&](const std::string& w) {
            return w.starts_with(path + ": ") && w.find(text) != std::string::npos;
        });
    };
    EXPECT_TRUE(warned("/Bad",
                       "material:binding:collection:a targets the collection </Nowhere.collection:x>, but no "
                       "prim /Nowhere; ignored, the next binding applies"));
    EXPECT_TRUE(warned("/Bad", "material:binding:collection:b has 1 target; a collection binding needs two"));
    EXPECT_TRUE(warned("/Bad",
                       "material:binding:collection:c targets the collection </Bad.collection:undefined>, "
                       "which /Bad does not define"));
    EXPECT_TRUE(warned("/Bad/Two", "material:binding has 2 targets; a direct binding needs one material"));
    EXPECT_FALSE(warned("/Bad", "material:binding:collection:d")) << "a usable binding that holds nothing here";
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    ASSERT_GE(p.result.scene.meshes[0].material, 0);
    EXPECT_EQ(p.result.scene.materials[std::size_t(p.result.scene.meshes[0].material)].name, "/Looks/Blue");
}

TEST(MaterialBinding, NativePropertyOrderIsUsdsDictionaryOrder) {
    EXPECT_TRUE(dictionaryLess("arm", "Body"));      // case is ignored
    EXPECT_TRUE(dictionaryLess("part9", "part10"));  // digits by value
    EXPECT_TRUE(dictionaryLess("part007", "part10"));
    EXPECT_TRUE(dictionaryLess("a_b", "aa"));    // '_' before letters
    EXPECT_TRUE(dictionaryLess("leg", "legL"));  // a prefix first
    EXPECT_FALSE(dictionaryLess("legL", "leg"));
    EXPECT_FALSE(dictionaryLess("same", "same"));
    std::vector<std::string> names = {"material:binding:collection:part10", "material:binding:collection:Part2",
                                      "material:binding:collection:body"};
    std::sort(names.begin(), names.end(), dictionaryLess);
    EXPECT_EQ(names, (std::vector<std::string>{"material:binding:collection:body", "material:binding:collection:Part2",
                                               "material:binding:collection:part10"}));
}

}  // namespace
}  // namespace fluence::delegate
