// BasisCurves and Points inside native instances, nested instances and PointInstancer prototypes
// (delegate/instancing.h): each prototype holds its curves and points once, and every instance
// renders them: a ray aimed at each placement's curve (or point) hits it, named by its instance.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "render/render_scene.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;

// A straight hair along x from -0.5 to 0.5, of radius 0.05, named `name`, with `extra` lines.
std::string strand(const std::string& name, const std::string& extra = "") {
    return "def BasisCurves \"" + name +
           "\"\n{\n    uniform token type = \"linear\"\n    int[] curveVertexCounts = [2]\n"
           "    point3f[] points = [(-0.5, 0, 0), (0.5, 0, 0)]\n    float[] widths = [0.1]\n" +
           extra + "}\n";
}

// A red hair (strand()) and a sphere of radius 0.1 above it at y = 0.5, under /_Hair.
const std::string kHairPrototype = "class Xform \"_Hair\"\n{\n" +
                                   strand("Strand", "    color3f[] primvars:displayColor = [(1, 0, 0)]\n") +
                                   "def Points \"Dot\"\n{\n    point3f[] points = [(0, 0.5, 0)]\n"
                                   "    float[] widths = [0.2]\n}\n}\n";

// An instanceable Xform `name` referencing `prototype`, moved by `translate` ("" for none).
std::string instance(const std::string& name, const std::string& prototype, const std::string& translate) {
    std::string usda =
        "def Xform \"" + name + "\" (\n    instanceable = true\n    references = <" + prototype + ">\n)\n{\n";
    if (!translate.empty())
        usda += "    double3 xformOp:translate = (" + translate +
                ")\n    uniform token[] xformOpOrder = [\"xformOp:translate\"]\n";
    return usda + "}\n";
}

// Shoots a ray down -z at (x, y) and returns the name of what it hits ("" for nothing), and
// whether that is a curve.
std::pair<std::string, bool> hitAt(const render::RenderScene& scene, double x, double y) {
    auto hit = scene.intersect(render::Ray{Vec3f(float(x), float(y), 10.0f), Vec3f(0, 0, -1)});
    if (!hit) return {"", false};
    return {scene.objectNames().name(hit->objectName), hit->material.hair.has_value()};
}

TEST(InstancedCurves, EachNativeInstanceRendersThePrototypesCurvesAndPoints) {
    std::string usda = kHairPrototype;
    for (int i = 0; i < 3; ++i) usda += instance("I" + std::to_string(i), "/_Hair", std::to_string(2 * i) + ", 0, 0");
    auto p = populate(usda);
    for (const std::string& w : p.warnings) ADD_FAILURE() << w;
    const render::SceneDescription& s = p.result.scene;
    EXPECT_TRUE(s.curves.empty()) << "the curves are the prototype's, not copies";
    EXPECT_TRUE(s.points.empty());
    ASSERT_EQ(s.prototypes.size(), 1u);
    ASSERT_EQ(s.prototypes[0].curves.size(), 1u);
    ASSERT_EQ(s.prototypes[0].points.size(), 1u);
    ASSERT_EQ(s.instances.size(), 3u);
    EXPECT_EQ(s.prototypes[0].curves[0].colors.size(), 2u) << "displayColor along the hair";

    render::RenderScene scene(s);
    for (int i = 0; i < 3; ++i) {
        const std::string name = "/I" + std::to_string(i);
        EXPECT_EQ(hitAt(scene, 2 * i + 0.3, 0.02), std::make_pair(name, true)) << "the hair of " << name;
        EXPECT_EQ(hitAt(scene, 2 * i, 0.52), std::make_pair(name, false)) << "the point of " << name;
        EXPECT_EQ(hitAt(scene, 2 * i + 0.3, 0.08).first, "") << "beside the hair of " << name;
        EXPECT_EQ(hitAt(scene, 2 * i + 0.15, 0.5).first, "") << "beside the point of " << name;
    }
    auto colour = scene.intersect(render::Ray{Vec3f(4.3f, 0.0f, 10.0f), Vec3f(0, 0, -1)});
    ASSERT_TRUE(colour.has_value());
    EXPECT_FLOAT_EQ(colour->material.diffuse.x, 1.0f) << "the hair's displayColor";
    EXPECT_FLOAT_EQ(colour->material.diffuse.y, 0.0f);
}

TEST(InstancedCurves, NestedInstancesRenderEveryPlacement) {
    // /_Pair holds two instances of the hair (at y = 0 and y = 2); /P0 and /P1 instance the pair.
    const std::string usda = std::string(kHairPrototype) + "class Xform \"_Pair\"\n{\n" +
                             instance("Low", "/_Hair", "") + instance("High", "/_Hair", "0, 2, 0") + "}\n" +
                             instance("P0", "/_Pair", "") + instance("P1", "/_Pair", "3, 0, 0");
    auto p = populate(usda);
    for (const std::string& w : p.warnings) ADD_FAILURE() << w;
    render::RenderScene scene(p.result.scene);
    for (const char* instance : {"/P0", "/P1"})
        for (double y : {0.0, 2.0}) {
            const double x = std::string(instance) == "/P1" ? 3.0 : 0.0;
            EXPECT_EQ(hitAt(scene, x + 0.3, y + 0.02), std::make_pair(std::string(instance), true))
                << instance << " hair at y " << y;
            EXPECT_EQ(hitAt(scene, x, y + 0.52), std::make_pair(std::string(instance), false))
                << instance << " point at y " << y;
        }
}

TEST(InstancedCurves, APointInstancerPlacesCurvesAndPointsPrototypes) {
    std::string usda = R"(
def PointInstancer "Field"
{
    rel prototypes = [</Field/Protos/Hair>, </Field/Protos/Dot>]
    int[] protoIndices = [0, 0, 1, 0]
    point3f[] positions = [(0, 0, 0), (2, 0, 0), (4, 0, 0), (6, 0, 0)]
    quath[] orientations = [(1, 0, 0, 0), (0.7071068, 0, 0, 0.7071068), (1, 0, 0, 0), (1, 0, 0, 0)]
    def Scope "Protos"
    {
        )" + strand("Hair") +
                       R"(
        def Points "Dot"
        {
            point3f[] points = [(0, 0, 0)]
            float[] widths = [0.4]
        }
    }
}
)";
    auto p = populate(usda);
    for (const std::string& w : p.warnings) ADD_FAILURE() << w;
    ASSERT_EQ(p.result.scene.instances.size(), 4u);
    render::RenderScene scene(p.result.scene);
    EXPECT_EQ(hitAt(scene, 0.3, 0.02), std::make_pair(std::string("/Field[0]"), true));
    EXPECT_EQ(hitAt(scene, 2.02, 0.3), std::make_pair(std::string("/Field[1]"), true)) << "turned a quarter";
    EXPECT_EQ(hitAt(scene, 2.3, 0.02).first, "") << "turned a quarter";
    EXPECT_EQ(hitAt(scene, 4.1, 0.1), std::make_pair(std::string("/Field[2]"), false));
    EXPECT_EQ(hitAt(scene, 6.3, 0.02), std::make_pair(std::string("/Field[3]"), true));
}

// Public files of OpenUSD's test suite in tests/corpus (byte-for-byte copies): the curves inside
// their instanceable prims are no longer dropped.
struct CorpusCounts {
    std::size_t worldCurves = 0, prototypes = 0, prototypeCurves = 0, instances = 0;
    std::vector<std::string> warnings;
};

CorpusCounts countsOf(const std::string& relative) {
    CorpusCounts counts;
    testing::Populated p;
    std::unique_ptr<usd::Stage> stage = usd::Stage::open(std::string(FLUENCE_SOURCE_DIR) + "/tests/corpus/" + relative);
    DelegateOptions options = testing::testOptions(p);
    const DelegateResult result = populateScene(*stage, options);
    counts.worldCurves = result.scene.curves.size();
    counts.prototypes = result.scene.prototypes.size();
    for (const render::PrototypeDesc& proto : result.scene.prototypes) counts.prototypeCurves += proto.curves.size();
    counts.instances = result.scene.instances.size();
    counts.warnings = p.warnings;
    return counts;
}

TEST(InstancedCurves, OpenUsdMoreCurvesRendersItsInstancedCurves) {
    // /World's Lines (4 curves), Bezier, Bspline and CatmullRom (5 each) and eight instanceable
    // prims referencing them: four at y = 20 and four scaled copies at y = 40.
    const CorpusCounts c =
        countsOf("OpenUSD/pxr/usdImaging/usdImagingGL/testenv/testUsdImagingGLCurves/moreCurves.usda");
    for (const std::string& w : c.warnings) EXPECT_EQ(w.find("not supported"), std::string::npos) << w;
    EXPECT_EQ(c.worldCurves, 19u);
    EXPECT_EQ(c.instances, 8u);
    EXPECT_EQ(c.prototypes, 4u);
    EXPECT_EQ(c.prototypeCurves, 19u) << "each prototype holds the curves of the prim it references";
}

TEST(InstancedCurves, OpenUsdHermiteCurvesAreNoLongerDropped) {
    const CorpusCounts c =
        countsOf("OpenUSD/pxr/usd/plugin/usdAbc/testenv/testUsdAbcConversionHermiteCurves/original.usda");
    for (const std::string& w : c.warnings) EXPECT_EQ(w.find("Curves"), std::string::npos) << w;
    EXPECT_EQ(c.worldCurves, 2u);
}

}  // namespace
}  // namespace fluence::delegate
