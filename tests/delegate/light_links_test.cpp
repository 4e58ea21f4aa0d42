// Light and shadow links read from UsdLux collections (delegate/light_links.h): UsdCollectionAPI's
// membership rules (nearest named ancestor, exclude over include, includeRoot, explicitOnly,
// collections included in collections),
// instance proxies, and a scene without links left in group 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::Populated;

const std::string kCubes = R"(
def Xform "World"
{
    def Cube "A" { }
    def Xform "B"
    {
        def Cube "Inner" { }
        def Cube "Kept" { }
    }
    def Cube "Blocker" { }
}
)";

int lightIndex(const Populated& p, const std::string& name) {
    const auto& lights = p.result.scene.lights;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].name == name) return int(i);
    ADD_FAILURE() << "no light " << name;
    return -1;
}

const render::LightLinkGroup* groupOf(const Populated& p, int group) {
    return group == 0 ? nullptr : &p.result.scene.lightLinkGroups.at(std::size_t(group - 1));
}

bool listed(const std::vector<int>& lights, int light) {
    return std::find(lights.begin(), lights.end(), light) != lights.end();
}

// Whether light `light` lights the mesh `mesh`, and whether the mesh casts its shadows.
bool lit(const Populated& p, const std::string& mesh, const std::string& light) {
    const render::LightLinkGroup* g = groupOf(p, p.mesh(mesh)->linkGroup);
    return !g || !listed(g->unlit, lightIndex(p, light));
}
bool shadows(const Populated& p, const std::string& mesh, const std::string& light) {
    const render::LightLinkGroup* g = groupOf(p, p.mesh(mesh)->linkGroup);
    return !g || !listed(g->unshadowed, lightIndex(p, light));
}

TEST(LightLinksDelegate, SceneWithoutLinksStaysInGroupZero) {
    const Populated p = populate(kCubes + R"(
def SphereLight "Key" (prepend apiSchemas = ["ShadowAPI"])
{
    bool collection:lightLink:includeRoot = 1
}
)");
    EXPECT_TRUE(p.result.scene.lightLinkGroups.empty());
    for (const render::MeshDesc& m : p.result.scene.meshes) EXPECT_EQ(m.linkGroup, 0) << m.name;
}

TEST(LightLinksDelegate, NearestNamedAncestorDecides) {
    const Populated p = populate(kCubes + R"(
def SphereLight "Key"
{
    bool collection:lightLink:includeRoot = 0
    rel collection:lightLink:includes = [</World/A>, </World/B>]
    rel collection:lightLink:excludes = </World/B/Inner>
}
def SphereLight "Fill"
{
    rel collection:lightLink:excludes = </World/B>
    rel collection:lightLink:includes = </World/B/Kept>
    rel collection:shadowLink:excludes = </World/Blocker>
}
def SphereLight "Rim"
{
}
)");
    EXPECT_TRUE(lit(p, "/World/A", "/Key"));
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Key"));
    EXPECT_TRUE(lit(p, "/World/B/Kept", "/Key"));
    EXPECT_FALSE(lit(p, "/World/Blocker", "/Key"));  // includeRoot = 0 and not included
    EXPECT_TRUE(lit(p, "/World/A", "/Fill"));        // includeRoot's fallback is true for UsdLux
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Fill"));
    EXPECT_TRUE(lit(p, "/World/B/Kept", "/Fill"));
    EXPECT_TRUE(lit(p, "/World/Blocker", "/Fill"));
    EXPECT_FALSE(shadows(p, "/World/Blocker", "/Fill"));
    EXPECT_TRUE(shadows(p, "/World/Blocker", "/Key"));
    EXPECT_TRUE(shadows(p, "/World/A", "/Fill"));
    for (const char* mesh : {"/World/A", "/World/B/Inner", "/World/B/Kept", "/World/Blocker"})
        EXPECT_TRUE(lit(p, mesh, "/Rim")) << mesh;
    // Meshes with the same links share a group.
    EXPECT_EQ(p.mesh("/World/A")->linkGroup, p.mesh("/World/B/Kept")->linkGroup);
}

TEST(LightLinksDelegate, ExcludeWinsOverAnIncludeOfTheSamePathAndExplicitOnlyDoesNotExpand) {
    const Populated p = populate(kCubes + R"(
def SphereLight "Key"
{
    rel collection:lightLink:includes = </World/A>
    rel collection:lightLink:excludes = </World/A>
}
def SphereLight "Narrow"
{
    uniform token collection:lightLink:expansionRule = "explicitOnly"
    rel collection:lightLink:includes = [</World/B>, </World/A>]
}
)");
    EXPECT_FALSE(lit(p, "/World/A", "/Key"));
    EXPECT_TRUE(lit(p, "/World/A", "/Narrow"));
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Narrow"));  // not expanded below /World/B
}

TEST(LightLinksDelegate, IncludedCollectionsMergeTheirRulesAndLaterOnesWin) {
    // Key includes the Scope's collection "set" (A and B but B/Inner), then excludes B/Kept; Fill
    // includes "set" then the whole of B again, which overrides set's exclude of B/Inner.
    const Populated p = populate(kCubes + R"(
def Scope "Sets" (prepend apiSchemas = ["CollectionAPI:set"])
{
    rel collection:set:includes = [</World/A>, </World/B>]
    rel collection:set:excludes = </World/B/Inner>
}
def SphereLight "Key"
{
    bool collection:lightLink:includeRoot = 0
    rel collection:lightLink:includes = </Sets.collection:set>
    rel collection:lightLink:excludes = </World/B/Kept>
}
def SphereLight "Fill"
{
    bool collection:lightLink:includeRoot = 0
    rel collection:lightLink:includes = [</Sets.collection:set>, </World/B/Inner>]
}
)");
    EXPECT_TRUE(lit(p, "/World/A", "/Key"));
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Key"));
    EXPECT_FALSE(lit(p, "/World/B/Kept", "/Key"));
    EXPECT_FALSE(lit(p, "/World/Blocker", "/Key"));  // the included collection's includeRoot is false
    EXPECT_TRUE(lit(p, "/World/B/Inner", "/Fill"));
    EXPECT_TRUE(lit(p, "/World/B/Kept", "/Fill"));
    EXPECT_FALSE(lit(p, "/World/Blocker", "/Fill"));
    EXPECT_TRUE(p.warnings.empty()) << p.warnings.front();
}

TEST(LightLinksDelegate, ACycleOfCollectionsAndAMissingOneAreWarnedAbout) {
    const Populated p = populate(kCubes + R"(
def Scope "Sets" (prepend apiSchemas = ["CollectionAPI:one", "CollectionAPI:two"])
{
    rel collection:one:includes = [</World/A>, </Sets.collection:two>]
    rel collection:two:includes = [</World/Blocker>, </Sets.collection:one>]
}
def SphereLight "Key"
{
    bool collection:lightLink:includeRoot = 0
    rel collection:lightLink:includes = [</Sets.collection:one>, </Nowhere.collection:x>]
}
)");
    EXPECT_TRUE(lit(p, "/World/A", "/Key"));
    EXPECT_TRUE(lit(p, "/World/Blocker", "/Key"));
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Key"));
    auto warned = [&](const std::string& what) {
        return std::any_of(p.warnings.begin(), p.warnings.end(),
                           [&](const std::string& w) { return w.find(what) != std::string::npos; });
    };
    EXPECT_TRUE(warned("cycle")) << ::testing::PrintToString(p.warnings);
    EXPECT_TRUE(warned("</Nowhere.collection:x>")) << ::testing::PrintToString(p.warnings);
}

TEST(LightLinksDelegate, MembershipExpressionsDecideInExpressionMode) {
    // Expression mode needs an empty rule map: includeRoot off and no includes or excludes.
    const Populated p = populate(kCubes + R"(
def Scope "Sets" (prepend apiSchemas = ["CollectionAPI:blockers"])
{
    rel collection:blockers:includes = </World/Blocker>
}
def SphereLight "Children"
{
    bool collection:lightLink:includeRoot = 0
    uniform pathExpression collection:lightLink:membershipExpression = "/World/*"
}
def SphereLight "Cubes"
{
    bool collection:lightLink:includeRoot = 0
    uniform pathExpression collection:lightLink:membershipExpression = "//{isa:Gprim} - %/Sets:blockers - /World/B/K*"
}
def SphereLight "Ignored"
{
    rel collection:lightLink:includes = </World/A>
    bool collection:lightLink:includeRoot = 0
    uniform pathExpression collection:lightLink:membershipExpression = "/World//"
}
def SphereLight "Broken"
{
    bool collection:lightLink:includeRoot = 0
    uniform pathExpression collection:lightLink:membershipExpression = "/World/{isa:Mesh"
}
)");
    EXPECT_TRUE(lit(p, "/World/A", "/Children"));
    EXPECT_TRUE(lit(p, "/World/Blocker", "/Children"));
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Children"));  // not expanded below what matches
    EXPECT_TRUE(lit(p, "/World/A", "/Cubes"));
    EXPECT_TRUE(lit(p, "/World/B/Inner", "/Cubes"));
    EXPECT_FALSE(lit(p, "/World/B/Kept", "/Cubes"));
    EXPECT_FALSE(lit(p, "/World/Blocker", "/Cubes"));
    EXPECT_TRUE(lit(p, "/World/A", "/Ignored"));  // relationship mode: the expression is ignored
    EXPECT_FALSE(lit(p, "/World/B/Inner", "/Ignored"));
    for (const char* mesh : {"/World/A", "/World/B/Inner", "/World/Blocker"})
        EXPECT_FALSE(lit(p, mesh, "/Broken")) << mesh;
    ASSERT_EQ(p.warnings.size(), 1u) << ::testing::PrintToString(p.warnings);
    EXPECT_NE(p.warnings[0].find("/Broken: collection:lightLink:membershipExpression"), std::string::npos)
        << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("column 17"), std::string::npos) << p.warnings[0];
}

TEST(LightLinksDelegate, InstanceProxiesAreJudgedAtTheirOwnPaths) {
    const Populated p = populate(R"(
def Xform "Proto"
{
    def Cube "Geo" { }
}
def Xform "I1" (instanceable = true
    references = </Proto>) { }
def Xform "I2" (instanceable = true
    references = </Proto>) { }
def SphereLight "Key"
{
    rel collection:lightLink:excludes = </I2/Geo>
}
)");
    const auto& instances = p.result.scene.instances;
    ASSERT_EQ(instances.size(), 2u);
    const int key = lightIndex(p, "/Key");
    for (const render::InstanceDesc& i : instances) {
        const render::LightLinkGroup* g = groupOf(p, i.linkGroup);
        const bool unlit = g && listed(g->unlit, key);
        EXPECT_EQ(unlit, i.name == "/I2") << i.name;
    }
}

}  // namespace
}  // namespace fluence::delegate
