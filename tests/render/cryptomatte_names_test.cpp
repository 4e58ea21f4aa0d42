// The names hits carry for Cryptomatte (RenderScene::objectNames, materialNames): a mesh's prim
// path (parts of one mesh share it), an instance's own name rather than its prototype's (emissive
// prototypes, copied per instance, included), a light's shape, and the bound material.
#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

// A unit quad in the z = 0 plane, its lower-left corner at (x, 0).
MeshDesc quadAt(const std::string& name, float x, int material) {
    return test::quadMesh(name, {Vec3f(x, 0, 0), Vec3f(x + 1, 0, 0), Vec3f(x + 1, 1, 0), Vec3f(x, 1, 0)}, material);
}

class CryptomatteNames : public ::testing::Test {
protected:
    void SetUp() override {
        SceneDescription desc;
        desc.materials = {test::diffuseMaterial("/Looks/Red", RGB(0.8f, 0.1f, 0.1f)),
                          test::diffuseMaterial("/Looks/Blue", RGB(0.1f, 0.1f, 0.8f)),
                          test::diffuseMaterial("/Looks/Glow", RGB(0.5f), RGB(3.0f))};
        desc.meshes = {quadAt("/World/Mesh", -6, 0), quadAt("/World/Mesh", -5, 1), quadAt("/World/Bare", -4, -1)};
        desc.prototypes = {{"/World/InstA", {quadAt("/World/InstA/Box", 0, 1)}},
                           {"/World/LampA", {quadAt("/World/LampA/Bulb", 0, 2)}}};
        desc.instances = {{0, Matrix4::translate({-2, 0, 0}), "/World/InstA"},
                          {0, Matrix4::translate({-1, 0, 0}), "/World/InstB"},
                          {1, Matrix4::translate({1, 0, 0}), "/World/Trees[7]"}};
        desc.lights = {test::rectLight("/World/Light", 1.0f, 1.0f, RGB(1.0f), Matrix4::translate({3.5, 0.5, 0}))};
        scene_ = std::make_unique<RenderScene>(desc);
    }
    // What a ray straight down onto (x, 0.5) from height z (up from below for z < 0) hits: its
    // object and material names ("" for none).
    std::pair<std::string, std::string> namesAt(float x, float z = 5.0f) const {
        std::optional<SurfaceHit> hit = scene_->intersect(Ray{Vec3f(x, 0.5f, z), Vec3f(0, 0, z > 0.0f ? -1.0f : 1.0f)});
        EXPECT_TRUE(hit.has_value()) << x;
        if (!hit) return {};
        return {hit->objectName == kNoName ? "" : scene_->objectNames().name(hit->objectName),
                hit->materialName == kNoName ? "" : scene_->materialNames().name(hit->materialName)};
    }
    std::unique_ptr<RenderScene> scene_;
};

TEST_F(CryptomatteNames, HitsCarryTheirPrimsNames) {
    EXPECT_EQ(namesAt(-5.5f), std::make_pair(std::string("/World/Mesh"), std::string("/Looks/Red")));
    EXPECT_EQ(namesAt(-4.5f), std::make_pair(std::string("/World/Mesh"), std::string("/Looks/Blue")));
    EXPECT_EQ(namesAt(-3.5f), std::make_pair(std::string("/World/Bare"), std::string()));
    EXPECT_EQ(namesAt(-1.5f), std::make_pair(std::string("/World/InstA"), std::string("/Looks/Blue")));
    EXPECT_EQ(namesAt(-0.5f), std::make_pair(std::string("/World/InstB"), std::string("/Looks/Blue")));
    EXPECT_EQ(namesAt(1.5f), std::make_pair(std::string("/World/Trees[7]"), std::string("/Looks/Glow")));
    // A rect light emits along its -z and is seen from that side only (rays pass through its back).
    EXPECT_EQ(namesAt(3.5f, -5.0f), std::make_pair(std::string("/World/Light"), std::string()));
}

// Each name is stored once, and prototype meshes' own names are not among them (a hit inside an
// instance is named by the instance).
TEST_F(CryptomatteNames, NamesAreStoredOnce) {
    const std::vector<std::string> objects = scene_->objectNames().names();
    EXPECT_EQ(objects, (std::vector<std::string>{"/World/Mesh", "/World/Bare", "/World/InstA", "/World/InstB",
                                                 "/World/Trees[7]", "/World/Light"}));
    EXPECT_EQ(scene_->materialNames().size(), 3u);
}

}  // namespace
}  // namespace fluence::render
