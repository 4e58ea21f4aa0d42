// Lights in the RenderScene: disk and cylinder shapes are hit exactly through Embree's user
// geometry, point and line lights have no shape, and chooseLight / lightProbability are the
// light tree's.
#include <gtest/gtest.h>

#include "render/render_scene.h"

namespace fluence::render {
namespace {

SceneDescription sceneWithEveryLight() {
    SceneDescription scene;
    LightDesc disk;
    disk.name = "/disk";
    disk.type = LightType::Disk;
    disk.radius = 0.5f;
    disk.transform = Matrix4::translate({0, 2, 0}) * Matrix4::rotateX(-90);  // emits down -Y at y = 2
    LightDesc tube;
    tube.name = "/tube";
    tube.type = LightType::Cylinder;
    tube.length = 2.0f;
    tube.radius = 0.25f;
    tube.transform = Matrix4::translate({4, 1, 0});  // along X
    LightDesc point;
    point.name = "/point";
    point.type = LightType::Sphere;
    point.treatAsPoint = true;
    point.transform = Matrix4::translate({-3, 1, 0});
    LightDesc line = tube;
    line.name = "/line";
    line.treatAsLine = true;
    line.transform = Matrix4::translate({-3, 1, 3});
    LightDesc dome;
    dome.name = "/dome";
    dome.type = LightType::Dome;
    dome.radiance = RGB(0.1f);
    scene.lights = {disk, tube, point, line, dome};
    return scene;
}

TEST(LightRenderScene, DiskAndCylinderShapesAreHitExactly) {
    RenderScene scene(sceneWithEveryLight());
    constexpr float kInf = std::numeric_limits<float>::infinity();
    auto diskHit = scene.intersect(Ray{Vec3f(0.3f, 0.0f, 0.3f), Vec3f(0, 1, 0), 0.0f, kInf});
    ASSERT_TRUE(diskHit);
    EXPECT_TRUE(diskHit->lightShape);
    EXPECT_EQ(diskHit->light, 0);
    EXPECT_NEAR(diskHit->t, 2.0f, 1e-5f);
    EXPECT_NEAR(diskHit->geometricNormal.y, -1.0f, 1e-6f);
    // Inside the disk's bounding box but 0.57 from its centre: no hit.
    EXPECT_FALSE(scene.intersect(Ray{Vec3f(0.4f, 0.0f, 0.4f), Vec3f(0, 1, 0), 0.0f, kInf}));

    auto tubeHit = scene.intersect(Ray{Vec3f(4.5f, 1.0f, 3.0f), Vec3f(0, 0, -1), 0.0f, kInf});
    ASSERT_TRUE(tubeHit);
    EXPECT_EQ(tubeHit->light, 1);
    EXPECT_NEAR(tubeHit->t, 2.75f, 1e-5f);
    EXPECT_NEAR(tubeHit->geometricNormal.z, 1.0f, 1e-5f);
    EXPECT_FALSE(scene.intersect(Ray{Vec3f(4.0f, 1.3f, 3.0f), Vec3f(0, 0, -1), 0.0f, kInf})) << "above the tube";

    // Point and line lights cannot be hit.
    EXPECT_FALSE(scene.intersect(Ray{Vec3f(-3.0f, 0.0f, 0.0f), Vec3f(0, 1, 0), 0.0f, kInf}));
    EXPECT_FALSE(scene.intersect(Ray{Vec3f(-3.0f, 0.0f, 3.0f), Vec3f(0, 1, 0), 0.0f, kInf}));
}

TEST(LightRenderScene, ChooseLightIsTheLightTreesChoice) {
    RenderScene scene(sceneWithEveryLight());
    ASSERT_EQ(scene.lightCount(), 5u);
    EXPECT_EQ(scene.lightsAtInfinity(), std::vector<int>{4});
    Vec3f p(0.5f, 0.0f, 0.5f), n(0, 1, 0);
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) sum += scene.lightProbability(p, n, i);
    EXPECT_NEAR(sum, 1.0, 1e-5);
    for (float u : {0.0f, 0.2f, 0.5f, 0.9f, 0.999f}) {
        LightChoice c = scene.chooseLight(p, n, u);
        ASSERT_GE(c.light, 0);
        EXPECT_NEAR(c.probability, scene.lightProbability(p, n, c.light), 1e-6f);
    }
    EXPECT_EQ(scene.lightSelection().size(), 5u) << "the power-based choice is still there";
}

}  // namespace
}  // namespace fluence::render
