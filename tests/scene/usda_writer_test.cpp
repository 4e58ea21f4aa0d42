// The USDA writer: every text layer Fluence parses (the shared corpus, usd_samples/, the scene
// tests' layers) reads back from its written text as the same Layer, spec for spec and value for
// value, and writing that Layer again gives the same text; and the values with tricky text forms
// (signed zeros, extremes, NaN and infinities, float, half, strings, assets, empty arrays, nested
// dictionaries, list ops, relationship and connection edits) are written as USD writes them.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "scene/crate_reader.h"
#include "scene/usda_parser.h"
#include "scene/usda_value_writer.h"
#include "scene/usda_writer.h"
#include "tests/support/shared_data.h"

namespace fluence::usd {
namespace {

namespace fs = std::filesystem;

// ---- Structural comparison of two layers --------------------------------------------------------
// Every field of every spec, except source locations, identifiers, headers and parse warnings.
// Numbers are compared bit for bit, NaNs as NaNs; a number of a float (half) type that is exactly a
// float (half) is compared as that float (half), since that is the value USD holds and the form the
// writer gives it (Fluence's reader keeps the written decimal as the nearest double).

using Difference = std::optional<std::string>;

std::string_view baseType(std::string_view typeName) {
    if (typeName.ends_with("[]")) typeName.remove_suffix(2);
    return typeName;
}

bool isHalfType(std::string_view type) { return type.starts_with("half") || type.ends_with('h'); }
bool isFloatType(std::string_view type) {
    return type.starts_with("float") || type.ends_with('f') || type.ends_with("Float");
}

bool sameNumber(double a, double b, std::string_view type) {
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    auto fits = [](double x, double max) { return std::isfinite(x) && std::fabs(x) <= max; };
    if (isHalfType(type) && fits(a, 65504.0) && double(_Float16(a)) == a) {
        return fits(b, 65519.0) &&
               std::bit_cast<std::uint16_t>(_Float16(a)) == std::bit_cast<std::uint16_t>(_Float16(b));
    }
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    if (isFloatType(type) && fits(a, kFloatMax) && double(float(a)) == a)
        return fits(b, kFloatMax) && std::bit_cast<std::uint32_t>(float(a)) == std::bit_cast<std::uint32_t>(float(b));
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

Difference compare(const Value& a, const Value& b, const std::string& where);

Difference compareDictionaries(const std::shared_ptr<const Dictionary>& a, const std::shared_ptr<const Dictionary>& b,
                               const std::string& where) {
    if (!a || !b) return bool(a) == bool(b) ? Difference{} : where + ": dictionary present on one side only";
    if (a->size() != b->size())
        return where + ": " + std::to_string(a->size()) + " vs " + std::to_string(b->size()) + " entries";
    for (std::size_t i = 0; i < a->size(); ++i) {
        if ((*a)[i].first != (*b)[i].first) return where + ": key '" + (*a)[i].first + "' vs '" + (*b)[i].first + "'";
        if (auto d = compare((*a)[i].second, (*b)[i].second, where + "." + (*a)[i].first)) return d;
    }
    return {};
}

Difference compare(const Value& a, const Value& b, const std::string& where) {
    auto differ = [&](const std::string& what) {
        return where + ": " + what + " (" + a.toString() + " vs " + b.toString() + ")";
    };
    if (a.typeName != b.typeName) return differ("type '" + a.typeName + "' vs '" + b.typeName + "'");
    if (a.kind != b.kind) return differ("kind");
    if (a.isArray != b.isArray) return differ("isArray");
    if (a.kind == ValueKind::Numeric && a.components != b.components) return differ("components");
    if (a.numbers.size() != b.numbers.size()) return differ("number count");
    for (std::size_t i = 0; i < a.numbers.size(); ++i)
        if (!sameNumber(a.numbers[i], b.numbers[i], baseType(a.typeName))) return differ("number " + std::to_string(i));
    if (a.strings != b.strings) return differ("strings");
    if (a.items.size() != b.items.size()) return differ("item count");
    for (std::size_t i = 0; i < a.items.size(); ++i)
        if (auto d = compare(a.items[i], b.items[i], where + "[" + std::to_string(i) + "]")) return d;
    return compareDictionaries(a.dictionary, b.dictionary, where);
}

Difference compare(const Metadata& a, const Metadata& b, const std::string& where) {
    if (a.size() != b.size())
        return where + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " metadata entries";
    for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string at = where + " metadata '" + a[i].key + "'";
        if (a[i].key != b[i].key) return at + " vs '" + b[i].key + "'";
        if (a[i].op != b[i].op) return at + ": list op";
        if (auto d = compare(a[i].value, b[i].value, at)) return d;
    }
    return {};
}

Difference compare(const AttributeSpec& a, const AttributeSpec& b, const std::string& where) {
    const std::string at = where + "." + a.name;
    if (a.name != b.name || a.typeName != b.typeName) return at + ": name or type (" + b.typeName + " " + b.name + ")";
    if (a.custom != b.custom || a.uniform != b.uniform) return at + ": custom or uniform";
    if (a.hasDefault != b.hasDefault) return at + ": default authored on one side only";
    if (a.hasDefault)
        if (auto d = compare(a.defaultValue, b.defaultValue, at)) return d;
    if (a.timeSamples.size() != b.timeSamples.size()) return at + ": time sample count";
    for (std::size_t i = 0; i < a.timeSamples.size(); ++i) {
        if (!sameNumber(a.timeSamples[i].first, b.timeSamples[i].first, "double")) return at + ": sample time";
        if (auto d = compare(a.timeSamples[i].second, b.timeSamples[i].second, at + ".timeSamples")) return d;
    }
    if (a.connections != b.connections || a.connectionOp != b.connectionOp) return at + ": connections";
    return compare(a.metadata, b.metadata, at);
}

Difference compare(const RelationshipSpec& a, const RelationshipSpec& b, const std::string& where) {
    const std::string at = where + "." + a.name;
    if (a.name != b.name) return at + ": name " + b.name;
    if (a.custom != b.custom || a.op != b.op || a.blocked != b.blocked) return at + ": custom, list op or block";
    if (a.targets != b.targets) return at + ": targets";
    return compare(a.metadata, b.metadata, at);
}

struct SpecBody {
    const Metadata& metadata;
    const std::vector<AttributeSpec>& attributes;
    const std::vector<RelationshipSpec>& relationships;
    const std::vector<std::unique_ptr<PrimSpec>>& children;
    const std::vector<VariantSetSpec>& variantSets;
};

Difference compare(const PrimSpec& a, const PrimSpec& b);

template <class T>
Difference compareEach(const std::vector<T>& a, const std::vector<T>& b, const std::string& where,
                       const auto& compareOne) {
    if (a.size() != b.size()) return where + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        if (auto d = compareOne(a[i], b[i])) return d;
    return {};
}

Difference compare(const SpecBody& a, const SpecBody& b, const std::string& where) {
    if (auto d = compare(a.metadata, b.metadata, where)) return d;
    auto attribute = [&](const AttributeSpec& x, const AttributeSpec& y) { return compare(x, y, where); };
    auto relationship = [&](const RelationshipSpec& x, const RelationshipSpec& y) { return compare(x, y, where); };
    auto child = [](const std::unique_ptr<PrimSpec>& x, const std::unique_ptr<PrimSpec>& y) { return compare(*x, *y); };
    auto variantSet = [&](const VariantSetSpec& x, const VariantSetSpec& y) -> Difference {
        const std::string at = where + "{" + x.name + "}";
        if (x.name != y.name) return at + ": variant set name " + y.name;
        return compareEach(x.variants, y.variants, at, [&](const VariantSpec& v, const VariantSpec& w) -> Difference {
            if (v.name != w.name) return at + ": variant name " + v.name + " vs " + w.name;
            return compare(SpecBody{v.metadata, v.attributes, v.relationships, v.children, v.variantSets},
                           SpecBody{w.metadata, w.attributes, w.relationships, w.children, w.variantSets},
                           at + "=" + v.name);
        });
    };
    if (auto d = compareEach(a.attributes, b.attributes, where + " attributes", attribute)) return d;
    if (auto d = compareEach(a.relationships, b.relationships, where + " relationships", relationship)) return d;
    if (auto d = compareEach(a.children, b.children, where + " children", child)) return d;
    return compareEach(a.variantSets, b.variantSets, where + " variant sets", variantSet);
}

Difference compare(const PrimSpec& a, const PrimSpec& b) {
    if (a.path != b.path || a.name != b.name) return a.path + ": path " + b.path;
    if (a.specifier != b.specifier || a.typeName != b.typeName) return a.path + ": specifier or type " + b.typeName;
    return compare(SpecBody{a.metadata, a.attributes, a.relationships, a.children, a.variantSets},
                   SpecBody{b.metadata, b.attributes, b.relationships, b.children, b.variantSets}, a.path);
}

Difference compare(const Layer& a, const Layer& b) {
    if (auto d = compare(a.metadata, b.metadata, "layer")) return d;
    return compareEach(
        a.rootPrims, b.rootPrims, "root prims",
        [](const std::unique_ptr<PrimSpec>& x, const std::unique_ptr<PrimSpec>& y) { return compare(*x, *y); });
}

// Writes `layer`, reads the text back and checks the Layer and the text are the same again.
// Returns the written text.
std::string expectRoundTrip(const Layer& layer, const std::string& name) {
    const std::string text = writeUsda(layer);
    std::unique_ptr<Layer> again;
    try {
        again = parseUsdaString(text, name + " (written)");
    } catch (const ParseError& error) {
        ADD_FAILURE() << name << ": the written text does not parse: " << error.what() << "\n" << text.substr(0, 4000);
        return text;
    }
    if (Difference d = compare(layer, *again)) ADD_FAILURE() << name << ": " << *d;
    EXPECT_EQ(writeUsda(*again), text) << name << ": writing the read-back layer changed the text";
    return text;
}

std::string roundTripText(std::string_view usda) {
    auto layer = parseUsdaString(usda, "test.usda");
    return expectRoundTrip(*layer, "test.usda");
}

TEST(UsdaWriter, TheComparisonSeesAOneUlpChangeAReorderedEntryAndAListOp) {
    const std::string path = FLUENCE_SOURCE_DIR "/tests/scene/data/kitchen_sink.usda";
    auto original = parseUsdaFile(path);
    EXPECT_FALSE(compare(*original, *parseUsdaFile(path)));

    auto changed = parseUsdaFile(path);
    AttributeSpec& translate = changed->rootPrims[0]->attributes[0];
    std::vector<double> numbers = translate.defaultValue.numbers;
    numbers[1] = std::nextafter(numbers[1], 10.0);
    translate.defaultValue.numbers = numbers;
    EXPECT_TRUE(compare(*original, *changed));

    changed = parseUsdaFile(path);
    std::swap(changed->metadata[1], changed->metadata[2]);
    EXPECT_TRUE(compare(*original, *changed));

    changed = parseUsdaFile(path);
    changed->rootPrims[0]->metadata[1].op = ListOpKind::Append;
    EXPECT_TRUE(compare(*original, *changed));
}

// ---- Every text layer Fluence parses -------------------------------------------------------------

bool isTextLayer(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    char start[5] = {};
    file.read(start, sizeof start);
    std::string_view head(start, static_cast<std::size_t>(file.gcount()));
    return head.starts_with("#usda") || head.starts_with("#sdf");
}

std::vector<fs::path> textLayersUnder(const fs::path& root) {
    std::vector<fs::path> files;
    if (!fs::is_directory(root)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() && (extension == ".usda" || extension == ".usd" || extension == ".sdf") &&
            isTextLayer(entry.path()))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(UsdaWriter, EveryParsedTextLayerRoundTrips) {
    const fs::path corpus = test::sharedPath("usd_corpus");
    FLUENCE_REQUIRE_SHARED(corpus);
    int roundTripped = 0, unparsed = 0;
    for (const fs::path& folder :
         {corpus, fs::path(FLUENCE_SOURCE_DIR) / "usd_samples", fs::path(FLUENCE_SOURCE_DIR) / "tests/scene"}) {
        for (const fs::path& path : textLayersUnder(folder)) {
            std::unique_ptr<Layer> layer;
            try {
                layer = parseUsdaFile(path.string());
            } catch (const std::exception&) {
                ++unparsed;  // invalid on purpose (error tests, OpenUSD's _bad_ layers)
                continue;
            }
            expectRoundTrip(*layer, path.string());
            ++roundTripped;
        }
    }
    std::cout << "[ writer   ] " << roundTripped << " text layers round-tripped (" << unparsed
              << " that do not parse skipped)\n";
    EXPECT_GE(roundTripped, 100);
}

// Crate layers hold floats and halves as such, and list ops, typed metadata and orderings as the
// crate reader maps them: their text reads back as the same Layer too.
TEST(UsdaWriter, EveryCrateLayerRoundTrips) {
    const fs::path corpus = test::sharedPath("usd_corpus");
    FLUENCE_REQUIRE_SHARED(corpus);
    int roundTripped = 0;
    for (const auto& entry : fs::recursive_directory_iterator(corpus)) {
        std::ifstream file(entry.path(), std::ios::binary);
        char magic[8] = {};
        file.read(magic, sizeof magic);
        if (!entry.is_regular_file() ||
            !isCrateHeader(std::string_view(magic, static_cast<std::size_t>(file.gcount()))))
            continue;
        std::unique_ptr<Layer> layer;
        try {
            layer = readCrateFile(entry.path().string());
        } catch (const FileError&) {
            continue;  // OpenUSD's deliberately corrupt test file
        }
        expectRoundTrip(*layer, entry.path().string());
        ++roundTripped;
    }
    std::cout << "[ writer   ] " << roundTripped << " crate layers round-tripped\n";
}

// ---- Values with tricky text forms ---------------------------------------------------------------

TEST(UsdaWriter, DoublesUseTheShortestFormThatReadsBack) {
    using detail::formatNumber;
    EXPECT_EQ(formatNumber(-0.0, "double"), "-0");
    EXPECT_EQ(formatNumber(1e-300, "double"), "1e-300");
    EXPECT_EQ(formatNumber(0.1, "double"), "0.1");
    EXPECT_EQ(formatNumber(1.0 / 3.0, "double"), "0.3333333333333333");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::quiet_NaN(), "double"), "nan");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity(), "float"), "inf");
    EXPECT_EQ(formatNumber(-std::numeric_limits<double>::infinity(), ""), "-inf");
    EXPECT_EQ(formatNumber(5e-324, "double"), "5e-324");
    EXPECT_EQ(formatNumber(1e-6, "double"), "0.000001");
    EXPECT_EQ(formatNumber(-1.25e-7, "double"), "-1.25e-7");
    EXPECT_EQ(formatNumber(100000, "float2"), "100000");
    EXPECT_EQ(formatNumber(123456789012345.0, ""), "123456789012345");
    EXPECT_EQ(formatNumber(2.5e15, ""), "2.5e15");
    EXPECT_EQ(formatNumber(-9223372036854775808.0, "int64"), "-9223372036854775808");
    EXPECT_EQ(formatNumber(18446744073709551615.0, "uint64"), "18446744073709551616");
    EXPECT_EQ(formatNumber(1.0, "bool"), "1");
}

TEST(UsdaWriter, FloatsAndHalvesAreWrittenAsUsdWritesThem) {
    using detail::formatNumber;
    // A float value (as a crate layer holds it) is its shortest float form, not its double digits.
    EXPECT_EQ(formatNumber(double(0.1f), "float"), "0.1");
    EXPECT_EQ(formatNumber(double(0.1f), "color3f"), "0.1");
    EXPECT_EQ(formatNumber(double(0.1f), "double"), "0.10000000149011612");
    // The decimal 0.1 read into a float attribute is kept as the double 0.1: written as such.
    EXPECT_EQ(formatNumber(0.1, "float"), "0.1");
    EXPECT_EQ(formatNumber(1.0 / 3.0, "float"), "0.3333333333333333");
    // Halves: the float with 6 significant digits, as USD streams a GfHalf.
    EXPECT_EQ(formatNumber(double(_Float16(0.1)), "half"), "0.0999756");
    EXPECT_EQ(formatNumber(double(_Float16(65504.0)), "half3"), "65504");
    EXPECT_EQ(formatNumber(0.5, "texCoord2h"), "0.5");
    EXPECT_EQ(formatNumber(0.1, "half"), "0.1");
}

TEST(UsdaWriter, TrickyNumbersRoundTripBitForBit) {
    const std::string text = roundTripText(R"(#usda 1.0
def "P"
{
    double zero = -0
    double tiny = 1e-300
    double third = 0.3333333333333333
    double a = nan
    double b = inf
    double c = -inf
    float f = 0.1
    float g = 0.100000001490116119384765625
    half h = 0.0999755859375
    half3 hs = (0.1, 65504, -0)
    double[] empty = []
    int64 big = -9223372036854775808
    uint64 huge = 18446744073709551615
    matrix2d m = ((1, -0), (1e-300, 2))
    quath q = (1, 0.5, 0.25, 0.125)
}
)");
    EXPECT_NE(text.find("double zero = -0\n"), std::string::npos) << text;
    EXPECT_NE(text.find("double tiny = 1e-300\n"), std::string::npos) << text;
    EXPECT_NE(text.find("double a = nan\n"), std::string::npos) << text;
    EXPECT_NE(text.find("double c = -inf\n"), std::string::npos) << text;
    EXPECT_NE(text.find("float g = 0.1\n"), std::string::npos) << text;  // exactly 0.1f
    EXPECT_NE(text.find("half h = 0.0999756\n"), std::string::npos) << text;
    EXPECT_NE(text.find("double[] empty = []\n"), std::string::npos) << text;
    EXPECT_NE(text.find("matrix2d m = ((1, -0), (1e-300, 2))\n"), std::string::npos) << text;
}

TEST(UsdaWriter, FloatValuesOfACrateLayerReadBackAsTheSameFloats) {
    Layer layer;
    auto prim = std::make_unique<PrimSpec>();
    prim->name = "P";
    prim->path = "/P";
    AttributeSpec color;
    color.name = "color";
    color.typeName = "color3f";
    color.hasDefault = true;
    color.defaultValue = Value::numeric("color3f", {double(0.1f), double(0.7f), double(1e-8f)}, 3, false);
    prim->attributes.push_back(color);
    layer.rootPrims.push_back(std::move(prim));
    const std::string text = expectRoundTrip(layer, "in-memory layer");
    EXPECT_NE(text.find("color3f color = (0.1, 0.7, 1e-8)\n"), std::string::npos) << text;
    auto again = parseUsdaString(text, "again");
    const Value& read = again->rootPrims[0]->attributes[0].defaultValue;
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(float(read.numbers[i]), float(color.defaultValue.numbers[i]));
}

TEST(UsdaWriter, StringsFollowUsdQuotingRules) {
    using detail::quoteString;
    EXPECT_EQ(quoteString("plain"), "\"plain\"");
    EXPECT_EQ(quoteString("say \"hi\""), "'say \"hi\"'");
    EXPECT_EQ(quoteString("both \" and '"), "\"both \\\" and '\"");
    EXPECT_EQ(quoteString("two\nlines"), "\"\"\"two\nlines\"\"\"");
    EXPECT_EQ(quoteString("tab\tback\\slash\rcr"), "\"tab\\tback\\\\slash\\rcr\"");
    EXPECT_EQ(quoteString("caf\xc3\xa9 \xe6\x83\x85\xe5\xa0\xb1 \xf0\x9f\x98\x80"),
              "\"caf\xc3\xa9 \xe6\x83\x85\xe5\xa0\xb1 \xf0\x9f\x98\x80\"");
    EXPECT_EQ(quoteString(std::string("bad\xff\x01", 5)), "\"bad\\xff\\x01\"");
    EXPECT_EQ(quoteString(""), "\"\"");
}

TEST(UsdaWriter, StringsAssetsAndTokensRoundTrip) {
    const std::string text = roundTripText(R"(#usda 1.0
(
    doc = """A layer
with "quotes" and 'apostrophes' and a \\ backslash"""
)

def "Strings" (
    comment = "tab\there \"quoted\" 'single'"
)
{
    string nul = "a\x00b"
    string unicode = "caf\xc3\xa9 情報 😀"
    string newline = "one\ntwo\r\n"
    string[] list = ["", "'", "\"", "\\"]
    token[] tokens = ["a:b", "with space", ""]
    asset plain = @textures/wood.png@
    asset at = @@@user@host/file.usda@@@
    asset triple = @@@a\@@@b@@@
    asset endsInAt = @@@ends@@@@
    asset[] assets = [@a.png@, @@@b@c.png@@@]
    pathExpression pattern = "/World/* - /World/Light"
}
)");
    EXPECT_NE(text.find("asset at = @@@user@host/file.usda@@@\n"), std::string::npos) << text;
    EXPECT_NE(text.find("asset triple = @@@a\\@@@b@@@\n"), std::string::npos) << text;
    EXPECT_NE(text.find("asset plain = @textures/wood.png@\n"), std::string::npos) << text;
    EXPECT_NE(text.find("string nul = \"a\\x00b\"\n"), std::string::npos) << text;
}

TEST(UsdaWriter, DictionariesListsAndUntypedMetadataRoundTrip) {
    const std::string text = roundTripText(R"(#usda 1.0
(
    customLayerData = {
        dictionary outer = {
            dictionary inner = {
                float3[] points = [(1, 2, 3)]
                string "not an identifier" = "x"
            }
            dictionary empty = {
            }
            int[] none = []
            token t = "tok"
            asset a = @a.usda@
            double d = None
        }
    }
    madeUpList = [1, 2.5, -0]
    madeUpTuples = [(1, 2), (3, 4)]
    madeUpMixed = (1, "two", <three>, four)
    madeUpWords = [alpha, beta:gamma]
    madeUpMap = {"key": "value", "other": "x"}
    madeUpPaths = {</a>: </b>}
    madeUpEmpty = []
)

def "P" (
    active = false
    instanceable = true
    permission = private
    displayUnit = mm
    symmetryFunction =
    kind = "component"
    prepend apiSchemas = ["A", "B"]
    delete apiSchemas = ["C"]
    append apiSchemas = ["D"]
    reorder apiSchemas = ["B", "A"]
)
{
}
)");
    EXPECT_NE(text.find("active = false\n"), std::string::npos) << text;
    EXPECT_NE(text.find("instanceable = true\n"), std::string::npos) << text;
    EXPECT_NE(text.find("permission = private\n"), std::string::npos) << text;
    EXPECT_NE(text.find("string \"not an identifier\" = \"x\"\n"), std::string::npos) << text;
    EXPECT_NE(text.find("madeUpWords = [alpha, beta:gamma]\n"), std::string::npos) << text;
}

TEST(UsdaWriter, CompositionArcsAndLayerOffsetsRoundTrip) {
    const std::string text = roundTripText(R"(#usda 1.0
(
    defaultPrim = "World"
    subLayers = [
        @./anim.usda@ (offset = 10; scale = 2),
        @zero.usda@ (offset = 0),
        @-zero.usda@ (offset = -0; scale = 3),
        @plain.usda@
    ]
    relocates = {
        </World/A>: </World/B>
    }
)
reorder rootPrims = ["World", "Class"]

def Xform "World" (
    prepend references = [
        @./chair.usda@</Chair> (offset = 5; customData = {string note = "hi"}),
        </Internal>,
        <>,
        @./default.usda@
    ]
    payload = @./heavy.usda@</Heavy> (scale = 0.5)
    inherits = </Class>
    specializes = [</A>, </B>]
    variants = {
        string shading = "red"
    }
    prepend variantSets = ["shading", "size"]
)
{
    reorder nameChildren = ["B", "A"]
    reorder properties = ["y", "x"]
    def "A" (
        references = None
    )
    {
    }

    def "B"
    {
    }
}

class "Class"
{
}
)");
    EXPECT_NE(text.find("@./anim.usda@ (offset = 10; scale = 2),\n"), std::string::npos) << text;
    EXPECT_NE(text.find("@zero.usda@ (offset = 0),\n"), std::string::npos) << text;
    EXPECT_NE(text.find("@-zero.usda@ (offset = -0; scale = 3),\n"), std::string::npos) << text;
    EXPECT_NE(text.find("reorder rootPrims = [\"World\", \"Class\"]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("payload = @./heavy.usda@</Heavy> (scale = 0.5)\n"), std::string::npos) << text;
}

TEST(UsdaWriter, PropertiesWithListOpsSamplesAndConnectionsRoundTrip) {
    const std::string text = roundTripText(R"(#usda 1.0
def Material "M"
{
    custom uniform token info:id = "UsdPreviewSurface" (
        doc = "the shader"
    )
    color3f inputs:color.connect = </M/Tex.outputs:rgb>
    prepend color3f inputs:other.connect = [</M/A.outputs:x>, </M/B.outputs:y>]
    delete color3f inputs:other.connect = </M/C.outputs:z>
    float inputs:roughness (
        customData = {
            string where = "before the edit"
        }
    )
    reorder float inputs:roughness.connect = [</M/B.outputs:y>, </M/A.outputs:x>]
    float inputs:roughness (
        customData = {
            string where = "after the edit"
        }
    )
    double3 xformOp:translate = (0, 0, 0)
    double3 xformOp:translate.timeSamples = {
        -1.5: (1, 2, 3),
        0: None,
        24: (4, 5, 6),
    }
    float onlySamples.timeSamples = {
        1: 0.5,
    }
    rel material:binding = </Looks/Red> (
        bindMaterialAs = "strongerThanDescendants"
    )
    prepend rel proxyPrim = [</A>, </B>]
    delete rel proxyPrim = </C>
    reorder rel proxyPrim = [</B>, </A>]
    custom rel blocked = None
    rel declared
    rel animated.timeSamples = {
        1.0: </A>,
        2: None,
    }
    add rel added = </X>
    append rel appended = </Y>
}
)");
    EXPECT_NE(text.find("delete color3f inputs:other.connect = </M/C.outputs:z>\n"), std::string::npos) << text;
    EXPECT_NE(text.find("        1.0: </A>,\n"), std::string::npos) << text;
    EXPECT_NE(text.find("custom rel blocked = None\n"), std::string::npos) << text;
}

TEST(UsdaWriter, VariantSetsNestAndKeepTheirOrder) {
    roundTripText(R"(#usda 1.0
over "Model" (
    variants = {
        string look = "b"
    }
)
{
    variantSet "look" = {
        "b" (
            kind = "subcomponent"
        ) {
            color3f color = (0, 0, 1)
            rel r = </X>
            def "Inside"
            {
                float x = 1
            }
            variantSet "nested" = {
                "one" {
                    reorder nameChildren = ["Q"]
                }
                "two-|3" {
                }
            }
        }
        "a" {
        }
    }
    variantSet "size" = {
        "large" {
            double scale = 2
        }
    }
}
)");
}

// Shapes only in-memory (crate) layers have: a list op on a single value, and target edits beside
// the relationship's own prepend, written as the USD statements that author them.
TEST(UsdaWriter, ListEditsOfInMemoryLayersAreWrittenAsUsdStatements) {
    Layer layer;
    auto prim = std::make_unique<PrimSpec>();
    prim->name = "P";
    prim->path = "/P";
    prim->metadata.push_back(
        {"apiSchemas", ListOpKind::Prepend, Value::string("", ValueKind::String, {"A"}, false), {}});
    RelationshipSpec relationship;
    relationship.name = "r";
    relationship.op = ListOpKind::Prepend;
    relationship.targets = {"/A"};
    relationship.metadata.push_back(
        {"targetPaths", ListOpKind::Append, Value::string("", ValueKind::Path, {"/B"}, true), {}});
    prim->relationships.push_back(relationship);
    layer.rootPrims.push_back(std::move(prim));
    const std::string text = writeUsda(layer);
    EXPECT_NE(text.find("    prepend apiSchemas = [\"A\"]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("    prepend rel r = </A>\n    append rel r = </B>\n"), std::string::npos) << text;
}

TEST(UsdaWriter, AnEmptyLayerIsJustTheHeader) { EXPECT_EQ(writeUsda(Layer{}), "#usda 1.0\n"); }

TEST(UsdaWriter, AValueNoUsdTypeHoldsIsAClearError) {
    Layer layer;
    Value dictionary;
    dictionary.kind = ValueKind::Dictionary;
    dictionary.typeName = "dictionary";
    Value list;
    list.kind = ValueKind::List;
    list.items = {Value::numeric("", {1}, 1, false)};
    dictionary.dictionary = std::make_shared<Dictionary>(Dictionary{{"bad", list}});
    layer.metadata.push_back({"customLayerData", ListOpKind::Explicit, dictionary, {}});
    EXPECT_THROW(writeUsda(layer), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::usd
