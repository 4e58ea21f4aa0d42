// Lights in the RenderScene: disk and cylinder shapes are hit exactly through Embree's user
// geometry, point and line lights have no shape, and chooseLight / lightProbability are the
// light tree's.
#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "tests/support/scenes.h"

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

// Rect and disk lights emit from their front only; a ray meeting one from behind passes through it
// (as shadow rays do) and finds what lies beyond: here a floor at y = 0 under both lights.
TEST(LightRenderScene, RaysPassThroughTheBackOfRectAndDiskLights) {
    SceneDescription desc = sceneWithEveryLight();
    desc.lights.resize(1);  // the disk at y = 2, emitting down
    LightDesc rect;
    rect.name = "/rect";
    rect.type = LightType::Rect;
    rect.transform = Matrix4::translate({3, 2, 0}) * Matrix4::rotateX(-90);  // emits down -Y at y = 2
    desc.lights.push_back(rect);
    desc.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    desc.meshes.push_back(test::quadMesh("/floor", {{{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}}}, 0));
    RenderScene scene(desc);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    for (const Vec3f& above : {Vec3f(0.1f, 4.0f, 0.1f), Vec3f(3.1f, 4.0f, 0.1f)}) {
        auto down = scene.intersect(Ray{above, Vec3f(0, -1, 0), 0.0f, kInf});
        ASSERT_TRUE(down);
        EXPECT_FALSE(down->lightShape) << "the back of the light at x = " << above.x << " stopped the ray";
        EXPECT_NEAR(down->t, 4.0f, 1e-5f);
        auto up = scene.intersect(Ray{Vec3f(above.x, 1.0f, above.z), Vec3f(0, 1, 0), 0.0f, kInf});
        ASSERT_TRUE(up);
        EXPECT_TRUE(up->lightShape) << "the front of the light at x = " << above.x;
        EXPECT_NEAR(up->t, 1.0f, 1e-5f);
    }
}

// A sphere light emits outwards only (its samples, power and emission): a ray from inside it meets
// the back of its surface and passes through, finding what lies inside (a floor at y = -1) or
// nothing; from outside it sees the light. arnold-usd test_1776's camera, inside a SphereLight of
// radius 10, used to see only the light's inside, white.
TEST(LightRenderScene, RaysFromInsideASphereLightPassThroughItsSurface) {
    SceneDescription desc;
    LightDesc sphere;
    sphere.name = "/sphere";
    sphere.type = LightType::Sphere;
    sphere.radius = 2.0f;
    desc.lights.push_back(sphere);
    desc.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    desc.meshes.push_back(test::quadMesh("/floor", {{{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}}, 0));
    RenderScene scene(desc);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    auto down = scene.intersect(Ray{Vec3f(0.1f, 0.0f, 0.1f), Vec3f(0, -1, 0), 0.0f, kInf});
    ASSERT_TRUE(down);
    EXPECT_FALSE(down->lightShape);
    EXPECT_NEAR(down->t, 1.0f, 1e-5f);
    EXPECT_FALSE(scene.intersect(Ray{Vec3f(0.1f, 0.0f, 0.1f), Vec3f(0, 1, 0), 0.0f, kInf}))
        << "the inside of the sphere light stopped the ray";
    auto outside = scene.intersect(Ray{Vec3f(0.0f, 5.0f, 0.0f), Vec3f(0, -1, 0), 0.0f, kInf});
    ASSERT_TRUE(outside);
    EXPECT_TRUE(outside->lightShape);
    EXPECT_NEAR(outside->t, 3.0f, 1e-5f);
}

// A segment through the disk's front (light 0) meets another light's shape for every light but the
// disk, and for "any light" (-1, bdpt's joins); with the disk the only light that has a shape, the
// disk's own query skips the search (render_scene.cpp) and the others still find it.
TEST(LightRenderScene, ASegmentMeetsTheShapesOfLightsOtherThanItsOwn) {
    const Vec3f below(0.1f, 0.0f, 0.1f), up(0, 1, 0);
    RenderScene everyLight(sceneWithEveryLight());  // the disk's and the tube's shapes
    EXPECT_FALSE(everyLight.meetsOtherLightShape(0, below, up, 3.0f, 0.0f));
    EXPECT_TRUE(everyLight.meetsOtherLightShape(1, below, up, 3.0f, 0.0f));
    EXPECT_TRUE(everyLight.meetsOtherLightShape(-1, below, up, 3.0f, 0.0f));
    EXPECT_FALSE(everyLight.meetsOtherLightShape(-1, below, up, 1.5f, 0.0f)) << "short of the disk";
    SceneDescription desc = sceneWithEveryLight();
    desc.lights.resize(1);
    RenderScene diskOnly(desc);
    EXPECT_FALSE(diskOnly.meetsOtherLightShape(0, below, up, 3.0f, 0.0f));
    EXPECT_TRUE(diskOnly.meetsOtherLightShape(-1, below, up, 3.0f, 0.0f));
}

TEST(LightRenderScene, ChooseLightIsTheLightTreesChoice) {
    RenderScene scene(sceneWithEveryLight());
    ASSERT_EQ(scene.lightCount(), 5u);
    EXPECT_EQ(scene.lightsAtInfinity(false), std::vector<int>{4});
    EXPECT_EQ(scene.lightsAtInfinity(true), std::vector<int>{4})
        << "a dome is seen by the camera unless marked not to be";
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
