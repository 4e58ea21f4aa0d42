// Composition conformance suite, written from the USD specification's composition chapter: one
// small scene per arc and per interaction (layers under tests/scene/composition/), each with its
// composed result asserted exactly — values, specifiers, children order, remapped targets and
// connections, time samples after layer offsets, warnings with their file:line:column.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "tests/scene/composition_helpers.h"

namespace fluence::usd {
namespace {

using namespace test;

// ---- Layer stack: sublayers ---------------------------------------------------------------------

TEST(CompositionSublayers, StrongerLayersWinAndLayerMetadataComesFromTheRoot) {
    auto stage = open("sublayers/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& world = at(*stage, "/World");
    EXPECT_EQ(world.specifier, Specifier::Def);  // the root layer only says `over`
    EXPECT_EQ(world.typeName, "Xform");
    EXPECT_EQ(world.location.str(), locate("sublayers/strong.usda", "def Xform \"World\""));
    EXPECT_EQ(number(world, "shared"), 1.0);
    EXPECT_EQ(number(world, "rootOnly"), 1.0);
    EXPECT_EQ(number(world, "strongOnly"), 2.0);
    EXPECT_EQ(number(world, "weakOnly"), 3.0);
    EXPECT_EQ(stage->upAxis(), 'Z');
    EXPECT_EQ(stage->metersPerUnit(), 1.0);
    EXPECT_EQ(stage->defaultPrim(), "World");
    EXPECT_EQ(stage->endTimeCode(), 40.0);
    EXPECT_EQ(findMetadata(stage->composedLayer().metadata, "subLayers"), nullptr);
}

TEST(CompositionSublayers, LayerOffsetsMoveTimeSamplesThroughNestedSublayers) {
    auto stage = open("sublayers/root.usda");
    const PrimSpec& world = at(*stage, "/World");
    // strong.usda (offset 10): its samples win as a whole over weak.usda's.
    EXPECT_EQ(samples(world, "animated"), (std::vector<std::pair<double, double>>{{10, 0}, {20, 10}}));
    // weak.usda (scale 2).
    EXPECT_EQ(samples(world, "weakAnimated"), (std::vector<std::pair<double, double>>{{2, 1}, {4, 2}}));
    // nested/deep.usda (offset 5, scale 0.5) under strong.usda (offset 10): t * 0.5 + 5 + 10.
    EXPECT_EQ(samples(world, "deepAnimated"), (std::vector<std::pair<double, double>>{{15, 0}, {17, 4}}));
    // A stronger default hides weaker time samples.
    const AttributeSpec& hidden = attribute(world, "defaultHidesWeakerSamples");
    EXPECT_TRUE(hidden.timeSamples.empty());
    EXPECT_EQ(Stage::resolve(hidden, 1.0)->asDouble(), 2.0);
    EXPECT_EQ(Stage::resolve(attribute(world, "animated"), 15.0)->asDouble(), 5.0);
}

TEST(CompositionSublayers, ChildrenAreUnitedWeakestFirstThenReordered) {
    auto stage = open("sublayers/root.usda");
    // weak: WeakChild; deep: FromDeep; strong: StrongChild; the root layer reorders.
    EXPECT_EQ(childNames(at(*stage, "/World")), (std::vector<std::string>{"StrongChild", "WeakChild", "FromDeep"}));
}

TEST(CompositionSublayers, AssetPathsAnchorAtTheLayerThatAuthoredThem) {
    auto stage = open("sublayers/root.usda");
    const PrimSpec& world = at(*stage, "/World");
    EXPECT_EQ(text(world, "texture"), layer("sublayers/nested/textures/wood.<UDIM>.png"));
    EXPECT_EQ(Stage::resolve(attribute(world, "maps"), kDefaultTime)->strings,
              (std::vector<std::string>{layer("sublayers/maps/a.png"), "/abs/b.png"}));
    // A reference authored in nested/deep.usda resolves from nested/.
    EXPECT_EQ(text(at(*stage, "/World/FromDeep"), "file"), layer("sublayers/nested/part_texture.png"));

    std::vector<AssetReference> assets = stage->assetReferences();
    auto texture =
        std::find_if(assets.begin(), assets.end(), [](const AssetReference& a) { return a.property == "texture"; });
    ASSERT_NE(texture, assets.end());
    EXPECT_EQ(texture->primPath, "/World");
    EXPECT_EQ(texture->authored, "./textures/wood.<UDIM>.png");
    EXPECT_EQ(texture->resolved, layer("sublayers/nested/textures/wood.<UDIM>.png"));
    EXPECT_FALSE(texture->exists);
    EXPECT_EQ(texture->location.str(), locate("sublayers/nested/deep.usda", "asset texture"));
    EXPECT_EQ(std::count_if(assets.begin(), assets.end(), [](const AssetReference& a) { return a.property == "maps"; }),
              2);

    EXPECT_EQ(stage->layerFiles(),
              (std::vector<std::string>{layer("sublayers/root.usda"), layer("sublayers/strong.usda"),
                                        layer("sublayers/nested/deep.usda"), layer("sublayers/weak.usda"),
                                        layer("sublayers/nested/part.usda")}));
}

// ---- References ---------------------------------------------------------------------------------

TEST(CompositionReferences, DefaultPrimReferenceSitsUnderLocalOpinions) {
    auto stage = open("references/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& prim = at(*stage, "/World/ByDefaultPrim");
    EXPECT_EQ(prim.specifier, Specifier::Def);
    EXPECT_EQ(prim.typeName, "Xform");     // from the asset: the local spec has no type
    EXPECT_EQ(number(prim, "size"), 2.0);  // local beats the reference
    EXPECT_EQ(findMetadata(prim.metadata, "kind")->value.asString(), "component");
    EXPECT_EQ(metadataStrings(prim, "apiSchemas"), (std::vector<std::string>{"LocalAPI", "AssetAPI"}));
    EXPECT_EQ(findMetadata(prim.metadata, "references"), nullptr);  // arcs are consumed
    EXPECT_EQ(childNames(prim), (std::vector<std::string>{"Geom", "Looks", "LocalChild"}));
    EXPECT_EQ(at(*stage, "/World/ByDefaultPrim/Geom").typeName, "Mesh");
    EXPECT_EQ(at(*stage, "/World/ByDefaultPrim/Geom").location.str(),
              locate("references/asset.usda", "def Mesh \"Geom\""));
}

TEST(CompositionReferences, TargetsAndConnectionsInsideTheAssetAreRemapped) {
    auto stage = open("references/root.usda");
    const PrimSpec& prim = at(*stage, "/World/ByDefaultPrim");
    EXPECT_EQ(prim.relationship("look")->targets, (std::vector<std::string>{"/World/ByDefaultPrim/Looks/Red"}));
    EXPECT_EQ(prim.relationship("outside")->targets, (std::vector<std::string>{"/Elsewhere/Thing"}));
    EXPECT_EQ(at(*stage, "/World/ByDefaultPrim/Geom").relationship("material:binding")->targets,
              (std::vector<std::string>{"/World/ByDefaultPrim/Looks/Red"}));
    EXPECT_EQ(attribute(at(*stage, "/World/ByDefaultPrim/Looks/Red"), "outputs:surface").connections,
              (std::vector<std::string>{"/World/ByDefaultPrim/Looks/Red/Shader.outputs:surface"}));
    // A relative connection is made absolute, then remapped.
    EXPECT_EQ(attribute(at(*stage, "/World/ByDefaultPrim/Looks/Red/Shader"), "inputs:diffuseColor").connections,
              (std::vector<std::string>{"/World/ByDefaultPrim/Looks/Red/Reader.outputs:result"}));
}

TEST(CompositionReferences, ExternalWithPrimPathAndInternalReferences) {
    auto stage = open("references/root.usda");
    const PrimSpec& byPath = at(*stage, "/World/ByPath");
    EXPECT_EQ(number(byPath, "size"), 5.0);
    EXPECT_EQ(number(byPath, "otherOnly"), 5.0);
    EXPECT_TRUE(byPath.children.empty());
    // </World/ByPath> brings ByPath's own reference along.
    const PrimSpec& internal = at(*stage, "/World/Internal");
    EXPECT_EQ(number(internal, "size"), 5.0);
    EXPECT_EQ(number(internal, "otherOnly"), 5.0);
    // The asset's other root prims are not part of the stage.
    EXPECT_EQ(stage->prim("/Other"), nullptr);
    EXPECT_EQ(stage->prim("/Asset"), nullptr);
}

TEST(CompositionReferences, ReferenceLayerOffsetMovesTimeSamples) {
    auto stage = open("references/root.usda");
    EXPECT_EQ(samples(at(*stage, "/World/Offset"), "anim"),
              (std::vector<std::pair<double, double>>{{5, 0}, {25, 100}}));
    EXPECT_EQ(samples(at(*stage, "/World/ByDefaultPrim"), "anim"),
              (std::vector<std::pair<double, double>>{{0, 0}, {10, 100}}));
}

TEST(CompositionReferences, ListOpsComposeAcrossLayers) {
    auto stage = open("references/root.usda");
    // weak.usda: [A, B]; root: delete A, prepend C  ->  [C, B].
    const PrimSpec& listOps = at(*stage, "/ListOps");
    EXPECT_EQ(number(listOps, "which"), 3.0);
    EXPECT_EQ(number(listOps, "onlyB"), 2.0);
    EXPECT_EQ(number(listOps, "onlyC"), 3.0);
    EXPECT_EQ(listOps.attribute("onlyA"), nullptr);
    // An explicit list replaces the weaker one: [C].
    const PrimSpec& explicitList = at(*stage, "/Explicit");
    EXPECT_EQ(number(explicitList, "which"), 3.0);
    EXPECT_EQ(explicitList.attribute("onlyA"), nullptr);
    EXPECT_EQ(explicitList.attribute("onlyB"), nullptr);
}

// ---- Payloads -----------------------------------------------------------------------------------

TEST(CompositionPayloads, LoadedByDefault) {
    auto stage = open("payloads/root.usda");
    const PrimSpec& loaded = at(*stage, "/World/Loaded");
    EXPECT_EQ(number(loaded, "local"), 1.0);
    EXPECT_EQ(number(loaded, "size"), 1.0);
    EXPECT_EQ(childNames(loaded), (std::vector<std::string>{"Geom", "Looks"}));
    EXPECT_EQ(at(*stage, "/World/Loaded/Geom").relationship("material:binding")->targets,
              (std::vector<std::string>{"/World/Loaded/Looks/Red"}));
}

TEST(CompositionPayloads, LeftOutWhenNotLoaded) {
    StageOptions options;
    options.loadRules = LoadRules::loadNone();
    auto stage = open("payloads/root.usda", options);
    const PrimSpec& loaded = at(*stage, "/World/Loaded");
    EXPECT_EQ(number(loaded, "local"), 1.0);
    EXPECT_EQ(loaded.attribute("size"), nullptr);
    EXPECT_TRUE(loaded.children.empty());
    EXPECT_EQ(stage->layerFiles(), (std::vector<std::string>{layer("payloads/root.usda")}));
}

// ---- Variants -----------------------------------------------------------------------------------

TEST(CompositionVariants, TheParserKeepsNestedVariantSets) {
    auto parsed = parseUsdaFile(layer("variants/model.usda"));
    const VariantSetSpec& size = parsed->primAtPath("/Model")->variantSets.at(1);
    ASSERT_EQ(size.name, "size");
    const VariantSpec& small = size.variants.at(1);
    ASSERT_EQ(small.name, "small");
    ASSERT_EQ(small.variantSets.size(), 1u);
    EXPECT_EQ(small.variantSets[0].name, "detail");
    ASSERT_EQ(small.variantSets[0].variants.size(), 2u);
    EXPECT_EQ(small.variantSets[0].variants[0].name, "high");
    EXPECT_EQ(small.variantSets[0].variants[0].children.at(0)->name, "Extra");
}

TEST(CompositionVariants, SelectionsAuthoredInTheFile) {
    auto stage = open("variants/model.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& model = at(*stage, "/Model");
    EXPECT_EQ(numbers(model, "color"), (std::vector<double>{1, 0, 0}));
    EXPECT_EQ(text(model, "tag"), "local");  // local opinions beat variants
    EXPECT_EQ(metadataStrings(model, "apiSchemas"), (std::vector<std::string>{"RedAPI"}));
    EXPECT_EQ(findMetadata(model.metadata, "variants"), nullptr);
    EXPECT_EQ(findMetadata(model.metadata, "variantSets"), nullptr);
    EXPECT_TRUE(model.variantSets.empty());
    EXPECT_EQ(childNames(model), (std::vector<std::string>{"Body", "RedOnly"}));
    EXPECT_EQ(text(at(*stage, "/Model/Body"), "paint"), "red");
    EXPECT_EQ(number(model, "scale"), 1.0);
    EXPECT_EQ(number(model, "level"), 1.0);  // nested set "detail" inside "small"
}

TEST(CompositionVariants, OptionsOverrideAuthoredSelections) {
    StageOptions options;
    options.variantSelections = {{"/Model", "look", "blue"}, {"/Model", "detail", "high"}};
    auto stage = open("variants/model.usda", options);
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& model = at(*stage, "/Model");
    EXPECT_EQ(numbers(model, "color"), (std::vector<double>{0, 0, 1}));
    EXPECT_TRUE(metadataStrings(model, "apiSchemas").empty());
    // Weakest opinion first: the nested variant "detail=high" is weaker than the prim's own specs.
    EXPECT_EQ(childNames(model), (std::vector<std::string>{"Extra", "Body"}));
    EXPECT_EQ(at(*stage, "/Model/Body").attribute("paint"), nullptr);
    EXPECT_EQ(number(model, "level"), 2.0);
}

TEST(CompositionVariants, UnknownSetsVariantsAndPrimsWarn) {
    StageOptions options;
    options.variantSelections = {{"/Model", "nope", "x"}, {"/Model", "look", "green"}, {"/Nowhere", "look", "red"}};
    auto stage = open("variants/model.usda", options);
    ASSERT_EQ(stage->warnings().size(), 3u) << allWarnings(*stage);
    EXPECT_EQ(warningsWith(*stage, "the prim has no variant set 'nope'").size(), 1u);
    EXPECT_EQ(warningsWith(*stage, "variant set 'look' has no variant 'green'").size(), 1u);
    EXPECT_EQ(warningsWith(*stage, "for </Nowhere> ignored: no such prim").size(), 1u);
    EXPECT_EQ(stage->warnings()[0].primPath, "/Model");
    // The unknown variant selects nothing; composition goes on.
    EXPECT_EQ(at(*stage, "/Model").attribute("color"), nullptr);
    EXPECT_EQ(number(at(*stage, "/Model"), "scale"), 1.0);
}

TEST(CompositionVariants, VariantsOfAReferencedAssetTakeTheReferencingSelection) {
    auto stage = open("variants/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    EXPECT_EQ(numbers(at(*stage, "/World/Referenced"), "color"), (std::vector<double>{0, 0, 1}));
    EXPECT_EQ(childNames(at(*stage, "/World/Referenced")), (std::vector<std::string>{"Body"}));
    EXPECT_EQ(numbers(at(*stage, "/World/Plain"), "color"), (std::vector<double>{1, 0, 0}));
    EXPECT_EQ(childNames(at(*stage, "/World/Plain")), (std::vector<std::string>{"Body", "RedOnly"}));
    // Options name prims by their composed path.
    StageOptions options;
    options.variantSelections = {{"/World/Plain", "size", "big"}};
    auto big = open("variants/root.usda", options);
    EXPECT_EQ(number(at(*big, "/World/Plain"), "scale"), 10.0);
    EXPECT_EQ(at(*big, "/World/Plain").attribute("level"), nullptr);
    EXPECT_EQ(number(at(*big, "/World/Referenced"), "scale"), 1.0);
}

// ---- Inherits -----------------------------------------------------------------------------------

TEST(CompositionInherits, LocalClassAndItsNamespace) {
    auto stage = open("inherits/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& instance = at(*stage, "/Instance");
    EXPECT_EQ(number(instance, "value"), 2.0);
    EXPECT_EQ(number(instance, "classOnly"), 1.0);
    EXPECT_EQ(number(at(*stage, "/Instance/FromClass"), "inClass"), 1.0);
    EXPECT_EQ(at(*stage, "/_class_Thing").specifier, Specifier::Class);
    std::vector<std::string> paths = traversed(*stage);
    EXPECT_EQ(std::count(paths.begin(), paths.end(), "/_class_Thing"), 0);
    EXPECT_EQ(std::count(paths.begin(), paths.end(), "/Instance/FromClass"), 1);
}

TEST(CompositionInherits, ClassesOfAReferencedAssetAreOverriddenFromTheStage) {
    auto stage = open("inherits/root.usda");
    const PrimSpec& prop = at(*stage, "/World/Prop");
    EXPECT_EQ(number(prop, "fromClass"), 7.0);       // the root layer's /_class_Prop
    EXPECT_EQ(number(prop, "assetClassOnly"), 1.0);  // the asset's /_class_Prop
    EXPECT_EQ(number(prop, "v"), 1.0);
}

TEST(CompositionInherits, InheritsAreStrongerThanReferences) {
    auto stage = open("inherits/root.usda");
    EXPECT_EQ(number(at(*stage, "/World/Both"), "v"), 5.0);
}

// ---- Specializes --------------------------------------------------------------------------------

TEST(CompositionSpecializes, SpecializesAreWeakerThanReferences) {
    auto stage = open("specializes/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    const PrimSpec& s = at(*stage, "/S");
    EXPECT_EQ(number(s, "v"), 1.0);  // the reference beats /_spec
    EXPECT_EQ(number(s, "specOnly"), 9.0);
    EXPECT_EQ(number(s, "z"), 1.0);  // the asset's own opinion beats the base it specializes
}

TEST(CompositionSpecializes, ABaseSpecializedInsideAnAssetCanBeOverriddenFromTheStage) {
    auto stage = open("specializes/root.usda");
    const PrimSpec& prop = at(*stage, "/Prop");
    EXPECT_EQ(number(prop, "w"), 3.0);  // the root layer's /_base is implied and stronger
    EXPECT_EQ(number(prop, "z"), 1.0);
    EXPECT_EQ(number(prop, "baseOnly"), 1.0);
}

// ---- Specifiers and activation ------------------------------------------------------------------

TEST(CompositionSpecifiers, OverOnlyPrimsStayOverAndAreNotTraversed) {
    auto stage = open("over_only/root.usda");
    EXPECT_EQ(at(*stage, "/Ghost").specifier, Specifier::Over);
    EXPECT_EQ(number(at(*stage, "/Ghost"), "value"), 1.0);
    EXPECT_EQ(at(*stage, "/Ghost/DefinedUnderOver").specifier, Specifier::Def);
    EXPECT_EQ(at(*stage, "/World/Overridden").specifier, Specifier::Def);
    EXPECT_EQ(number(at(*stage, "/World/Overridden"), "value"), 2.0);
    EXPECT_EQ(traversed(*stage), (std::vector<std::string>{"/World", "/World/Visible"}));
}

TEST(CompositionSpecifiers, InactivePrimsKeepNoDescendants) {
    auto stage = open("over_only/root.usda");
    EXPECT_NE(stage->prim("/World/Overridden"), nullptr);
    EXPECT_EQ(stage->prim("/World/Overridden/HiddenChild"), nullptr);
}

// ---- Cycles -------------------------------------------------------------------------------------

TEST(CompositionCycles, SublayerCycleIsReportedAndCut) {
    auto stage = open("cycles/a.usda");
    ASSERT_EQ(stage->warnings().size(), 1u) << allWarnings(*stage);
    const CompositionWarning& w = stage->warnings()[0];
    EXPECT_NE(w.message.find("sublayer cycle: a.usda -> b.usda -> a.usda"), std::string::npos) << w.message;
    EXPECT_EQ(w.location.str(), locate("cycles/b.usda", "subLayers"));
    EXPECT_NE(stage->prim("/FromA"), nullptr);
    EXPECT_NE(stage->prim("/FromB"), nullptr);
}

TEST(CompositionCycles, ReferenceCyclesAreReportedAndCut) {
    auto stage = open("cycles/refs.usda");
    auto cycles = warningsWith(*stage, "reference cycle");
    ASSERT_EQ(cycles.size(), 4u) << allWarnings(*stage);
    EXPECT_EQ(warningsWith(*stage, "@refs.usda@</A> -> @refs.usda@</B> -> @refs.usda@</A>").size(), 1u)
        << allWarnings(*stage);
    EXPECT_EQ(warningsWith(*stage, "@refs.usda@</Parent/Child> -> @refs.usda@</Parent>").size(), 1u)
        << allWarnings(*stage);
    auto crossFile = warningsWith(*stage, "@x.usda@</X> -> @y.usda@</Y> -> @x.usda@</X>");
    ASSERT_EQ(crossFile.size(), 1u) << allWarnings(*stage);
    EXPECT_EQ(crossFile[0].location.str(), locate("cycles/y.usda", "references"));
    EXPECT_EQ(crossFile[0].primPath, "/CrossFile");
    // Each prim still gets every opinion reached before the cycle closed.
    EXPECT_EQ(number(at(*stage, "/A"), "fromB"), 1.0);
    EXPECT_EQ(number(at(*stage, "/B"), "fromA"), 1.0);
    EXPECT_EQ(number(at(*stage, "/CrossFile"), "fromX"), 1.0);
    EXPECT_EQ(number(at(*stage, "/CrossFile"), "fromY"), 1.0);
    EXPECT_TRUE(at(*stage, "/Parent/Child").children.empty());
}

// ---- Missing and unusable files -----------------------------------------------------------------

TEST(CompositionErrors, MissingFilesAndPrimsAreWarningsWithLocations) {
    auto stage = open("missing/root.usda");
    ASSERT_EQ(stage->warnings().size(), 5u) << allWarnings(*stage);
    const auto& w = stage->warnings();
    EXPECT_EQ(w[0].location.str(), locate("missing/root.usda", "subLayers"));
    EXPECT_NE(w[0].message.find("sublayer @./no_such_sublayer.usda@ ignored: cannot find '" +
                                layer("missing/no_such_sublayer.usda") + "'"),
              std::string::npos)
        << w[0].message;
    EXPECT_EQ(w[1].location.str(), locate("missing/root.usda", "references = @./no_such_file.usda@"));
    EXPECT_EQ(w[1].primPath, "/MissingFile");
    EXPECT_NE(w[1].message.find("cannot find '" + layer("missing/no_such_file.usda") + "'"), std::string::npos);
    EXPECT_EQ(w[2].location.str(), locate("missing/root.usda", "references = @./target.usda@</NoSuchPrim>"));
    EXPECT_EQ(w[2].primPath, "/MissingPrim");
    EXPECT_NE(w[2].message.find("</NoSuchPrim> does not exist in 'target.usda'"), std::string::npos) << w[2].message;
    EXPECT_EQ(w[3].location.str(), locate("missing/root.usda", "references = @./target.usda@\n"));
    EXPECT_NE(w[3].message.find("'target.usda' has no defaultPrim"), std::string::npos) << w[3].message;
    EXPECT_EQ(w[4].location.str(), locate("missing/root.usda", "references = @./notes.txt@"));
    EXPECT_EQ(w[4].primPath, "/NotUsd");
    EXPECT_NE(w[4].message.find("is not a USD layer"), std::string::npos) << w[4].message;
    // Composition went on.
    EXPECT_EQ(number(at(*stage, "/Good"), "found"), 1.0);
    EXPECT_EQ(at(*stage, "/MissingFile").specifier, Specifier::Def);
}

TEST(CompositionErrors, UnresolvedArcTargetsAreListedAsAssets) {
    auto stage = open("missing/root.usda");
    std::vector<AssetReference> assets = stage->assetReferences();
    ASSERT_EQ(assets.size(), 3u);
    EXPECT_EQ(assets[0].property, "subLayers");
    EXPECT_EQ(assets[0].authored, "./no_such_sublayer.usda");
    EXPECT_EQ(assets[0].resolved, layer("missing/no_such_sublayer.usda"));
    EXPECT_FALSE(assets[0].exists);
    EXPECT_EQ(assets[1].primPath, "/MissingFile");
    EXPECT_EQ(assets[1].property, "references");
    EXPECT_EQ(assets[2].resolved, layer("missing/notes.txt"));
    EXPECT_TRUE(assets[2].exists);  // it is there, but not a USD layer
}

TEST(CompositionErrors, SyntaxErrorInAReferencedLayerIsAParseError) {
    try {
        open("errors/root.usda");
        FAIL() << "no ParseError";
    } catch (const ParseError& error) {
        EXPECT_EQ(error.location().file, layer("errors/bad_syntax.usda"));
        EXPECT_EQ(error.location().line, 5);
        EXPECT_EQ(error.location().column, 16);
    }
}

TEST(CompositionErrors, UnreadableRootLayers) {
    EXPECT_THROW(open("errors/no_such_root.usda"), FileError);
    // A damaged crate file, as the root layer or behind an arc, is an error naming it.
    for (const char* root : {"errors/crate_root.usd", "errors/damaged_crate_payload.usda"}) {
        try {
            open(root);
            ADD_FAILURE() << root << ": no FileError";
        } catch (const FileError& error) {
            EXPECT_NE(std::string(error.what()).find("crate_root.usd': damaged or unsupported USD crate file"),
                      std::string::npos)
                << error.what();
        }
    }
}

// ---- Instancing ---------------------------------------------------------------------------------

std::string prototypeKey(const Stage& stage, const std::string& path) {
    const MetadataEntry* entry = findMetadata(at(stage, path).metadata, "fluence:instancePrototype");
    return entry ? entry->value.asString().value_or("") : "";
}

TEST(CompositionInstancing, InstancesOfOneAssetShareAPrototypeKey) {
    auto stage = open("instancing/root.usda");
    EXPECT_TRUE(stage->warnings().empty()) << allWarnings(*stage);
    std::string first = prototypeKey(*stage, "/World/First");
    EXPECT_FALSE(first.empty());
    EXPECT_EQ(prototypeKey(*stage, "/World/Second"), first);  // local opinions on the root don't matter
    EXPECT_NE(prototypeKey(*stage, "/World/Blue"), first);    // another variant selection
    EXPECT_EQ(prototypeKey(*stage, "/World/NotInstanced"), "");
    // Instances are full copies.
    EXPECT_EQ(numbers(at(*stage, "/World/First/Geom"), "color"), (std::vector<double>{1, 0, 0}));
    EXPECT_EQ(numbers(at(*stage, "/World/Blue/Geom"), "color"), (std::vector<double>{0, 0, 1}));
    EXPECT_EQ(number(at(*stage, "/World/Second"), "local"), 2.0);
}

TEST(CompositionInstancing, LocalOpinionsBelowAnInstanceDoNotApply) {
    auto stage = open("instancing/root.usda");
    EXPECT_EQ(number(at(*stage, "/World/First/Geom"), "size"), 1.0);
    EXPECT_EQ(number(at(*stage, "/World/NotInstanced/Geom"), "size"), 99.0);
}

TEST(CompositionCycles, ArcsThatMultiplyWithoutEndStopWithAWarning) {
    // Each level references the one before from itself and from ten children: 10^8 prims.
    std::string text = "#usda 1.0\ndef \"L0\"\n{\n    def \"leaf\"\n    {\n    }\n}\n";
    for (int level = 1; level <= 8; ++level) {
        std::string previous = "</L" + std::to_string(level - 1) + ">";
        text += "def \"L" + std::to_string(level) + "\" (references = " + previous + ")\n{\n";
        for (int child = 0; child < 10; ++child)
            text += "    def \"c" + std::to_string(child) + "\" (references = " + previous + ")\n    {\n    }\n";
        text += "}\n";
    }
    Stage stage(parseUsdaString(text, "bomb.usda"));
    auto stopped = warningsWith(stage, "composition stopped at");
    ASSERT_EQ(stopped.size(), 1u) << allWarnings(stage);
    EXPECT_NE(stopped[0].message.find("more than 1000-fold"), std::string::npos) << stopped[0].message;
    EXPECT_NE(stage.prim("/L0/leaf"), nullptr);
}

// ---- Edits --------------------------------------------------------------------------------------

TEST(CompositionEdits, SetAttributeIsTheStrongestOpinion) {
    auto stage = open("sublayers/root.usda");
    ASSERT_TRUE(stage->setAttribute("/World", "animated", Value::numeric("double", {42}, 1, false)));
    const AttributeSpec& animated = attribute(at(*stage, "/World"), "animated");
    EXPECT_TRUE(animated.timeSamples.empty());  // a stronger default hides the samples
    EXPECT_EQ(Stage::resolve(animated, 15.0)->asDouble(), 42.0);
    ASSERT_TRUE(stage->setAttribute("/World", "brandNew", Value::numeric("float", {1}, 1, false)));
    EXPECT_EQ(attribute(at(*stage, "/World"), "brandNew").typeName, "float");
    EXPECT_FALSE(stage->setAttribute("/Nowhere", "x", Value::numeric("float", {1}, 1, false)));
}

TEST(CompositionEdits, AVariantSwitchRecomposesOnlyThatSubtree) {
    auto stage = open("variants/root.usda");
    const PrimSpec* referenced = stage->prim("/World/Referenced");
    ASSERT_TRUE(
        stage->setAttribute("/World/Plain/Body", "paint", Value::string("token", ValueKind::Token, {"green"}, false)));
    stage->setVariantSelection("/World/Plain", "look", "blue");
    EXPECT_EQ(stage->prim("/World/Referenced"), referenced);  // untouched
    EXPECT_EQ(numbers(at(*stage, "/World/Plain"), "color"), (std::vector<double>{0, 0, 1}));
    EXPECT_EQ(childNames(at(*stage, "/World/Plain")), (std::vector<std::string>{"Body"}));
    EXPECT_EQ(stage->prim("/World/Plain/RedOnly"), nullptr);
    EXPECT_EQ(text(at(*stage, "/World/Plain/Body"), "paint"), "green");  // the edit is kept
    EXPECT_EQ(childNames(at(*stage, "/World")), (std::vector<std::string>{"Referenced", "Plain"}));
    stage->setVariantSelection("/World/Plain", "look", "red");
    EXPECT_NE(stage->prim("/World/Plain/RedOnly"), nullptr);
}

// ---- In-memory stages ---------------------------------------------------------------------------

TEST(CompositionInMemory, InternalArcsComposeInAStageBuiltFromText) {
    Stage stage(parseUsdaString(R"(#usda 1.0
class "_class_Light"
{
    float intensity = 5
}

def "Proto"
{
    def "Part"
    {
    }
}

def "Copy" (
    inherits = </_class_Light>
    references = </Proto>
)
{
}
)",
                                "inline.usda"));
    EXPECT_TRUE(stage.warnings().empty()) << allWarnings(stage);
    EXPECT_EQ(number(at(stage, "/Copy"), "intensity"), 5.0);
    EXPECT_EQ(childNames(at(stage, "/Copy")), (std::vector<std::string>{"Part"}));
    EXPECT_EQ(stage.rootLayer().primAtPath("/Copy")->children.size(), 0u);  // the root layer as parsed
    EXPECT_EQ(stage.layerFiles(), (std::vector<std::string>{"inline.usda"}));
}

// Composition copies values without copying their numbers: every instance of a referenced mesh,
// the mesh itself and the root layer as parsed hold one array of points.
TEST(CompositionInMemory, ComposedValuesShareTheAuthoredNumbers) {
    Stage stage(parseUsdaString(R"(#usda 1.0
def Mesh "Asset"
{
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0)]
}

def "A" (
    references = </Asset>
)
{
}

def "B" (
    references = </Asset>
)
{
}
)",
                                "shared.usda"));
    const NumberArray& authored = stage.rootLayer().primAtPath("/Asset")->attribute("points")->defaultValue.numbers;
    ASSERT_EQ(authored.size(), 9u);
    for (const char* path : {"/Asset", "/A", "/B"}) {
        const AttributeSpec& points = attribute(at(stage, path), "points");
        EXPECT_EQ(points.defaultValue.numbers.data(), authored.data()) << path;
        EXPECT_EQ(Stage::resolve(points, kDefaultTime)->numbers.data(), authored.data()) << path;
    }
}

}  // namespace
}  // namespace fluence::usd
