// The USDA reader on valid input: one scene exercising every construct, checked value by value.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "scene/usda_parser.h"

namespace fluence::usd {
namespace {

// Line numbers below are the text's own: line 1 is the header.
const char* const kScene = R"usda(#usda 1.0
(
    "The layer doc"
    defaultPrim = "World"
    upAxis = "Z"
    metersPerUnit = 0.01
    startTimeCode = 1
    endTimeCode = 24
    timeCodesPerSecond = 24
    framesPerSecond = 12
    subLayers = [@./a.usda@ (offset = 1; scale = 2), @b.usda@]
    customLayerData = {
        string x = "y"
        dictionary d = {
            int n = 3
        }
    }
    madeUpKey = [1, 2, 3]
)

def Xform "World" (
    kind = "component"
    prepend apiSchemas = ["GeomModelAPI", "MaterialBindingAPI"]
    customData = {bool flag = true}
)
{
    double3 xformOp:translate = (1, 2.5, -3e2)
    uniform token[] xformOpOrder = ["xformOp:translate"]

    def Mesh "Box" (
        references = @./box.usda@</Box> (offset = 10; scale = 0.5)
        instanceable = true
        active = false
        hidden = true
        variants = {
            string shading = "red"
        }
        prepend variantSets = "shading"
    )
    {
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0)]
        int[] faceVertexIndices = [0, 1, 2]  # a comment
        texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1)] (
            interpolation = "vertex"
            elementSize = 2
        )
        int[] primvars:st:indices = None
        float radius.timeSamples = {
            2: 4.5,
            1: 1,
            -1.5: 3,
            3: None,
        }
        float radius = 7
        matrix4d xformOp:transform = ( (1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (5, 6, 7, 1) )
        custom string note = "tab\there \"quoted\" \x41 'single'"
        string multi = """line one
line two"""
        asset tex = @@@odd@name.png@@@
        bool[] flags = [true, false, 1, 0]
        uchar small = 255
        int64 big = -9223372036854775808
        half h = .5
        quatf q = (1, 0, 0, 0)
        double nums = -inf
        float notANumber = nan
        frame4d frame = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))
        pathExpression pattern = "/World/*"
        rel material:binding = </World/Looks/Red>
        prepend rel proxyPrim = [</World/A>, </World/B>,]
        rel empty = None
        variantSet "shading" = {
            "red" (kind = "subcomponent") {
                color3f inputs:color = (1, 0, 0)
                def Scope "Inside"
                {
                }
            }
            "blue" {
            }
        }
    }

    def Scope "Looks"
    {
        reorder nameChildren = ["Red"]
        def Shader "Red"
        {
            uniform token info:id = "UsdPreviewSurface"
            color3f inputs:diffuseColor.connect = </World/Looks/Tex.outputs:rgb>
            token outputs:surface
        }
    }
}

over "Extra"
{
}

class "_class_Thing" /* block comment */
{
    // line comment
}
)usda";

class UsdaSceneTest : public ::testing::Test {
protected:
    void SetUp() override {
        layer = parseUsdaString(kScene, "scene.usda");
        world = layer->primAtPath("/World");
        box = layer->primAtPath("/World/Box");
        ASSERT_NE(world, nullptr);
        ASSERT_NE(box, nullptr);
    }
    const Value& metadata(const Metadata& entries, const std::string& key) {
        const MetadataEntry* entry = findMetadata(entries, key);
        EXPECT_NE(entry, nullptr) << key;
        static const Value missing;
        return entry ? entry->value : missing;
    }
    const AttributeSpec& attribute(const std::string& name) {
        const AttributeSpec* spec = box->attribute(name);
        EXPECT_NE(spec, nullptr) << name;
        static const AttributeSpec missing;
        return spec ? *spec : missing;
    }

    std::unique_ptr<Layer> layer;
    const PrimSpec* world = nullptr;
    const PrimSpec* box = nullptr;
};

TEST_F(UsdaSceneTest, LayerHeaderAndMetadata) {
    EXPECT_EQ(layer->identifier, "scene.usda");
    EXPECT_EQ(layer->header, "#usda 1.0");
    EXPECT_EQ(metadata(layer->metadata, "doc").asString(), "The layer doc");
    EXPECT_EQ(metadata(layer->metadata, "defaultPrim").asString(), "World");
    EXPECT_EQ(metadata(layer->metadata, "upAxis").asString(), "Z");
    EXPECT_DOUBLE_EQ(*metadata(layer->metadata, "metersPerUnit").asDouble(), 0.01);
    EXPECT_EQ(metadata(layer->metadata, "startTimeCode").asDouble(), 1.0);
    EXPECT_EQ(metadata(layer->metadata, "endTimeCode").asDouble(), 24.0);
    EXPECT_EQ(metadata(layer->metadata, "timeCodesPerSecond").asDouble(), 24.0);
    EXPECT_EQ(metadata(layer->metadata, "framesPerSecond").asDouble(), 12.0);
    const MetadataEntry* defaultPrim = findMetadata(layer->metadata, "defaultPrim");
    EXPECT_EQ(defaultPrim->location.str(), "scene.usda:4:5");

    const Value& madeUp = metadata(layer->metadata, "madeUpKey");
    EXPECT_EQ(madeUp.kind, ValueKind::Numeric);
    EXPECT_TRUE(madeUp.isArray);
    EXPECT_EQ(madeUp.numbers, (std::vector<double>{1, 2, 3}));
}

TEST_F(UsdaSceneTest, SubLayersKeepTheirLayerOffsets) {
    const Value& subLayers = metadata(layer->metadata, "subLayers");
    ASSERT_EQ(subLayers.kind, ValueKind::List);
    ASSERT_EQ(subLayers.items.size(), 2u);
    EXPECT_EQ(subLayers.items[0].kind, ValueKind::Reference);
    EXPECT_EQ(subLayers.items[0].strings[0], "./a.usda");
    EXPECT_EQ(subLayers.items[0].numbers, (std::vector<double>{1, 2}));
    EXPECT_EQ(subLayers.items[1].strings[0], "b.usda");
    EXPECT_TRUE(subLayers.items[1].numbers.empty());
}

TEST_F(UsdaSceneTest, NestedDictionaries) {
    const Value& data = metadata(layer->metadata, "customLayerData");
    ASSERT_EQ(data.kind, ValueKind::Dictionary);
    ASSERT_NE(data.find("x"), nullptr);
    EXPECT_EQ(data.find("x")->typeName, "string");
    EXPECT_EQ(data.find("x")->asString(), "y");
    const Value* nested = data.find("d");
    ASSERT_NE(nested, nullptr);
    EXPECT_EQ(nested->typeName, "dictionary");
    ASSERT_NE(nested->find("n"), nullptr);
    EXPECT_EQ(nested->find("n")->typeName, "int");
    EXPECT_EQ(nested->find("n")->asDouble(), 3.0);
    EXPECT_EQ(data.find("missing"), nullptr);
}

TEST_F(UsdaSceneTest, PrimTreeAndLocations) {
    ASSERT_EQ(layer->rootPrims.size(), 3u);
    EXPECT_EQ(world->specifier, Specifier::Def);
    EXPECT_EQ(world->typeName, "Xform");
    EXPECT_EQ(world->path, "/World");
    EXPECT_EQ(world->location.str(), "scene.usda:21:1");
    EXPECT_EQ(box->typeName, "Mesh");
    EXPECT_EQ(box->path, "/World/Box");
    EXPECT_EQ(box->location.line, 30);
    EXPECT_EQ(box->location.column, 5);
    EXPECT_EQ(world->children.size(), 2u);
    EXPECT_EQ(world->child("Looks")->path, "/World/Looks");
    EXPECT_EQ(layer->primAtPath("/World/Looks/Red")->typeName, "Shader");
    EXPECT_EQ(layer->primAtPath("/World/Nope"), nullptr);
    EXPECT_EQ(layer->primAtPath("World"), nullptr);

    const PrimSpec* extra = layer->primAtPath("/Extra");
    ASSERT_NE(extra, nullptr);
    EXPECT_EQ(extra->specifier, Specifier::Over);
    EXPECT_EQ(extra->typeName, "");
    const PrimSpec* thing = layer->primAtPath("/_class_Thing");
    ASSERT_NE(thing, nullptr);
    EXPECT_EQ(thing->specifier, Specifier::Class);
}

TEST_F(UsdaSceneTest, PrimMetadata) {
    EXPECT_EQ(metadata(world->metadata, "kind").asString(), "component");
    const MetadataEntry* apiSchemas = findMetadata(world->metadata, "apiSchemas");
    ASSERT_NE(apiSchemas, nullptr);
    EXPECT_EQ(apiSchemas->op, ListOpKind::Prepend);
    EXPECT_EQ(apiSchemas->value.kind, ValueKind::String);
    EXPECT_EQ(apiSchemas->value.strings, (std::vector<std::string>{"GeomModelAPI", "MaterialBindingAPI"}));
    EXPECT_EQ(metadata(world->metadata, "customData").find("flag")->asDouble(), 1.0);

    const Value& references = metadata(box->metadata, "references");
    EXPECT_EQ(references.kind, ValueKind::Reference);
    EXPECT_EQ(references.strings, (std::vector<std::string>{"./box.usda", "/Box"}));
    EXPECT_EQ(references.numbers, (std::vector<double>{10, 0.5}));
    EXPECT_EQ(metadata(box->metadata, "instanceable").asDouble(), 1.0);
    EXPECT_EQ(metadata(box->metadata, "active").asDouble(), 0.0);
    EXPECT_EQ(metadata(box->metadata, "hidden").asDouble(), 1.0);
    EXPECT_EQ(metadata(box->metadata, "variants").find("shading")->asString(), "red");
    const MetadataEntry* variantSets = findMetadata(box->metadata, "variantSets");
    EXPECT_EQ(variantSets->op, ListOpKind::Prepend);
    EXPECT_EQ(variantSets->value.asString(), "shading");
}

TEST_F(UsdaSceneTest, ScalarAndTupleValues) {
    const AttributeSpec* translate = world->attribute("xformOp:translate");
    ASSERT_NE(translate, nullptr);
    EXPECT_EQ(translate->typeName, "double3");
    EXPECT_TRUE(translate->hasDefault);
    EXPECT_EQ(translate->defaultValue.components, 3);
    EXPECT_FALSE(translate->defaultValue.isArray);
    EXPECT_EQ(translate->defaultValue.numbers, (std::vector<double>{1, 2.5, -300}));
    EXPECT_EQ(translate->location.str(), "scene.usda:27:5");

    const AttributeSpec* order = world->attribute("xformOpOrder");
    EXPECT_TRUE(order->uniform);
    EXPECT_EQ(order->defaultValue.kind, ValueKind::Token);
    EXPECT_TRUE(order->defaultValue.isArray);
    EXPECT_EQ(order->defaultValue.strings, (std::vector<std::string>{"xformOp:translate"}));

    EXPECT_EQ(attribute("small").defaultValue.numbers, (std::vector<double>{255}));
    EXPECT_EQ(attribute("big").defaultValue.numbers, (std::vector<double>{-9223372036854775808.0}));
    EXPECT_EQ(attribute("h").defaultValue.numbers, (std::vector<double>{0.5}));
    EXPECT_EQ(attribute("q").defaultValue.numbers, (std::vector<double>{1, 0, 0, 0}));
    EXPECT_EQ(attribute("nums").defaultValue.asDouble(), -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(*attribute("notANumber").defaultValue.asDouble()));
    EXPECT_EQ(attribute("frame").defaultValue.components, 16);
    EXPECT_EQ(attribute("pattern").defaultValue.kind, ValueKind::String);
    EXPECT_EQ(attribute("pattern").defaultValue.asString(), "/World/*");

    const Value& matrix = attribute("xformOp:transform").defaultValue;
    EXPECT_EQ(matrix.typeName, "matrix4d");
    EXPECT_EQ(matrix.components, 16);
    EXPECT_EQ(matrix.numbers, (std::vector<double>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}));
}

TEST_F(UsdaSceneTest, ArrayValues) {
    const Value& points = attribute("points").defaultValue;
    EXPECT_EQ(points.typeName, "point3f[]");
    EXPECT_EQ(points.kind, ValueKind::Numeric);
    EXPECT_TRUE(points.isArray);
    EXPECT_EQ(points.components, 3);
    EXPECT_EQ(points.size(), 3u);
    EXPECT_EQ(points.numbers, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0}));

    EXPECT_EQ(attribute("faceVertexIndices").defaultValue.numbers, (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(attribute("flags").defaultValue.numbers, (std::vector<double>{1, 0, 1, 0}));

    const AttributeSpec& st = attribute("primvars:st");
    EXPECT_EQ(st.defaultValue.components, 2);
    EXPECT_EQ(st.defaultValue.size(), 3u);
    EXPECT_EQ(findMetadata(st.metadata, "interpolation")->value.asString(), "vertex");
    EXPECT_EQ(findMetadata(st.metadata, "elementSize")->value.asDouble(), 2.0);

    const AttributeSpec& indices = attribute("primvars:st:indices");
    EXPECT_TRUE(indices.hasDefault);
    EXPECT_TRUE(indices.defaultValue.isBlocked());
    EXPECT_EQ(indices.defaultValue.typeName, "int[]");
}

TEST_F(UsdaSceneTest, StringsAndAssets) {
    EXPECT_TRUE(attribute("note").custom);
    EXPECT_EQ(attribute("note").defaultValue.asString(), "tab\there \"quoted\" A 'single'");
    EXPECT_EQ(attribute("multi").defaultValue.asString(), "line one\nline two");
    const Value& tex = attribute("tex").defaultValue;
    EXPECT_EQ(tex.kind, ValueKind::Asset);
    EXPECT_EQ(tex.asString(), "odd@name.png");
}

TEST_F(UsdaSceneTest, TimeSamplesAreSortedAndMergedWithTheDefault) {
    const AttributeSpec& radius = attribute("radius");
    EXPECT_EQ(radius.typeName, "float");
    ASSERT_EQ(radius.timeSamples.size(), 4u);
    EXPECT_EQ(radius.timeSamples[0].first, -1.5);
    EXPECT_EQ(radius.timeSamples[0].second.asDouble(), 3.0);
    EXPECT_EQ(radius.timeSamples[1].first, 1.0);
    EXPECT_EQ(radius.timeSamples[2].first, 2.0);
    EXPECT_EQ(radius.timeSamples[2].second.asDouble(), 4.5);
    EXPECT_EQ(radius.timeSamples[3].first, 3.0);
    EXPECT_TRUE(radius.timeSamples[3].second.isBlocked());
    EXPECT_TRUE(radius.hasDefault);
    EXPECT_EQ(radius.defaultValue.asDouble(), 7.0);
    EXPECT_EQ(radius.location.line, 48);  // the first statement naming it
}

TEST_F(UsdaSceneTest, RelationshipsAndConnections) {
    const RelationshipSpec* binding = box->relationship("material:binding");
    ASSERT_NE(binding, nullptr);
    EXPECT_EQ(binding->op, ListOpKind::Explicit);
    EXPECT_EQ(binding->targets, (std::vector<std::string>{"/World/Looks/Red"}));
    const RelationshipSpec* proxy = box->relationship("proxyPrim");
    EXPECT_EQ(proxy->op, ListOpKind::Prepend);
    EXPECT_EQ(proxy->targets, (std::vector<std::string>{"/World/A", "/World/B"}));
    EXPECT_TRUE(box->relationship("empty")->blocked);

    const PrimSpec* red = layer->primAtPath("/World/Looks/Red");
    const AttributeSpec* diffuse = red->attribute("inputs:diffuseColor");
    ASSERT_NE(diffuse, nullptr);
    EXPECT_FALSE(diffuse->hasDefault);
    EXPECT_EQ(diffuse->connections, (std::vector<std::string>{"/World/Looks/Tex.outputs:rgb"}));
    EXPECT_FALSE(red->attribute("outputs:surface")->hasDefault);
    EXPECT_EQ(red->attribute("info:id")->defaultValue.asString(), "UsdPreviewSurface");

    const MetadataEntry* reorder = findMetadata(world->child("Looks")->metadata, "nameChildren");
    ASSERT_NE(reorder, nullptr);
    EXPECT_EQ(reorder->op, ListOpKind::Reorder);
    EXPECT_EQ(reorder->value.strings, (std::vector<std::string>{"Red"}));
}

TEST_F(UsdaSceneTest, VariantSets) {
    ASSERT_EQ(box->variantSets.size(), 1u);
    const VariantSetSpec& shading = box->variantSets[0];
    EXPECT_EQ(shading.name, "shading");
    ASSERT_EQ(shading.variants.size(), 2u);
    const VariantSpec& red = shading.variants[0];
    EXPECT_EQ(red.name, "red");
    EXPECT_EQ(findMetadata(red.metadata, "kind")->value.asString(), "subcomponent");
    ASSERT_EQ(red.attributes.size(), 1u);
    EXPECT_EQ(red.attributes[0].name, "inputs:color");
    ASSERT_EQ(red.children.size(), 1u);
    EXPECT_EQ(red.children[0]->path, "/World/Box{shading=red}Inside");
    EXPECT_EQ(shading.variants[1].name, "blue");
    EXPECT_TRUE(shading.variants[1].attributes.empty());
}

TEST(UsdaParser, AcceptsSdfCookieAndEmptyLayers) {
    EXPECT_EQ(parseUsdaString("#sdf 1.4.32", "a.sdf")->header, "#sdf 1.4.32");
    EXPECT_TRUE(parseUsdaString("#usda 1.0\n", "a.usda")->rootPrims.empty());
    EXPECT_TRUE(parseUsdaString("#usda 1.0\r\n\r\n", "a.usda")->rootPrims.empty());
}

TEST(UsdaParser, SemicolonsSeparateStatements) {
    auto layer = parseUsdaString(
        "#usda 1.0\n(upAxis = \"Y\"; metersPerUnit = 1)\n"
        "def \"A\" { double a = 1; double b = 2; }\n",
        "a.usda");
    EXPECT_EQ(layer->primAtPath("/A")->attributes.size(), 2u);
    EXPECT_EQ(findMetadata(layer->metadata, "metersPerUnit")->value.asDouble(), 1.0);
}

TEST(UsdaParser, ReferenceListsAndArcs) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P" (
    prepend references = [@./a.usda@</A>, </Internal> (offset = 2), @b.usda@]
    payload = @./p.usda@
    inherits = </_class>
    specializes = [</S1>, </S2>]
    add variantSets = ["x", "y"]
)
{
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    const MetadataEntry* references = findMetadata(prim->metadata, "references");
    EXPECT_EQ(references->op, ListOpKind::Prepend);
    ASSERT_EQ(references->value.items.size(), 3u);
    EXPECT_EQ(references->value.items[0].strings, (std::vector<std::string>{"./a.usda", "/A"}));
    EXPECT_EQ(references->value.items[1].strings, (std::vector<std::string>{"", "/Internal"}));
    EXPECT_EQ(references->value.items[1].numbers, (std::vector<double>{2, 1}));
    EXPECT_EQ(references->value.items[2].strings, (std::vector<std::string>{"b.usda", ""}));
    const Value& payload = findMetadata(prim->metadata, "payload")->value;
    EXPECT_EQ(payload.kind, ValueKind::Reference);
    EXPECT_EQ(payload.strings[0], "./p.usda");
    const Value& inherits = findMetadata(prim->metadata, "inherits")->value;
    EXPECT_EQ(inherits.kind, ValueKind::Path);
    EXPECT_FALSE(inherits.isArray);
    EXPECT_EQ(inherits.asString(), "/_class");
    EXPECT_EQ(findMetadata(prim->metadata, "specializes")->value.strings, (std::vector<std::string>{"/S1", "/S2"}));
    EXPECT_EQ(findMetadata(prim->metadata, "variantSets")->value.strings, (std::vector<std::string>{"x", "y"}));
}

TEST(UsdaParser, ListEditedTargetsAndConnections) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P"
{
    custom rel r
    delete rel r = </Gone>
    add rel r = [</A>, </B>]
    varying rel v.default = </V>
    double x = 1
    prepend double x.connect = [</P.a>, </P.b>]
    reorder double x.connect = [</P.b>, </P.a>]
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    ASSERT_EQ(prim->relationships.size(), 2u);
    const RelationshipSpec* r = prim->relationship("r");
    EXPECT_TRUE(r->custom);
    EXPECT_EQ(r->op, ListOpKind::Add);
    EXPECT_EQ(r->targets, (std::vector<std::string>{"/A", "/B"}));
    const MetadataEntry* deleted = findMetadata(r->metadata, "targetPaths");
    ASSERT_NE(deleted, nullptr);
    EXPECT_EQ(deleted->op, ListOpKind::Delete);
    EXPECT_EQ(deleted->value.strings, (std::vector<std::string>{"/Gone"}));
    EXPECT_EQ(prim->relationship("v")->targets, (std::vector<std::string>{"/V"}));

    const AttributeSpec* x = prim->attribute("x");
    EXPECT_EQ(x->connectionOp, ListOpKind::Prepend);
    EXPECT_EQ(x->connections, (std::vector<std::string>{"/P.a", "/P.b"}));
    EXPECT_EQ(findMetadata(x->metadata, "connectionPaths")->op, ListOpKind::Reorder);
    EXPECT_EQ(x->defaultValue.asDouble(), 1.0);
}

TEST(UsdaParser, UnknownTypesAndMetadataAreKeptGenerically) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P" (noSuchField = "testing"; permission = private; symmetryFunction = )
{
    unknownType a = 5
    Some::Enum b = SomeValue (displayUnit = mm)
    Bogus[] c = [(1, 2), (3, 4)]
    Bogus d = [1, "x"]
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    EXPECT_EQ(findMetadata(prim->metadata, "noSuchField")->value.asString(), "testing");
    EXPECT_EQ(findMetadata(prim->metadata, "permission")->value.kind, ValueKind::Token);
    EXPECT_EQ(findMetadata(prim->metadata, "symmetryFunction")->value.asString(), "");
    EXPECT_EQ(prim->attribute("a")->defaultValue.typeName, "unknownType");
    EXPECT_EQ(prim->attribute("a")->defaultValue.asDouble(), 5.0);
    EXPECT_EQ(prim->attribute("b")->defaultValue.kind, ValueKind::Token);
    EXPECT_EQ(prim->attribute("b")->defaultValue.asString(), "SomeValue");
    const Value& c = prim->attribute("c")->defaultValue;
    EXPECT_EQ(c.typeName, "Bogus[]");
    EXPECT_EQ(c.components, 2);
    EXPECT_EQ(c.numbers, (std::vector<double>{1, 2, 3, 4}));
    const Value& d = prim->attribute("d")->defaultValue;
    EXPECT_EQ(d.kind, ValueKind::List);
    EXPECT_EQ(d.items.size(), 2u);
}

TEST(UsdaParser, DisplayUnitsNameSdfUnits) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P"
{
    double a = 1 (displayUnit = mm)
    double b = 1 (displayUnit = deg)
    double c = 1 (displayUnit = default)
    double d = 1 (displayUnit = in)
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    for (auto [name, unit] : {std::pair{"a", "mm"}, {"b", "deg"}, {"c", "default"}, {"d", "in"}}) {
        const MetadataEntry* entry = findMetadata(prim->attribute(name)->metadata, "displayUnit");
        ASSERT_NE(entry, nullptr) << name;
        EXPECT_EQ(entry->value.kind, ValueKind::Token);
        EXPECT_EQ(entry->value.asString(), unit);
    }
}

TEST(UsdaParser, StringEscapesAndQuotes) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P"
{
    string a = 'single "double" \'escaped\''
    string b = "\\ \n \t \x7e \101 \q"
    string c = '''triple
'single' ''quoted'' '''
    asset d = @@@with \@@@ inside@@@
    asset e = @@
    string f = "UTF-8: Süßigkeiten 響"
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    EXPECT_EQ(prim->attribute("a")->defaultValue.asString(), "single \"double\" 'escaped'");
    EXPECT_EQ(prim->attribute("b")->defaultValue.asString(), "\\ \n \t ~ A q");
    EXPECT_EQ(prim->attribute("c")->defaultValue.asString(), "triple\n'single' ''quoted'' ");
    EXPECT_EQ(prim->attribute("d")->defaultValue.asString(), "with @@@ inside");
    EXPECT_EQ(prim->attribute("e")->defaultValue.asString(), "");
    EXPECT_EQ(prim->attribute("f")->defaultValue.asString(), "UTF-8: Süßigkeiten 響");
}

TEST(UsdaParser, NumberForms) {
    auto layer = parseUsdaString(R"(#usda 1.0
def "P"
{
    double[] a = [0, -1, 1.5, -.25, 1e3, 2.5E-2, 7., inf, -inf]
    uint64 b = 18446744073709551615
    bool[] c = [1, 0, true, false, True, False]
}
)",
                                 "a.usda");
    const PrimSpec* prim = layer->primAtPath("/P");
    double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(prim->attribute("a")->defaultValue.numbers,
              (std::vector<double>{0, -1, 1.5, -0.25, 1000, 0.025, 7, inf, -inf}));
    EXPECT_EQ(prim->attribute("b")->defaultValue.numbers, (std::vector<double>{18446744073709551615.0}));
    EXPECT_EQ(prim->attribute("c")->defaultValue.numbers, (std::vector<double>{1, 0, 1, 0, 1, 0}));
}

TEST(UsdaParser, RelocatesAndStringMaps) {
    auto layer = parseUsdaString(R"(#usda 1.0
(
    relocates = {
        </a> : </b>,
        <c/d> : <>,
    }
)
def "P" (
    prefixSubstitutions = {"$Left": "Right", "L": "R",}
)
{
}
)",
                                 "a.usda");
    const Value& relocates = findMetadata(layer->metadata, "relocates")->value;
    ASSERT_EQ(relocates.kind, ValueKind::Dictionary);
    EXPECT_EQ(relocates.find("/a")->asString(), "/b");
    EXPECT_EQ(relocates.find("c/d")->asString(), "");
    const Value& substitutions = findMetadata(layer->primAtPath("/P")->metadata, "prefixSubstitutions")->value;
    EXPECT_EQ(substitutions.find("$Left")->asString(), "Right");
}

TEST(UsdaParser, ParsesLargeArraysQuickly) {
    std::string text = "#usda 1.0\ndef Mesh \"M\"\n{\n    point3f[] points = [";
    const int count = 200000;
    for (int i = 0; i < count; ++i) {
        if (i) text += ", ";
        text += '(';
        text += std::to_string(i);
        text += ".5, -1e-3, 2)";
    }
    text += "]\n}\n";
    auto layer = parseUsdaString(text, "big.usda");
    const Value& points = layer->primAtPath("/M")->attribute("points")->defaultValue;
    ASSERT_EQ(points.size(), static_cast<std::size_t>(count));
    EXPECT_EQ(points.numbers[3 * (count - 1)], count - 1 + 0.5);
    EXPECT_EQ(points.numbers[1], -1e-3);
}

TEST(UsdaParser, ReadsFiles) {
    auto layer = parseUsdaFile(FLUENCE_SOURCE_DIR "/tests/scene/data/simple.usda");
    EXPECT_EQ(layer->identifier, FLUENCE_SOURCE_DIR "/tests/scene/data/simple.usda");
    ASSERT_NE(layer->primAtPath("/World/Sphere"), nullptr);
    EXPECT_EQ(layer->primAtPath("/World/Sphere")->attribute("radius")->defaultValue.asDouble(), 2.0);
    EXPECT_THROW(parseUsdaFile(FLUENCE_SOURCE_DIR "/tests/scene/data/does_not_exist.usda"), FileError);
    EXPECT_THROW(parseUsdaFile(FLUENCE_SOURCE_DIR "/tests/scene/data"), FileError);
}

}  // namespace
}  // namespace fluence::usd
