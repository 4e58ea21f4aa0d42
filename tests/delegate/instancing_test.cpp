// Instancing in the delegate: native instances and PointInstancers become one shared prototype
// plus one transform per placement, and edits re-sync only what they touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "delegate/scene_delegate.h"
#include "tests/delegate/delegate_test_support.h"

namespace fluence::delegate {
namespace {

using testing::populate;
using testing::stageFrom;

struct Delegated {
    std::unique_ptr<usd::Stage> stage;
    std::unique_ptr<SceneDelegate> delegate;
};

// A delegate on `usda` (with a camera), synced once.
Delegated delegateFor(const std::string& usda) {
    Delegated d{stageFrom(testing::kCamera + usda), nullptr};
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [](const std::string&, const std::string&) {};
    d.delegate = std::make_unique<SceneDelegate>(*d.stage, options);
    d.delegate->sync();
    return d;
}

// Two instances of one referenced prototype, one of another variant, and a non-instanced copy.
const char* kNativeInstances = R"(
class Xform "_Prop" (
    variants = {
        string size = "small"
    }
    prepend variantSets = "size"
)
{
    variantSet "size" = {
        "small" {
            def Sphere "Ball"
            {
                double radius = 0.5
            }
        }
        "large" {
            def Sphere "Ball"
            {
                double radius = 2
            }
        }
    }
    def Cube "Box"
    {
        double size = 1
        double3 xformOp:translate = (0, 3, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def SphereLight "Lamp"
    {
        float inputs:radius = 0.1
    }
}
def Xform "A" (
    instanceable = true
    references = </_Prop>
)
{
    double3 xformOp:translate = (10, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Xform "B" (
    instanceable = true
    references = </_Prop>
)
{
    double3 xformOp:translate = (20, 0, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Xform "C" (
    instanceable = true
    references = </_Prop>
    variants = {
        string size = "large"
    }
)
{
}
def Xform "D" (
    references = </_Prop>
)
{
}
)";

TEST(Instancing, NativeInstancesShareOnePrototypePerCompositionKey) {
    auto p = populate(kNativeInstances);
    const auto& scene = p.result.scene;
    ASSERT_EQ(scene.prototypes.size(), 2u) << "A and B share one prototype; C selects another variant";
    ASSERT_EQ(scene.instances.size(), 3u);
    EXPECT_EQ(scene.instances[0].prototype, scene.instances[1].prototype);
    EXPECT_NE(scene.instances[0].prototype, scene.instances[2].prototype);
    EXPECT_EQ(scene.instances[0].transform, Matrix4::translate({10, 0, 0}));
    EXPECT_EQ(scene.instances[1].transform, Matrix4::translate({20, 0, 0}));
    EXPECT_EQ(scene.prototypes[0].name, "/A");

    // The prototype is the instance's descendants in the instance's space: the ball at the origin
    // and the box moved by its own transform.
    const render::PrototypeDesc& small = scene.prototypes[scene.instances[0].prototype];
    ASSERT_EQ(small.meshes.size(), 2u);
    Vec3f lo(1e9f), hi(-1e9f);
    for (const Vec3f& q : small.meshes[0].positions) lo = vmin(lo, q), hi = vmax(hi, q);
    EXPECT_NEAR(hi.x, 0.5f, 1e-5f);
    EXPECT_NEAR(lo.y, -0.5f, 1e-5f);
    float boxLowest = 1e9f;
    for (const Vec3f& q : small.meshes[1].positions) boxLowest = std::min(boxLowest, q.y);
    EXPECT_NEAR(boxLowest, 2.5f, 1e-5f);

    // Only the non-instanced copy D is flattened into world meshes.
    for (const auto& mesh : scene.meshes) EXPECT_TRUE(mesh.name.starts_with("/D/")) << mesh.name;
    EXPECT_EQ(scene.meshes.size(), 2u);
    // Lights inside instances are not shared: one per instance, plus D's.
    EXPECT_EQ(scene.lights.size(), 4u);
}

TEST(Instancing, MovingAnInstanceResyncsOnlyThatInstance) {
    Delegated d = delegateFor(kNativeInstances);
    SceneDelegate& delegate = *d.delegate;
    const auto& index = delegate.renderIndex();
    auto prototypeReads = [&] {
        int reads = 0;
        for (const auto& [path, prim] : index.prims())
            if (prim->kind() == RenderPrim::Kind::Prototype)
                reads += static_cast<const SurfaceRprim&>(*prim).dataReads();
        return reads;
    };
    EXPECT_EQ(prototypeReads(), 2);

    delegate.setAttribute("/B", "xformOp:translate", usd::Value::numeric("double3", {30, 0, 0}, 3, false));
    EXPECT_EQ(delegate.sync(), 2u) << "the instance and the light inside it";
    EXPECT_EQ(index.find("/B")->syncCount(), 2);
    EXPECT_EQ(index.find("/B/Lamp")->syncCount(), 2);
    EXPECT_EQ(index.find("/A")->syncCount(), 1);
    EXPECT_EQ(prototypeReads(), 2);
    EXPECT_EQ(delegate.sceneDescription().instances[1].transform, Matrix4::translate({30, 0, 0}));
}

TEST(Instancing, InstanceProxiesAreReadOnly) {
    Delegated d = delegateFor(kNativeInstances);
    SceneDelegate& delegate = *d.delegate;
    try {
        delegate.setAttribute("/A/Ball", "radius", usd::Value::numeric("double", {1}, 1, false));
        FAIL() << "an edit inside an instance was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("inside the instance /A"), std::string::npos) << e.what();
    }
}

TEST(Instancing, HidingThePrototypeSourceReadsItFromTheNextInstance) {
    Delegated d = delegateFor(kNativeInstances);
    SceneDelegate& delegate = *d.delegate;
    delegate.setAttribute("/A", "visibility", usd::Value::string("token", usd::ValueKind::Token, {"invisible"}, false));
    delegate.sync();
    render::SceneDescription scene = delegate.sceneDescription();
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.prototypes[scene.instances[0].prototype].name, "/B");
    EXPECT_EQ(scene.prototypes[scene.instances[0].prototype].meshes.size(), 2u);
}

const char* kPointInstancer = R"(
def Xform "World"
{
    double3 xformOp:translate = (0, 0, -5)
    uniform token[] xformOpOrder = ["xformOp:translate"]
    def PointInstancer "Scatter" (
        prepend inactiveIds = [13]
    )
    {
        int[] protoIndices = [0, 1, 0, 0, 7]
        int64[] ids = [10, 11, 12, 13, 14]
        int64[] invisibleIds = [12]
        point3f[] positions = [(1, 0, 0), (2, 0, 0), (3, 0, 0), (4, 0, 0), (5, 0, 0)]
        quath[] orientations = [(0.70710678, 0, 0, 0.70710678), (2, 0, 0, 0), (1, 0, 0, 0), (1, 0, 0, 0), (1, 0, 0, 0)]
        float3[] scales = [(2, 1, 1), (1, 1, 1), (1, 1, 1), (1, 1, 1), (1, 1, 1)]
        rel prototypes = [</World/Scatter/Protos/Pebble>, </World/Scatter/Protos/Rock>]
        def Scope "Protos"
        {
            def Xform "Pebble"
            {
                double3 xformOp:translate = (0, 1, 0)
                uniform token[] xformOpOrder = ["xformOp:translate"]
                def Mesh "Tri"
                {
                    uniform token subdivisionScheme = "none"
                    int[] faceVertexCounts = [3]
                    int[] faceVertexIndices = [0, 1, 2]
                    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
                }
            }
            def Sphere "Rock"
            {
                double radius = 0.25
            }
        }
    }
}
)";

TEST(Instancing, PointInstancerPlacesPrototypesByPositionOrientationAndScale) {
    auto p = populate(kPointInstancer);
    const auto& scene = p.result.scene;
    EXPECT_TRUE(scene.meshes.empty()) << "prototypes below the instancer render only through it";
    ASSERT_EQ(scene.prototypes.size(), 2u);
    // ids 12 (invisibleIds) and 13 (inactiveIds) are hidden; id 14 names no prototype.
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings.at(0).find("outside the 2 prototypes"), std::string::npos) << p.warnings.at(0);

    // Instance 0: the Pebble's vertex (1, 0, 0) moves by its root transform to (1, 1, 0), is
    // scaled to (2, 1, 0), rotated 90 degrees about Z to (-1, 2, 0), translated to (0, 2, 0),
    // then by the World to (0, 2, -5).
    const render::InstanceDesc& first = scene.instances[0];
    const render::MeshDesc& tri = scene.prototypes[first.prototype].meshes.at(0);
    Vec3d moved = first.transform.transformPoint(Vec3d(tri.positions[tri.indices[1]]));
    EXPECT_NEAR(moved.x, 0.0, 1e-6);
    EXPECT_NEAR(moved.y, 2.0, 1e-6);
    EXPECT_NEAR(moved.z, -5.0, 1e-6);
    // Instance 1: the Rock, with an unnormalised quaternion (2, 0, 0, 0) read as the identity.
    EXPECT_EQ(scene.instances[1].transform, Matrix4::translate({0, 0, -5}) * Matrix4::translate({2, 0, 0}));
}

TEST(Instancing, EditingAPointInstancerPrototypeRereadsOnlyThatPrototype) {
    Delegated d = delegateFor(kPointInstancer);
    SceneDelegate& delegate = *d.delegate;
    delegate.setAttribute("/World/Scatter/Protos/Rock", "radius", usd::Value::numeric("double", {0.5}, 1, false));
    EXPECT_EQ(delegate.sync(), 1u) << "only the Rock's prototype";
    EXPECT_EQ(delegate.renderIndex().find("/World/Scatter")->syncCount(), 1);

    delegate.setAttribute("/World/Scatter", "positions",
                          usd::Value::numeric("point3f[]", {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, 3, true));
    EXPECT_EQ(delegate.sync(), 1u) << "only the instancer";
    EXPECT_EQ(delegate.sceneDescription().instances[1].transform, Matrix4::translate({0, 0, -5}));
}

TEST(Instancing, PositionsOfTheWrongLengthPlaceNothing) {
    auto p = populate(R"(
def PointInstancer "Bad"
{
    int[] protoIndices = [0, 0]
    point3f[] positions = [(0, 0, 0)]
    rel prototypes = </Bad/P>
    def Sphere "P"
    {
    }
}
)");
    EXPECT_TRUE(p.result.scene.instances.empty());
    ASSERT_FALSE(p.warnings.empty());
    EXPECT_NE(p.warnings.front().find("'positions' has 1 elements for 2 instances"), std::string::npos)
        << p.warnings.front();
}

TEST(Instancing, NestedPointInstancersExpandInsideThePrototype) {
    auto p = populate(R"(
def PointInstancer "Outer"
{
    int[] protoIndices = [0, 0]
    point3f[] positions = [(0, 0, 0), (10, 0, 0)]
    rel prototypes = </Outer/Inner>
    def PointInstancer "Inner"
    {
        int[] protoIndices = [0, 0, 0]
        point3f[] positions = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]
        rel prototypes = </Outer/Inner/Leaf>
        def Sphere "Leaf"
        {
            double radius = 0.1
        }
    }
}
)");
    ASSERT_EQ(p.result.scene.prototypes.size(), 1u);
    EXPECT_EQ(p.result.scene.prototypes[0].meshes.size(), 3u);
    EXPECT_EQ(p.result.scene.instances.size(), 2u);
}

// Lights inside prototypes are placed once per instance: by a PointInstancer (the prototype root's
// own transform included), by a PointInstancer nested in the prototype, and by native instances.
TEST(Instancing, EveryInstanceOfAPrototypePlacesItsLights) {
    auto p = populate(R"(
def PointInstancer "Lamps"
{
    int[] protoIndices = [0, 0, 1]
    point3f[] positions = [(-2, 1, 0), (2, 1, 0), (0, 0, 10)]
    rel prototypes = [</Lamps/Lamp>, </Lamps/Pair>]
    def Xform "Lamp"
    {
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        def SphereLight "Bulb"
        {
            float inputs:intensity = 20
            float inputs:radius = 0.1
            double3 xformOp:translate = (0, 0.5, 0)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
    }
    def PointInstancer "Pair"
    {
        int[] protoIndices = [0, 0]
        point3f[] positions = [(-1, 0, 0), (1, 0, 0)]
        rel prototypes = </Lamps/Pair/Spot>
        def DiskLight "Spot"
        {
            float inputs:radius = 0.2
        }
    }
}
class Xform "_Fixture"
{
    def RectLight "Panel"
    {
        float inputs:width = 1
        float inputs:height = 1
    }
    def PointInstancer "Row"
    {
        int[] protoIndices = [0, 0]
        point3f[] positions = [(-3, 0, 0), (3, 0, 0)]
        rel prototypes = </_Fixture/Row/Dot>
        def SphereLight "Dot"
        {
            float inputs:radius = 0.05
        }
    }
}
def Xform "Hall" (
    instanceable = true
    references = </_Fixture>
)
{
    double3 xformOp:translate = (0, 5, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def Xform "Lobby" (
    instanceable = true
    references = </_Fixture>
)
{
    double3 xformOp:translate = (0, 7, 0)
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
)");
    const std::vector<render::LightDesc>& lights = p.result.scene.lights;
    EXPECT_EQ(lights.size(), 10u) << "two bulbs, two spots of the nested pair, and per fixture a panel and two dots";
    auto at = [](const render::LightDesc& l) { return l.transform.transformPoint({0, 0, 0}); };
    std::vector<std::string> found;
    for (const render::LightDesc& l : lights) {
        const Vec3d c = at(l);
        char text[96];
        std::snprintf(text, sizeof text, "%s (%g %g %g)", l.name.c_str(), c.x, c.y, c.z);
        found.push_back(text);
    }
    std::sort(found.begin(), found.end());
    // (A native prototype is read from its first instance, /Hall: its point-instanced dots carry
    // that name in both fixtures.)
    EXPECT_EQ(found,
              (std::vector<std::string>{"/Hall/Panel (0 5 0)", "/Hall/Row/Dot (-3 5 0)", "/Hall/Row/Dot (-3 7 0)",
                                        "/Hall/Row/Dot (3 5 0)", "/Hall/Row/Dot (3 7 0)", "/Lamps/Lamp/Bulb (-2 1.5 1)",
                                        "/Lamps/Lamp/Bulb (2 1.5 1)", "/Lamps/Pair/Spot (-1 0 10)",
                                        "/Lamps/Pair/Spot (1 0 10)", "/Lobby/Panel (0 7 0)"}))
        << ::testing::PrintToString(found);
}

}  // namespace
}  // namespace fluence::delegate
