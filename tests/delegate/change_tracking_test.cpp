// The dirty-bit contract of the render index: an edit re-syncs only the render prims it
// affects, and a transform edit never re-reads mesh data.
#include <gtest/gtest.h>

#include "delegate/scene_delegate.h"
#include "scene/usda_parser.h"

namespace fluence::delegate {
namespace {

const char* kScene = R"(#usda 1.0
def Xform "World"
{
    def Camera "Cam"
    {
    }
    def RectLight "Key"
    {
        float inputs:intensity = 2
    }
    def Xform "Group"
    {
        double3 xformOp:translate = (0, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        def Mesh "A" (
            prepend apiSchemas = ["MaterialBindingAPI"]
        )
        {
            int[] faceVertexCounts = [3]
            int[] faceVertexIndices = [0, 1, 2]
            point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
            rel material:binding = </World/Looks/Red>
        }
        def Sphere "Ball"
        {
            double radius = 0.5
        }
    }
    def Mesh "Spinning"
    {
        int[] faceVertexCounts = [3]
        int[] faceVertexIndices = [0, 1, 2]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
        float xformOp:rotateZ.timeSamples = {
            1: 0,
            2: 90,
        }
        uniform token[] xformOpOrder = ["xformOp:rotateZ"]
    }
    def Xform "Prop" (
        variants = {
            string size = "small"
        }
        prepend variantSets = "size"
    )
    {
        variantSet "size" = {
            "small" {
                def Sphere "Body"
                {
                    double radius = 1
                }
            }
            "large" {
                def Sphere "Body"
                {
                    double radius = 3
                }
                def Sphere "Extra"
                {
                }
            }
        }
    }
    def Scope "Looks"
    {
        def Material "Red"
        {
            token outputs:surface.connect = </World/Looks/Red/S.outputs:surface>
            def Shader "S"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (1, 0, 0)
            }
        }
    }
}
)";

class ChangeTracking : public ::testing::Test {
protected:
    void SetUp() override {
        stage_ = std::make_unique<usd::Stage>(usd::parseUsdaString(kScene, "change.usda"));
        DelegateOptions options;
        options.time = 1.0;
        options.convertColor = [](const RGB& c, const std::string&) { return c; };
        options.warn = [](const std::string&, const std::string&) {};
        delegate_ = std::make_unique<SceneDelegate>(*stage_, options);
        initiallySynced_ = delegate_->sync();
    }
    int syncs(const std::string& path) const {
        const RenderPrim* p = delegate_->renderIndex().find(path);
        return p ? p->syncCount() : -1;
    }
    int dataReads(const std::string& path) const {
        return static_cast<const MeshRprim*>(delegate_->renderIndex().find(path))->dataReads();
    }
    static usd::Value number(const char* type, double v) { return usd::Value::numeric(type, {v}, 1, false); }

    std::unique_ptr<usd::Stage> stage_;
    std::unique_ptr<SceneDelegate> delegate_;
    std::size_t initiallySynced_ = 0;
};

TEST_F(ChangeTracking, EveryPrimIsSyncedOnceAtFirst) {
    // Camera, light, two meshes, a sphere, the variant's sphere, and the bound material.
    EXPECT_EQ(initiallySynced_, 7u);
    for (const auto& [path, prim] : delegate_->renderIndex().prims()) EXPECT_EQ(prim->syncCount(), 1) << path;
    EXPECT_EQ(delegate_->sync(), 0u) << "a clean index syncs nothing";
}

TEST_F(ChangeTracking, EditingALightResyncsOnlyThatLight) {
    delegate_->setAttribute("/World/Key", "inputs:intensity", number("float", 8));
    EXPECT_EQ(delegate_->sync(), 1u);
    EXPECT_EQ(syncs("/World/Key"), 2);
    EXPECT_EQ(syncs("/World/Group/A"), 1);
    EXPECT_EQ(dataReads("/World/Group/A"), 1);
    EXPECT_EQ(syncs("/World/Group/Ball"), 1);
    EXPECT_EQ(syncs("/World/Looks/Red"), 1);
    EXPECT_EQ(delegate_->sceneDescription().lights.at(0).radiance, RGB(8.0f));
}

TEST_F(ChangeTracking, MovingAGroupRetransformsItsMeshesWithoutRereadingThem) {
    delegate_->setAttribute("/World/Group", "xformOp:translate", usd::Value::numeric("double3", {5, 0, 0}, 3, false));
    EXPECT_EQ(delegate_->sync(), 2u);
    EXPECT_EQ(syncs("/World/Group/A"), 2);
    EXPECT_EQ(syncs("/World/Group/Ball"), 2);
    EXPECT_EQ(dataReads("/World/Group/A"), 1) << "a transform edit must not re-read or re-triangulate the mesh";
    EXPECT_EQ(dataReads("/World/Group/Ball"), 1) << "nor re-tessellate the sphere";
    EXPECT_EQ(syncs("/World/Spinning"), 1);
    EXPECT_EQ(syncs("/World/Key"), 1);
    render::SceneDescription scene = delegate_->sceneDescription();
    bool moved = false;
    for (const auto& m : scene.meshes)
        if (m.name == "/World/Group/A") moved = m.positions[0] == Vec3f(5, 0, 0);
    EXPECT_TRUE(moved);
}

TEST_F(ChangeTracking, EditingAShaderResyncsOnlyItsMaterial) {
    delegate_->setAttribute("/World/Looks/Red/S", "inputs:diffuseColor",
                            usd::Value::numeric("color3f", {0, 0, 1}, 3, false));
    EXPECT_EQ(delegate_->sync(), 1u);
    EXPECT_EQ(syncs("/World/Looks/Red"), 2);
    EXPECT_EQ(dataReads("/World/Group/A"), 1);
    EXPECT_EQ(delegate_->sceneDescription().materials.at(0).diffuse, RGB(0, 0, 1));
}

TEST_F(ChangeTracking, EditingMeshPointsRereadsOnlyThatMesh) {
    delegate_->setAttribute("/World/Group/A", "points",
                            usd::Value::numeric("point3f[]", {0, 0, 0, 2, 0, 0, 0, 2, 0}, 3, true));
    EXPECT_EQ(delegate_->sync(), 1u);
    EXPECT_EQ(dataReads("/World/Group/A"), 2);
    EXPECT_EQ(dataReads("/World/Group/Ball"), 1);
}

TEST_F(ChangeTracking, ANewTimeResyncsOnlyAnimatedPrims) {
    delegate_->setTime(2.0);
    EXPECT_EQ(delegate_->sync(), 1u);
    EXPECT_EQ(syncs("/World/Spinning"), 2);
    EXPECT_EQ(dataReads("/World/Spinning"), 1) << "only its transform is animated";
    render::SceneDescription scene = delegate_->sceneDescription();
    for (const auto& m : scene.meshes)
        if (m.name == "/World/Spinning") {
            EXPECT_NEAR(m.positions[1].x, 0.0f, 1e-6f);  // (1,0,0) rotated by 90 degrees
            EXPECT_NEAR(m.positions[1].y, 1.0f, 1e-6f);
        }
}

TEST_F(ChangeTracking, HidingASubtreeRemovesItsPrimsAndShowingItBringsThemBack) {
    delegate_->setAttribute("/World/Group", "visibility",
                            usd::Value::string("token", usd::ValueKind::Token, {"invisible"}, false));
    delegate_->sync();
    EXPECT_EQ(syncs("/World/Group/A"), -1);
    EXPECT_EQ(syncs("/World/Group/Ball"), -1);
    EXPECT_EQ(syncs("/World/Key"), 1);
    delegate_->setAttribute("/World/Group", "visibility",
                            usd::Value::string("token", usd::ValueKind::Token, {"inherited"}, false));
    EXPECT_EQ(delegate_->sync(), 2u);
    EXPECT_EQ(syncs("/World/Group/A"), 1);
}

TEST_F(ChangeTracking, ASwitchedVariantRepopulatesOnlyItsPrim) {
    delegate_->setVariantSelection("/World/Prop", "size", "large");
    EXPECT_EQ(delegate_->sync(), 2u);  // the new Body and Extra
    EXPECT_EQ(syncs("/World/Prop/Extra"), 1);
    EXPECT_EQ(syncs("/World/Group/A"), 1);
    EXPECT_EQ(syncs("/World/Key"), 1);
    EXPECT_EQ(dataReads("/World/Group/Ball"), 1);
}

}  // namespace
}  // namespace fluence::delegate
