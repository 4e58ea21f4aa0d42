// A camera sample's time (integrators/renderer.h, cameraSampleRay): drawn from the stream's own
// shutter dimension when the camera or anything in the scene moves (RenderScene::moves, which
// every kind of motion sets), and 0, with no draw, when nothing does; the sample's other
// dimensions are the same either way.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "integrators/renderer.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

// A grey quad under a rect light, nothing moving.
render::SceneDescription stillScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    s.meshes.push_back(test::quadMesh(
        "/floor",
        {Vec3f(-1.0f, -1.0f, 0.0f), Vec3f(1.0f, -1.0f, 0.0f), Vec3f(1.0f, 1.0f, 0.0f), Vec3f(-1.0f, 1.0f, 0.0f)}, 0));
    s.lights.push_back(test::rectLight("/light", 1.0f, 1.0f, RGB(2.0f), Matrix4::translate({0.0, 0.0, 3.0})));
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

render::CurvesDesc curve() {
    render::CurvesDesc c;
    c.name = "/hair";
    c.points = {Vec3f(-1.0f, 0.0f, 0.5f), Vec3f(1.0f, 0.0f, 0.5f)};
    c.radii = {0.05f, 0.05f};
    c.segments = {0};
    return c;
}

render::PointsDesc point() {
    render::PointsDesc p;
    p.name = "/sparks";
    p.positions = {Vec3f(0.0f, 0.0f, 0.5f)};
    p.radii = {0.1f};
    return p;
}

// The still scene's floor as the prototype of one instance.
render::SceneDescription instancedFloor() {
    render::SceneDescription s = stillScene();
    s.prototypes.push_back({"/proto", {s.meshes.front()}});
    s.meshes.clear();
    render::InstanceDesc instance;
    instance.name = "/instance";
    s.instances.push_back(instance);
    return s;
}

const Matrix4 kNudge = Matrix4::translate({0.1, 0.0, 0.0});

// The still scene changed by one kind of motion, named.
struct Motion {
    std::string name;
    std::function<void(render::SceneDescription&)> add;
};

// Motion steps for a mesh, a curve and a point set: their positions twice, the mesh's first corner moved.
void deform(render::MeshDesc& m) {
    m.motionPositions = {m.positions, m.positions};
    m.motionPositions.back()[0].z += 0.1f;
}
void addMovingCurve(std::vector<render::CurvesDesc>& curves) {
    curves.push_back(curve());
    curves.back().motionPoints = {curves.back().points, curves.back().points};
}
void addMovingPoint(std::vector<render::PointsDesc>& points) {
    points.push_back(point());
    points.back().motionPositions = {points.back().positions, points.back().positions};
}

std::vector<Motion> everyKindOfMotion() {
    using Scene = render::SceneDescription;
    return {
        {"deforming mesh", [](Scene& s) { deform(s.meshes.front()); }},
        {"moving light",
         [](Scene& s) {
             s.lights.front().motionTransforms = {kNudge, kNudge};
         }},
        {"moving curves", [](Scene& s) { addMovingCurve(s.curves); }},
        {"moving points", [](Scene& s) { addMovingPoint(s.points); }},
        {"moving instance",
         [](Scene& s) {
             s = instancedFloor();
             s.instances.front().motionTransforms = {Matrix4::identity(), kNudge};
         }},
        {"deforming prototype mesh",
         [](Scene& s) {
             s = instancedFloor();
             deform(s.prototypes.front().meshes.front());
         }},
        {"moving prototype curves",
         [](Scene& s) {
             s = instancedFloor();
             addMovingCurve(s.prototypes.front().curves);
         }},
        {"moving prototype points",
         [](Scene& s) {
             s = instancedFloor();
             addMovingPoint(s.prototypes.front().points);
         }},
    };
}

TEST(RenderSceneMotion, EveryKindOfMotionMakesTheSceneMove) {
    EXPECT_FALSE(render::RenderScene(stillScene()).moves());
    render::SceneDescription stillParts = instancedFloor();
    stillParts.curves.push_back(curve());
    stillParts.points.push_back(point());
    stillParts.prototypes.front().curves.push_back(curve());
    stillParts.prototypes.front().points.push_back(point());
    EXPECT_FALSE(render::RenderScene(stillParts).moves()) << "still curves, points and instances";
    for (const Motion& motion : everyKindOfMotion()) {
        render::SceneDescription s = stillScene();
        motion.add(s);
        EXPECT_TRUE(render::RenderScene(s).moves()) << motion.name;
    }
}

// The camera rays of samples 0-15 of pixel (3, 2) and the stream's value after each.
struct CameraSamples {
    std::vector<render::Ray> rays;
    std::vector<float> shutterTimes, after;
};

CameraSamples cameraSamples(const render::SceneDescription& description) {
    const render::RenderScene scene(description);
    const render::Camera camera(*description.camera, 8, 8);
    CameraSamples out;
    for (std::uint64_t sample = 0; sample < 16; ++sample) {
        SampleStream rng(5, 19, sample, SamplerKind::Sobol);
        out.rays.push_back(cameraSampleRay(scene, camera, rng, 3, 2));
        out.shutterTimes.push_back(rng.shutterTime());
        out.after.push_back(rng.next());
    }
    return out;
}

TEST(CameraSampleRay, DrawsTheShutterTimeOnlyWhenTheCameraOrTheSceneMoves) {
    const CameraSamples still = cameraSamples(stillScene());
    render::SceneDescription movingCamera = stillScene();
    movingCamera.camera->motionTransforms = {movingCamera.camera->transform, movingCamera.camera->transform};
    std::vector<std::pair<std::string, CameraSamples>> moving = {{"moving camera", cameraSamples(movingCamera)}};
    for (const Motion& motion : everyKindOfMotion()) {
        render::SceneDescription s = stillScene();
        motion.add(s);
        moving.emplace_back(motion.name, cameraSamples(s));
    }
    for (std::size_t i = 0; i < still.rays.size(); ++i) {
        ASSERT_NE(still.shutterTimes[i], 0.0f) << "sample " << i << " would not tell a skipped draw";
        EXPECT_EQ(still.rays[i].time, 0.0f) << "sample " << i;
        for (const auto& [name, samples] : moving) {
            EXPECT_EQ(samples.rays[i].time, samples.shutterTimes[i]) << name << ", sample " << i;
            // The same later draws: the time took no other dimension.
            EXPECT_EQ(samples.after[i], still.after[i]) << name << ", sample " << i;
        }
    }
}

}  // namespace
}  // namespace fluence::integrators
