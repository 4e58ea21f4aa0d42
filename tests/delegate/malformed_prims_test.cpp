// One bad prim never sinks a render (delegate/render_index.h): a malformed prim is skipped with
// one warning naming it and the reason, the rest is described; in strict mode it is a SceneError.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::populateStrict;
using testing::stageFrom;

// A well-formed quad beside every malformed prim.
const std::string kGoodQuad = R"(
def Mesh "Good"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
}
)";

// A mesh /Bad of two quads with `scheme` and `lines` added.
std::string badMesh(const std::string& scheme, const std::string& counts, const std::string& indices,
                    const std::string& lines = "") {
    return "def Mesh \"Bad\"\n{\n    uniform token subdivisionScheme = \"" + scheme +
           "\"\n    int[] faceVertexCounts = " + counts + "\n    int[] faceVertexIndices = " + indices +
           "\n    point3f[] points = [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1), (2, 0, 1), (2, 1, 1)]\n" + lines +
           "}\n";
}

const std::string kTwoQuads = "[0, 1, 2, 3, 1, 4, 5, 2]";

struct MalformedCase {
    const char* what;
    std::string usda;
    const char* reason;  // a fragment of the warning
};

std::vector<MalformedCase> malformedCases() {
    return {
        {"face counts that do not match the indices", badMesh("none", "[4, 4]", "[0, 1, 2, 3, 1, 4]"),
         "faceVertexCounts add up to 8 but faceVertexIndices has 6 entries"},
        {"an index past the points", badMesh("none", "[4, 4]", "[0, 1, 2, 3, 1, 4, 9, 2]"),
         "faceVertexIndices[6] = 9 is out of range (6 points)"},
        {"a GeomSubset index out of range",
         badMesh("none", "[4, 4]", kTwoQuads,
                 "    def GeomSubset \"Far\"\n    {\n        uniform token elementType = \"face\"\n"
                 "        uniform token familyName = \"materialBind\"\n        int[] indices = [1, 5]\n    }\n"),
         "/Bad/Far: indices[1] = 5 is not a face of /Bad (2 faces)"},
        {"a loop-scheme mesh with quads", badMesh("loop", "[4, 4]", kTwoQuads),
         "the loop scheme needs triangles, but face 0 has 4 points"},
        {"a primvar of the wrong size",
         badMesh("none", "[4, 4]", kTwoQuads,
                 "    color3f[] primvars:displayColor = [(1, 0, 0), (0, 1, 0)] (interpolation = \"vertex\")\n"),
         "'primvars:displayColor' has 2 values but vertex interpolation needs 6"},
    };
}

TEST(MalformedPrims, AreSkippedWithOneWarningNamingThePrimAndTheReason) {
    for (const MalformedCase& c : malformedCases()) {
        SCOPED_TRACE(c.what);
        testing::Populated p = populate(kGoodQuad + c.usda);
        ASSERT_EQ(p.result.scene.meshes.size(), 1u);
        EXPECT_EQ(p.result.scene.meshes[0].name, "/Good");
        ASSERT_EQ(p.warnings.size(), 1u);
        EXPECT_EQ(p.warnings[0].rfind("/Bad: not rendered: test.usda:", 0), 0u) << p.warnings[0];
        EXPECT_NE(p.warnings[0].find(c.reason), std::string::npos) << p.warnings[0];
    }
}

TEST(MalformedPrims, AreSceneErrorsInStrictMode) {
    for (const MalformedCase& c : malformedCases()) {
        SCOPED_TRACE(c.what);
        try {
            populateStrict(kGoodQuad + c.usda);
            ADD_FAILURE() << "strict mode accepted " << c.what;
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find(c.reason), std::string::npos) << e.what();
        }
    }
}

// A well-formed mesh /Rig/Mesh under an Xform whose ops are `ops`.
std::string rig(const std::string& ops) {
    return "def Xform \"Rig\"\n{\n" + ops +
           "    uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:scale\"]\n" +
           badMesh("none", "[4, 4]", kTwoQuads) + "}\n";
}

TEST(MalformedPrims, ABadXformOpSkipsThePrimsBelowIt) {
    testing::Populated p =
        populate(kGoodQuad + rig("    double xformOp:translate = 5\n    float3 xformOp:scale = (2, 2, 2)\n"));
    ASSERT_EQ(p.result.scene.meshes.size(), 1u);
    EXPECT_EQ(p.result.scene.meshes[0].name, "/Good");
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("/Rig/Bad: not rendered: "), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("/Rig: xform op 'xformOp:translate' needs 3 numbers"), std::string::npos)
        << p.warnings[0];
}

// As UsdGeomXformable: an op xformOpOrder names without a value is left out, with a warning.
TEST(MalformedPrims, AnXformOpWithoutAValueIsSkipped) {
    testing::Populated p = populate(kGoodQuad + rig("    float3 xformOp:scale = (2, 2, 2)\n"));
    ASSERT_EQ(p.result.scene.meshes.size(), 2u);
    const render::MeshDesc* scaled = p.mesh("/Rig/Bad");
    ASSERT_NE(scaled, nullptr);
    EXPECT_EQ(scaled->positions.at(5), Vec3f(4, 2, 2)) << "scaled, not translated";
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_EQ(p.warnings[0],
              "/Rig: xformOpOrder names 'xformOp:translate', which has no value; the op is skipped, as USD skips it");
}

TEST(MalformedPrims, AFailedPrimIsTriedAgainAfterAnEditAndWarnsOnce) {
    auto stage = stageFrom(testing::kCamera + kGoodQuad + badMesh("none", "[4, 4]", "[0, 1, 2, 3, 1, 4]"));
    std::vector<std::string> warnings;
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&](const std::string& path, const std::string& message) {
        warnings.push_back(path + ": " + message);
    };
    SceneDelegate delegate(*stage, options);
    delegate.sync();
    EXPECT_TRUE(delegate.renderIndex().find("/Bad")->failed());
    delegate.setTime(2.0);  // a failed prim is read again at a new time, and fails the same way
    delegate.sync();
    EXPECT_EQ(delegate.sceneDescription().meshes.size(), 1u);
    EXPECT_EQ(warnings.size(), 1u) << "the same failure is warned about once";

    delegate.setAttribute("/Bad", "faceVertexIndices", usd::Value::numeric("int[]", {0, 1, 2, 3, 1, 4, 5, 2}, 1, true));
    delegate.sync();
    EXPECT_FALSE(delegate.renderIndex().find("/Bad")->failed());
    EXPECT_EQ(delegate.sceneDescription().meshes.size(), 2u) << "the fixed mesh renders";
}

TEST(MalformedPrims, AMalformedCameraIsSkippedUnlessItIsTheOneAskedFor) {
    const std::string scene = "#usda 1.0\ndef Camera \"Broken\"\n{\n    float focalLength = -1\n}\n" + kGoodQuad;
    testing::Populated p = populate(scene);
    EXPECT_EQ(p.result.cameraPath, "") << "framed by the default camera";
    ASSERT_GE(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("/Broken: not rendered: "), std::string::npos) << p.warnings[0];
    EXPECT_NE(p.warnings[0].find("focalLength must be positive"), std::string::npos) << p.warnings[0];
    try {
        populate(scene, "/Broken");
        ADD_FAILURE() << "a malformed camera asked for was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("camera /Broken cannot be used: "), std::string::npos) << e.what();
    }
}

// UsdGeomImageable reads a visibility or purpose that is not a token as not authored
// (UsdAttribute::Get<TfToken> fails): the prim renders, with a warning; under strict, an error.
TEST(MalformedPrims, AVisibilityOrPurposeThatIsNotATokenIsReadAsNotAuthored) {
    for (const std::string& attribute :
         {std::string("int visibility = 3"), std::string("string visibility = \"invisible\""),
          std::string("string purpose = \"guide\"")}) {
        SCOPED_TRACE(attribute);
        const std::string scene =
            kGoodQuad + "def Xform \"Rig\"\n{\n    " + attribute + "\n" + badMesh("none", "[4, 4]", kTwoQuads) + "}\n";
        testing::Populated p = populate(scene);
        EXPECT_NE(p.mesh("/Rig/Bad"), nullptr) << "rendered, the value read as not authored";
        ASSERT_EQ(p.warnings.size(), 1u);
        EXPECT_EQ(p.warnings[0].rfind("/Rig: read as not authored, as USD reads it: test.usda:", 0), 0u)
            << p.warnings[0];
        EXPECT_NE(p.warnings[0].find("must be a token, got"), std::string::npos) << p.warnings[0];
        EXPECT_THROW(populateStrict(scene), SceneError);
    }
}

// A point-instancer prototype /Protos with a well-formed quad and a malformed mesh; the
// instancer places it twice.
std::string instancedPrototype(const std::string& badLines) {
    return R"(
def PointInstancer "Instancer"
{
    rel prototypes = </Instancer/Protos>
    int[] protoIndices = [0, 0]
    point3f[] positions = [(0, 0, 0), (5, 0, 0)]
    def Xform "Protos"
    {
)" + kGoodQuad +
           badLines + R"(
    }
}
)";
}

TEST(MalformedPrims, InAPrototypeOnlyTheMalformedPrimIsLeftOut) {
    for (const MalformedCase& c : malformedCases()) {
        SCOPED_TRACE(c.what);
        testing::Populated p = populate(instancedPrototype(c.usda));
        ASSERT_EQ(p.result.scene.prototypes.size(), 1u);
        EXPECT_EQ(p.result.scene.prototypes[0].meshes.size(), 1u) << "the well-formed quad stays";
        EXPECT_EQ(p.result.scene.instances.size(), 2u);
        ASSERT_EQ(p.warnings.size(), 1u);
        EXPECT_EQ(p.warnings[0].rfind("/Instancer/Protos/Bad: not rendered: test.usda:", 0), 0u) << p.warnings[0];
        std::string reason = c.reason;  // the prims it names are inside the prototype
        for (std::size_t at = reason.find("/Bad"); at != std::string::npos; at = reason.find("/Bad", at + 20))
            reason.replace(at, 4, "/Instancer/Protos/Bad");
        EXPECT_NE(p.warnings[0].find(reason), std::string::npos) << p.warnings[0];
        EXPECT_THROW(populateStrict(instancedPrototype(c.usda)), SceneError);
    }
}

TEST(MalformedPrims, InANativeInstanceOnlyTheMalformedMeshIsLeftOut) {
    const std::string scene = "def Xform \"Asset\"\n{\n" + kGoodQuad + badMesh("none", "[4, 4]", "[0, 1, 2, 3, 1, 4]") +
                              "}\n" +
                              "def \"A\" (instanceable = true\n references = </Asset>)\n{\n}\n"
                              "def \"B\" (instanceable = true\n references = </Asset>)\n{\n}\n";
    testing::Populated p = populate(scene);
    ASSERT_EQ(p.result.scene.prototypes.size(), 1u);
    EXPECT_EQ(p.result.scene.prototypes[0].meshes.size(), 1u);
    EXPECT_EQ(p.result.scene.instances.size(), 2u);
    EXPECT_NE(p.mesh("/Asset/Good"), nullptr);
    EXPECT_EQ(p.mesh("/Asset/Bad"), nullptr);
}

TEST(MalformedPrims, TheDelegateListsEveryMalformedPrim) {
    auto stage = stageFrom(testing::kCamera + kGoodQuad + badMesh("loop", "[4, 4]", kTwoQuads) +
                           "def Xform \"Hidden\"\n{\n    int visibility = 0\n}\n" +
                           instancedPrototype(badMesh("none", "[4, 4]", "[0, 1, 2, 3, 1, 4]")));
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [](const std::string&, const std::string&) {};
    SceneDelegate delegate(*stage, options);
    delegate.sync();
    std::vector<MalformedPrim> malformed = delegate.malformedPrims();
    ASSERT_EQ(malformed.size(), 3u);
    EXPECT_EQ(malformed[0].path, "/Bad");
    EXPECT_NE(malformed[0].reason.find("the loop scheme needs triangles"), std::string::npos) << malformed[0].reason;
    EXPECT_EQ(malformed[1].path, "/Hidden");
    EXPECT_EQ(malformed[2].path, "/Instancer/Protos/Bad");
}

}  // namespace
}  // namespace fluence::delegate
