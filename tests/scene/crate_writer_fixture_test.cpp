// Issue #11: a crate file written by the tests' own fixture (tests/support/crate_writer.h) with a
// layer holding each value type the crate reader supports, read back with usd::readCrateBytes
// and checked value by value.
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "scene/crate_reader.h"
#include "tests/support/crate_writer.h"

namespace fluence::usd {
namespace {

using test::CrateWriter;
using Rep = CrateWriter::Rep;
namespace T = detail::crate_type;
using ST = detail::CrateSpecType;

// Half bits of a float exactly representable as a normal half.
std::uint16_t half(float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    if ((bits & 0x7FFFFFFF) == 0) return static_cast<std::uint16_t>(bits >> 16);
    auto exponent = static_cast<std::int32_t>((bits >> 23) & 0xFF) - 127 + 15;
    return static_cast<std::uint16_t>(((bits >> 16) & 0x8000) | (exponent << 10) | ((bits >> 13) & 0x3FF));
}
std::vector<std::uint16_t> halves(std::initializer_list<float> fs) {
    std::vector<std::uint16_t> out;
    for (float f : fs) out.push_back(half(f));
    return out;
}
std::uint32_t inlineBits(std::initializer_list<std::int8_t> bytes) {
    std::uint32_t bits = 0;
    int shift = 0;
    for (std::int8_t b : bytes) bits |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(b)) << shift, shift += 8;
    return bits;
}

struct NumericCase {
    std::string name, typeName;
    Rep rep;
    std::vector<double> numbers;
    int components;
    bool isArray;
};
struct StringCase {
    std::string name, typeName;
    Rep rep;
    ValueKind kind;
    std::vector<std::string> strings;
    bool isArray;
};

class CrateWriterFixture : public ::testing::Test {
protected:
    void SetUp() override {
        CrateWriter w;
        auto num = [&](std::string name, std::string type, Rep rep, std::vector<double> n, int c = 1, bool a = false) {
            numerics.push_back({std::move(name), std::move(type), rep, std::move(n), c, a});
        };
        num("b", "bool", w.value<std::uint8_t>(T::Bool, {1}), {1});
        num("uc", "uchar", w.value<std::uint8_t>(T::UChar, {200}), {200});
        num("i", "int", w.value<std::int32_t>(T::Int, {-7}), {-7});
        num("u", "uint", w.value<std::uint32_t>(T::UInt, {4000000000u}), {4000000000.0});
        num("i64", "int64", w.value<std::int64_t>(T::Int64, {-5000000000LL}), {-5000000000.0});
        num("u64", "uint64", w.value<std::uint64_t>(T::UInt64, {1ULL << 40}), {1099511627776.0});
        num("h", "half", w.value(T::Half, halves({1.5f})), {1.5});
        num("f", "float", w.value<float>(T::Float, {0.25f}), {0.25});
        num("d", "double", w.value<double>(T::Double, {3.141592653589793}), {3.141592653589793});
        num("f2", "float2", w.value<float>(T::Vec2f, {1, 2}), {1, 2}, 2);
        num("f3", "float3", w.value<float>(T::Vec3f, {1, 2, 3}), {1, 2, 3}, 3);
        num("f4", "float4", w.value<float>(T::Vec4f, {1, 2, 3, 4.5f}), {1, 2, 3, 4.5}, 4);
        num("d2", "double2", w.value<double>(T::Vec2d, {0.1, 0.2}), {0.1, 0.2}, 2);
        num("d3", "double3", w.value<double>(T::Vec3d, {0.1, 0.2, 0.3}), {0.1, 0.2, 0.3}, 3);
        num("d4", "double4", w.value<double>(T::Vec4d, {0.1, 0.2, 0.3, 0.4}), {0.1, 0.2, 0.3, 0.4}, 4);
        num("h2", "half2", w.value(T::Vec2h, halves({0.5f, -2})), {0.5, -2}, 2);
        num("h3", "half3", w.value(T::Vec3h, halves({0.5f, -2, 4})), {0.5, -2, 4}, 3);
        num("h4", "half4", w.value(T::Vec4h, halves({0.5f, -2, 4, 0.125f})), {0.5, -2, 4, 0.125}, 4);
        num("i2", "int2", w.value<std::int32_t>(T::Vec2i, {-1, 2}), {-1, 2}, 2);
        num("i3", "int3", w.value<std::int32_t>(T::Vec3i, {-1, 2, -3}), {-1, 2, -3}, 3);
        num("i4", "int4", w.value<std::int32_t>(T::Vec4i, {-1, 2, -3, 4}), {-1, 2, -3, 4}, 4);
        num("m2", "matrix2d", w.value<double>(T::Matrix2d, {1, 2, 3, 4}), {1, 2, 3, 4}, 4);
        num("m3", "matrix3d", w.value<double>(T::Matrix3d, {1, 2, 3, 4, 5, 6, 7, 8, 9}), {1, 2, 3, 4, 5, 6, 7, 8, 9},
            9);
        std::vector<double> m4;
        for (int k = 0; k < 16; ++k) m4.push_back(k * 0.5);
        num("m4", "matrix4d", w.value(T::Matrix4d, m4), m4, 16);
        // On disk (i, j, k, real); read back (real, i, j, k).
        num("qf", "quatf", w.value<float>(T::Quatf, {0.5f, 0.25f, 0.125f, 1}), {1, 0.5, 0.25, 0.125}, 4);
        num("qd", "quatd", w.value<double>(T::Quatd, {0.1, 0.2, 0.3, 0.9}), {0.9, 0.1, 0.2, 0.3}, 4);
        // OpenUSD's inlined forms.
        num("inlineInt", "int", CrateWriter::inlined(T::Int, static_cast<std::uint32_t>(-3)), {-3});
        float half_ = 0.5f;
        std::uint32_t floatBits;
        std::memcpy(&floatBits, &half_, sizeof floatBits);
        num("inlineDouble", "double", CrateWriter::inlined(T::Double, floatBits), {0.5});
        num("inlineVec", "float3", CrateWriter::inlined(T::Vec3f, inlineBits({1, -2, 3})), {1, -2, 3}, 3);
        num("inlineMatrix", "matrix2d", CrateWriter::inlined(T::Matrix2d, inlineBits({2, -1})), {2, 0, 0, -1}, 4);
        // Arrays.
        num("fa", "float[]", w.array<float>(T::Float, {1.5f, 2.5f, -3}, 3), {1.5, 2.5, -3}, 1, true);
        num("ia", "int[]", w.array<std::int32_t>(T::Int, {1, -2, 3, 4}, 4), {1, -2, 3, 4}, 1, true);
        num("i64a", "int64[]", w.array<std::int64_t>(T::Int64, {-1, 1LL << 35}, 2), {-1, 34359738368.0}, 1, true);
        num("da", "double[]", w.array<double>(T::Double, {0.1, 0.2}, 2), {0.1, 0.2}, 1, true);
        num("ha", "half[]", w.array(T::Half, halves({1, 2, 0.75f}), 3), {1, 2, 0.75}, 1, true);
        num("f3a", "float3[]", w.array<float>(T::Vec3f, {1, 2, 3, 4, 5, 6}, 2), {1, 2, 3, 4, 5, 6}, 3, true);
        num("d3a", "double3[]", w.array<double>(T::Vec3d, {0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, 2),
            {0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, 3, true);
        num("i2a", "int2[]", w.array<std::int32_t>(T::Vec2i, {1, 2, 3, 4}, 2), {1, 2, 3, 4}, 2, true);
        num("qfa", "quatf[]", w.array<float>(T::Quatf, {0, 0, 0, 1, 0.5f, 0, 0, 0.5f}, 2), {1, 0, 0, 0, 0.5, 0.5, 0, 0},
            4, true);
        num("m4a", "matrix4d[]", w.array(T::Matrix4d, m4, 1), m4, 16, true);
        num("emptyA", "float[]", CrateWriter::rep(T::Float, 0, true), {}, 1, true);

        auto str = [&](std::string name, std::string type, Rep rep, ValueKind kind, std::vector<std::string> s,
                       bool a = false) {
            strings.push_back({std::move(name), std::move(type), rep, kind, std::move(s), a});
        };
        str("s", "string", w.stringValue("hello world"), ValueKind::String, {"hello world"});
        str("t", "token", w.tokenValue("someToken"), ValueKind::Token, {"someToken"});
        str("a", "asset", w.assetValue("./tex/wood.png"), ValueKind::Asset, {"./tex/wood.png"});
        str("ta", "token[]", w.tokenArray({"x", "y", "someToken"}), ValueKind::Token, {"x", "y", "someToken"}, true);
        str("sa", "string[]", w.stringArray({"one", "two"}), ValueKind::String, {"one", "two"}, true);

        CrateWriter::Fields rootFields;
        std::vector<std::string> properties;
        auto attribute = [&](const std::string& name, const std::string& type, CrateWriter::Fields extra) {
            properties.push_back(name);
            extra.insert(extra.begin(), {"typeName", w.tokenValue(type)});
            w.spec("/Root." + name, ST::Attribute, extra);
        };
        for (const auto& c : numerics) attribute(c.name, c.typeName, {{"default", c.rep}});
        for (const auto& c : strings) attribute(c.name, c.typeName, {{"default", c.rep}});
        attribute("ts", "float",
                  {{"custom", CrateWriter::inlined(T::Bool, 1)},
                   {"variability", CrateWriter::inlined(T::Variability, 1)},
                   {"timeSamples",
                    w.timeSamples({24, 1}, {w.value<float>(T::Float, {20}), w.value<float>(T::Float, {10})})}});
        properties.push_back("rel");
        w.spec("/Root.rel", ST::Relationship, {{"targetPaths", w.explicitPathListOp({"/Root/Child", "/Root.f"})}});

        Rep nested = w.dictionary({{"flag", w.value<std::uint8_t>(T::Bool, {1})}});
        w.spec("/", ST::PseudoRoot, {{"defaultPrim", w.tokenValue("Root")}, {"primChildren", w.tokenVector({"Root"})}});
        w.spec("/Root", ST::Prim,
               {{"specifier", CrateWriter::inlined(T::Specifier, 0)},
                {"typeName", w.tokenValue("Xform")},
                {"properties", w.tokenVector(properties)},
                {"primChildren", w.tokenVector({"Child"})},
                {"variantSetChildren", w.tokenVector({"look"})},
                {"customData", w.dictionary({{"note", w.stringValue("hi")},
                                             {"scale", w.value<double>(T::Double, {2.5})},
                                             {"nested", nested},
                                             {"empty", CrateWriter::inlined(T::Dictionary, 0)}})},
                {"apiSchemas", w.tokenListOp({"SkelBindingAPI"}, {"MaterialBindingAPI", "CollectionAPI"})},
                {"references", w.prependReferenceListOp({{"./model.usd", "/Model", 5, 2}})},
                {"variantSelection", w.variantSelection({{"look", "red"}})}});
        w.spec("/Root/Child", ST::Prim,
               {{"specifier", CrateWriter::inlined(T::Specifier, 2)}, {"typeName", w.tokenValue("Scope")}});
        w.spec("/Root{look=}", ST::VariantSet, {{"variantChildren", w.tokenVector({"red", "blue"})}});
        w.spec("/Root{look=red}", ST::Variant, {{"properties", w.tokenVector({"color"})}});
        w.spec("/Root{look=red}.color", ST::Attribute,
               {{"typeName", w.tokenValue("color3f")}, {"default", w.value<float>(T::Vec3f, {1, 0, 0})}});
        w.spec("/Root{look=blue}", ST::Variant, {});
        bytes = w.finish();
        layer = readCrateBytes(bytes, "fixture.usdc");
        root = layer->primAtPath("/Root");
        ASSERT_NE(root, nullptr);
    }

    std::vector<NumericCase> numerics;
    std::vector<StringCase> strings;
    std::vector<char> bytes;
    std::unique_ptr<Layer> layer;
    const PrimSpec* root = nullptr;
};

TEST_F(CrateWriterFixture, NumericValuesRoundTrip) {
    for (const auto& c : numerics) {
        SCOPED_TRACE(c.name);
        const AttributeSpec* a = root->attribute(c.name);
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->typeName, c.typeName);
        ASSERT_TRUE(a->hasDefault);
        EXPECT_EQ(a->defaultValue.typeName, c.typeName);
        EXPECT_EQ(a->defaultValue.kind, ValueKind::Numeric);
        EXPECT_EQ(a->defaultValue.isArray, c.isArray);
        EXPECT_EQ(a->defaultValue.components, c.components);
        EXPECT_EQ(a->defaultValue.numbers.vector(), c.numbers);
    }
}

TEST_F(CrateWriterFixture, StringValuesRoundTrip) {
    for (const auto& c : strings) {
        SCOPED_TRACE(c.name);
        const AttributeSpec* a = root->attribute(c.name);
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->defaultValue.typeName, c.typeName);
        EXPECT_EQ(a->defaultValue.kind, c.kind);
        EXPECT_EQ(a->defaultValue.isArray, c.isArray);
        EXPECT_EQ(a->defaultValue.strings, c.strings);
    }
}

// The reader's own type names (before the attribute's declared type is applied).
TEST_F(CrateWriterFixture, CrateTypeNames) {
    detail::CrateFile file(holdBytes(bytes), "fixture.usdc");
    detail::CrateValues values(file);
    std::map<std::string, std::string> expected;
    for (const auto& c : numerics) expected["/Root." + c.name] = c.typeName;
    for (const auto& c : strings) expected["/Root." + c.name] = c.typeName;
    expected["/Root{look=red}.color"] = "float3";
    std::size_t checked = 0;
    for (const auto& spec : file.specs()) {
        for (const detail::CrateField* field : file.fieldsOf(spec)) {
            if (file.token(field->token) != "default") continue;
            const std::string& path = file.path(spec.path);
            SCOPED_TRACE(path);
            ASSERT_TRUE(expected.count(path));
            EXPECT_EQ(values.value(field->value).typeName, expected[path]);
            ++checked;
        }
    }
    EXPECT_EQ(checked, expected.size());
    EXPECT_EQ(file.version().str(), "0.8.0");
}

TEST_F(CrateWriterFixture, TimeSamplesAndProperties) {
    const AttributeSpec* ts = root->attribute("ts");
    ASSERT_NE(ts, nullptr);
    EXPECT_TRUE(ts->custom);
    EXPECT_TRUE(ts->uniform);
    EXPECT_FALSE(ts->hasDefault);
    ASSERT_EQ(ts->timeSamples.size(), 2u);
    EXPECT_EQ(ts->timeSamples[0].first, 1.0);
    EXPECT_EQ(ts->timeSamples[0].second.numbers.vector(), std::vector<double>{10});
    EXPECT_EQ(ts->timeSamples[0].second.typeName, "float");
    EXPECT_EQ(ts->timeSamples[1].first, 24.0);
    EXPECT_EQ(ts->timeSamples[1].second.numbers.vector(), std::vector<double>{20});

    const RelationshipSpec* rel = root->relationship("rel");
    ASSERT_NE(rel, nullptr);
    EXPECT_EQ(rel->op, ListOpKind::Explicit);
    EXPECT_EQ(rel->targets, (std::vector<std::string>{"/Root/Child", "/Root.f"}));

    // Authored order: numerics, strings, ts, then the relationship.
    EXPECT_EQ(root->attributes.size(), numerics.size() + strings.size() + 1);
    EXPECT_EQ(root->attributes.front().name, "b");
}

TEST_F(CrateWriterFixture, PrimsAndMetadata) {
    EXPECT_TRUE(layer->warnings.empty());
    ASSERT_EQ(layer->rootPrims.size(), 1u);
    EXPECT_EQ(root->typeName, "Xform");
    EXPECT_EQ(root->specifier, Specifier::Def);
    const PrimSpec* child = layer->primAtPath("/Root/Child");
    ASSERT_NE(child, nullptr);
    EXPECT_EQ(child->typeName, "Scope");
    EXPECT_EQ(child->specifier, Specifier::Class);

    ASSERT_EQ(layer->metadata.size(), 1u);
    EXPECT_EQ(layer->metadata[0].key, "defaultPrim");
    EXPECT_EQ(layer->metadata[0].value.asString(), "Root");

    auto entries = [&](const std::string& key) {
        std::vector<const MetadataEntry*> out;
        for (const auto& e : root->metadata)
            if (e.key == key) out.push_back(&e);
        return out;
    };
    auto custom = entries("customData");
    ASSERT_EQ(custom.size(), 1u);
    const Value& dict = custom[0]->value;
    ASSERT_EQ(dict.kind, ValueKind::Dictionary);
    ASSERT_EQ(dict.size(), 4u);
    EXPECT_EQ((*dict.dictionary)[0].first, "note");
    EXPECT_EQ(dict.find("note")->strings, std::vector<std::string>{"hi"});
    EXPECT_EQ(dict.find("note")->typeName, "string");
    EXPECT_EQ(dict.find("scale")->numbers.vector(), std::vector<double>{2.5});
    EXPECT_EQ(dict.find("scale")->typeName, "double");
    ASSERT_NE(dict.find("nested"), nullptr);
    ASSERT_NE(dict.find("nested")->find("flag"), nullptr);
    EXPECT_EQ(dict.find("nested")->find("flag")->asDouble(), 1.0);
    EXPECT_EQ(dict.find("empty")->kind, ValueKind::Dictionary);
    EXPECT_EQ(dict.find("empty")->size(), 0u);

    auto schemas = entries("apiSchemas");
    ASSERT_EQ(schemas.size(), 2u);
    EXPECT_EQ(schemas[0]->op, ListOpKind::Prepend);
    EXPECT_EQ(schemas[0]->value.strings, std::vector<std::string>{"SkelBindingAPI"});
    EXPECT_EQ(schemas[1]->op, ListOpKind::Append);
    EXPECT_EQ(schemas[1]->value.strings, (std::vector<std::string>{"MaterialBindingAPI", "CollectionAPI"}));

    auto refs = entries("references");
    ASSERT_EQ(refs.size(), 1u);
    EXPECT_EQ(refs[0]->op, ListOpKind::Prepend);
    ASSERT_EQ(refs[0]->value.kind, ValueKind::List);
    ASSERT_EQ(refs[0]->value.items.size(), 1u);
    const Value& ref = refs[0]->value.items[0];
    EXPECT_EQ(ref.kind, ValueKind::Reference);
    EXPECT_EQ(ref.strings, (std::vector<std::string>{"./model.usd", "/Model"}));
    EXPECT_EQ(ref.numbers.vector(), (std::vector<double>{5, 2}));

    auto variants = entries("variants");
    ASSERT_EQ(variants.size(), 1u);
    ASSERT_NE(variants[0]->value.find("look"), nullptr);
    EXPECT_EQ(variants[0]->value.find("look")->strings, std::vector<std::string>{"red"});

    ASSERT_EQ(root->variantSets.size(), 1u);
    const VariantSetSpec& look = root->variantSets[0];
    EXPECT_EQ(look.name, "look");
    ASSERT_EQ(look.variants.size(), 2u);
    EXPECT_EQ(look.variants[0].name, "red");
    EXPECT_EQ(look.variants[1].name, "blue");
    ASSERT_EQ(look.variants[0].attributes.size(), 1u);
    EXPECT_EQ(look.variants[0].attributes[0].typeName, "color3f");
    EXPECT_EQ(look.variants[0].attributes[0].defaultValue.numbers.vector(), (std::vector<double>{1, 0, 0}));
    EXPECT_TRUE(look.variants[1].attributes.empty());
}

}  // namespace
}  // namespace fluence::usd
