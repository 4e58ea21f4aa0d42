// SdfPathExpression evaluation (scene/path_expression.h) and the collection predicate library
// (scene/prim_predicates.h) on a small composed stage: glob elements, `//` stretches, relative
// patterns, predicates, references, the set operators and their precedence, and syntax errors
// naming their column.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "scene/path_expression.h"
#include "scene/usda_parser.h"

namespace fluence::usd {
namespace {

const char* kScene = R"(#usda 1.0
def Xform "World" (kind = "assembly")
{
    def Xform "Chair" (
        kind = "component"
        prepend apiSchemas = ["CollectionAPI:legs", "MaterialBindingAPI"]
    )
    {
        def Mesh "Seat" { }
        def Cube "Leg1" { }
        def Cube "Leg2" { }
        def Sphere "Knob" { }
    }
    def Xform "Table" (kind = "component")
    {
        def Mesh "Top" { }
        def BasisCurves "Grain" { }
    }
    def SphereLight "Lamp" { }
    over "Ghost" { }
}
class "Template"
{
    def Mesh "Proto" { }
}
)";

class PathExpressionTest : public ::testing::Test {
protected:
    std::unique_ptr<Stage> stage_ = std::make_unique<Stage>(parseUsdaString(kScene, "scene.usda"));

    // Whether the expression (anchored at `anchor`) matches `path`; %:legs and %/World/Chair:legs
    // hold the legs.
    bool match(const std::string& expression, const std::string& path, const std::string& anchor = "/World") {
        PathExpression e(expression, anchor);
        return e.matches(path, *stage_, [](const PathExpression::Reference& r, const std::string& p) {
            return r.prim == "/World/Chair" && r.name == "legs" && p.find("/Leg") != std::string::npos;
        });
    }
    std::string error(const std::string& expression) {
        try {
            PathExpression e(expression, "/World");
        } catch (const PathExpressionError& e) {
            return e.what();
        }
        return "no error";
    }
};

TEST_F(PathExpressionTest, GlobsMatchOneLevelAndStretchesAnyNumber) {
    EXPECT_TRUE(match("/World/*", "/World/Chair"));
    EXPECT_FALSE(match("/World/*", "/World/Chair/Seat"));  // no expansion below what matches
    EXPECT_FALSE(match("/World/*", "/World"));
    EXPECT_TRUE(match("/World/*/Leg?", "/World/Chair/Leg2"));
    EXPECT_TRUE(match("/World/Chair/Leg[12]", "/World/Chair/Leg1"));
    EXPECT_FALSE(match("/World/Chair/Leg[!12]", "/World/Chair/Leg1"));
    EXPECT_TRUE(match("/World/Chair/[K-L]*", "/World/Chair/Knob"));
    EXPECT_TRUE(match("//Seat", "/World/Chair/Seat"));
    EXPECT_TRUE(match("//", "/World/Table/Grain"));
    EXPECT_TRUE(match("/World//", "/World"));  // a trailing stretch matches its prefix too
    EXPECT_TRUE(match("/World//", "/World/Table/Top"));
    EXPECT_FALSE(match("/World//", "/Template/Proto"));
    EXPECT_TRUE(match("/World//Top", "/World/Table/Top"));
    EXPECT_FALSE(match("/World//Top", "/World/Chair/Seat"));
    EXPECT_FALSE(match("/World/Chair.xformOp:translate", "/World/Chair"));  // a property names no prim
}

TEST_F(PathExpressionTest, RelativePatternsAreAnchoredAtTheCollectionsPrim) {
    EXPECT_TRUE(match("Chair/Seat", "/World/Chair/Seat"));
    EXPECT_TRUE(match(".", "/World"));
    EXPECT_TRUE(match(".//Top", "/World/Table/Top"));
    EXPECT_TRUE(match("../Table/Top", "/World/Table/Top", "/World/Chair"));
    EXPECT_FALSE(match("../Top", "/World/Table/Top", "/World/Chair"));
    EXPECT_TRUE(match("..//Grain", "/World/Table/Grain", "/World/Chair"));
}

TEST_F(PathExpressionTest, PredicatesReadTheComposedPrim) {
    EXPECT_TRUE(match("//{isa:Gprim}", "/World/Chair/Leg1"));
    EXPECT_TRUE(match("//{isa:Gprim}", "/World/Table/Grain"));  // BasisCurves -> Curves -> PointBased -> Gprim
    EXPECT_FALSE(match("//{isa:Gprim}", "/World/Chair"));
    EXPECT_TRUE(match("//{isa:Mesh,Cube}", "/World/Chair/Leg2"));
    EXPECT_FALSE(match("//{isa(PointBased, strict=true)}", "/World/Chair/Seat"));
    EXPECT_TRUE(match("//{isa:BoundableLightBase}", "/World/Lamp"));
    EXPECT_TRUE(match("/World/{kind:component}", "/World/Table"));
    EXPECT_TRUE(match("/World/{model}", "/World/Table"));
    EXPECT_FALSE(match("/World/{group}", "/World/Table"));
    EXPECT_TRUE(match("/{group}", "/World"));
    EXPECT_FALSE(match("/{kind(group, strict=true)}", "/World"));
    EXPECT_TRUE(match("/World/{hasAPI:CollectionAPI}", "/World/Chair"));
    EXPECT_TRUE(match("/World/{hasAPI(CollectionAPI, instanceName=legs)}", "/World/Chair"));
    EXPECT_FALSE(match("/World/{hasAPI(CollectionAPI, instanceName=arms)}", "/World/Chair"));
    EXPECT_TRUE(match("/World/{specifier:over}", "/World/Ghost"));
    EXPECT_FALSE(match("/World/{defined}", "/World/Ghost"));
    EXPECT_TRUE(match("//{abstract}", "/Template/Proto"));
    EXPECT_FALSE(match("//{abstract}", "/World/Table/Top"));
    // not, and, or, the implied and, parentheses; a predicate on a named element and on a stretch.
    EXPECT_TRUE(match("//{isa:Gprim and not isa:Mesh}", "/World/Chair/Knob"));
    EXPECT_FALSE(match("//{isa:Gprim not isa:Sphere}", "/World/Chair/Knob"));
    EXPECT_TRUE(match("//{isa:Sphere or (isa:Mesh defined)}", "/World/Table/Top"));
    EXPECT_TRUE(match("/World/T*{kind:component}//Top", "/World/Table/Top"));
    EXPECT_FALSE(match("/World/C*{kind:component}//Top", "/World/Table/Top"));
}

TEST_F(PathExpressionTest, SetOperatorsAndTheirPrecedence) {
    EXPECT_TRUE(match("/World/Chair/Seat /World/Table/Top", "/World/Table/Top"));  // implied union
    EXPECT_TRUE(match("/World/Chair/* - /World/Chair/Knob", "/World/Chair/Seat"));
    EXPECT_FALSE(match("/World/Chair/* - /World/Chair/Knob", "/World/Chair/Knob"));
    EXPECT_TRUE(match("~/World//", "/Template/Proto"));
    EXPECT_TRUE(match("//{isa:Cube} & /World/Chair/Leg1", "/World/Chair/Leg1"));
    EXPECT_FALSE(match("//{isa:Cube} & /World/Chair/Leg1", "/World/Chair/Leg2"));
    // Union binds tighter than difference, as OpenUSD builds it: A - B + C is A - (B + C).
    EXPECT_FALSE(match("/World/Chair/* - /World/Chair/Seat + /World/Chair/Knob", "/World/Chair/Knob"));
    EXPECT_TRUE(match("(/World/Chair/* - /World/Chair/Seat) + /World/Chair/Knob", "/World/Chair/Knob"));
    // Intersection binds looser than union: A + B & C is (A + B) & C.
    EXPECT_FALSE(match("/World/Chair/Seat + /World/Chair/Knob & //{isa:Sphere}", "/World/Chair/Seat"));
    EXPECT_TRUE(match("/World/Chair/Seat + (/World/Chair/Knob & //{isa:Sphere})", "/World/Chair/Seat"));
    // References: other collections' members; %_ (the weaker expression) is nothing.
    EXPECT_TRUE(match("%/World/Chair:legs", "/World/Chair/Leg1"));
    EXPECT_TRUE(match("%:legs", "/World/Chair/Leg2", "/World/Chair"));
    EXPECT_FALSE(match("/World/Chair/* - %/World/Chair:legs", "/World/Chair/Leg2"));
    EXPECT_FALSE(match("%_", "/World/Chair/Leg2"));
    PathExpression e("%/World/Chair:legs + %:looks + %_", "/World");
    ASSERT_EQ(e.references().size(), 2u);
    EXPECT_EQ(e.references()[1].prim, "/World");
    EXPECT_EQ(e.references()[1].name, "looks");
}

TEST_F(PathExpressionTest, SyntaxErrorsNameTheirColumn) {
    EXPECT_EQ(error("/World/{isa:Mesh"), "column 17: expected '}'");
    EXPECT_EQ(error("/World/(x"), "column 8: expected a prim name pattern after '/'");
    EXPECT_EQ(error("(/World"), "column 8: expected ')'");
    EXPECT_EQ(error("/World/Chair/Leg[12"), "column 17: '[' without ']'");
    EXPECT_EQ(error("//{colour:red}"),
              "column 4: unknown predicate 'colour' (known: abstract, defined, model, group, "
              "kind, specifier, isa, hasAPI)");
    EXPECT_EQ(error("//{specifier:dif}"), "column 4: predicate 'specifier': 'dif' is not def, over or class");
    EXPECT_EQ(error("%/World"), "column 1: a reference is %<prim path>:<collection name>");
    EXPECT_EQ(error("/World +"), "column 9: expected a path pattern, a reference or '('");
    EXPECT_EQ(error(std::string(300, '(') + "/World" + std::string(300, ')')), "column 201: nested more than 200 deep");
    EXPECT_NE(error("//{" + std::string(300, '(') + "isa:Mesh" + std::string(300, ')') + "}")
                  .find("nested more than 200 deep"),
              std::string::npos);
}

TEST_F(PathExpressionTest, StretchesDoNotBacktrackExponentially) {
    // 40 stretches against a 30-level path that does not match: every (element, level) pair once.
    std::string deep, pattern;
    for (int i = 0; i < 30; ++i) deep += "/a";
    for (int i = 0; i < 40; ++i) pattern += "//a";
    EXPECT_FALSE(match(pattern + "/b", deep));
    EXPECT_TRUE(match(pattern.substr(0, 3 * 30), deep));
}

}  // namespace
}  // namespace fluence::usd
