// A moving camera (CameraDesc::motionTransforms, render/camera_motion.h): a still square seen by a
// camera sliding to the left smears as the same square sliding to the right seen by a still camera
// (the two images agree within noise); a turning camera turns at constant speed and keeps its
// scale between steps; a moving camera has the importance of the still camera at each time; the
// motionvector AOV holds the camera's own motion.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "integrators/first_hit_aovs.h"
#include "integrators/path_tracer.h"
#include "render/camera.h"
#include "render/camera_motion.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr int kSize = 48;
constexpr float kView = 1.5f;    // the camera sees x and y in [-1.5, 1.5]
constexpr float kTravel = 0.4f;  // how far the square (or, the other way, the camera) moves
constexpr int kSpp = 64;

render::SceneDescription squareUnderSky(const std::vector<Vec3f>& corners) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    s.lights.push_back(test::domeLight("/sky", RGB(1.0f)));
    s.lights.back().visibleToCamera = false;
    render::CameraDesc c;
    c.name = "/cam";
    c.projection = render::Projection::Orthographic;
    c.horizontalAperture = c.verticalAperture = 20.0f * kView;
    c.nearClip = 0.1f;
    c.farClip = 100.0f;
    c.transform = Matrix4::translate({0, 0, 5});
    s.camera = c;
    s.meshes.push_back(test::quadMesh("/square", {corners[0], corners[1], corners[2], corners[3]}, 0));
    return s;
}

std::vector<Vec3f> squareFrom(float left) {
    return {Vec3f(left, -0.5f, 0.0f), Vec3f(left + 0.8f, -0.5f, 0.0f), Vec3f(left + 0.8f, 0.5f, 0.0f),
            Vec3f(left, 0.5f, 0.0f)};
}

double meanAlphaOfColumn(const Image& image, int column) {
    const int a = image.channelIndex("A");
    double sum = 0.0;
    for (int y = kSize / 2 - 6; y < kSize / 2 + 6; ++y) sum += image.pixel(column, y)[a];
    return sum / 12.0;
}

TEST(CameraMotionBlur, AMovingCameraSmearsAStillSceneAsAMovingSceneSmearsForAStillCamera) {
    const PathTracer tracer{IntegratorSettings{.maxDepth = 1, .parameters = {}, .lightPathAovs = {}}};
    render::SceneDescription moving = squareUnderSky(squareFrom(-0.4f));
    moving.meshes.front().motionPositions = {squareFrom(-0.4f), squareFrom(-0.4f + kTravel)};
    render::SceneDescription panning = squareUnderSky(squareFrom(-0.4f));
    panning.camera->motionTransforms = {Matrix4::translate({0, 0, 5}), Matrix4::translate({-kTravel, 0, 5})};
    const Image a = test_support::renderWith(tracer, moving, kSize, kSpp, 0, 21).image;
    const Image b = test_support::renderWith(tracer, panning, kSize, kSpp, 0, 22).image;
    int smeared = 0;
    for (int column = 0; column < kSize; ++column) {
        const double p = meanAlphaOfColumn(a, column), n = 12.0 * kSpp;
        // Of a difference of two binomial means of n samples each.
        const double sigma = std::sqrt(2.0 * std::max(p * (1.0 - p), 1.0 / n) / n);
        EXPECT_NEAR(meanAlphaOfColumn(b, column), p, 5.0 * sigma + 1e-6) << "column " << column;
        smeared += p > 0.02 && p < 0.98;
    }
    // The ramps at both edges: kTravel of the view's 3 units, 6.4 columns each.
    EXPECT_GE(smeared, 10);
}

TEST(CameraMotionBlur, ATurningCameraTurnsAtConstantSpeedAndKeepsItsScale) {
    const std::vector<Matrix4> steps{Matrix4::translate({0, 0, 0}),
                                     Matrix4::translate({2, 0, 0}) * Matrix4::rotateY(90.0)};
    const Matrix4 half = render::cameraTransformAt(steps, 0.5f);
    // Halfway: a 45-degree turn, unit axes (interpolating elements would shrink them to cos 45).
    const Vec3d forward = half.transformVector({0, 0, -1});
    EXPECT_NEAR(length(forward), 1.0, 1e-9);
    EXPECT_NEAR(forward.x, -std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(forward.z, -std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(half.transformPoint({0, 0, 0}).x, 1.0, 1e-9);
    const Matrix4 end = render::cameraTransformAt(steps, 1.0f);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(end.m[r][c], steps[1].m[r][c], 1e-9) << r << "," << c;
}

TEST(CameraMotionBlur, AMovingCameraHasImportanceAtATimeAndRaysLeaveFromWhereItIs) {
    render::CameraDesc desc = *squareUnderSky(squareFrom(0.0f)).camera;
    desc.projection = render::Projection::Perspective;
    desc.motionTransforms = {Matrix4::translate({0, 0, 5}), Matrix4::translate({1, 0, 5})};
    const render::Camera camera(desc, kSize, kSize);
    EXPECT_FALSE(camera.hasImportance());  // only the still camera at a time has
    const render::Camera quarter = camera.at(0.25f);
    EXPECT_TRUE(quarter.hasImportance());
    EXPECT_NEAR(quarter.position().x, 0.25f, 1e-6f);
    // A point straight ahead of the camera at that time lands in the image's centre.
    const std::optional<Vec2f> raster = quarter.rasterPosition({0.25f, 0.0f, 0.0f});
    ASSERT_TRUE(raster.has_value());
    EXPECT_NEAR(raster->x, 0.5f * kSize, 1e-3f);
    EXPECT_NEAR(camera.generateRay(24.0f, 24.0f, {0.5f, 0.5f}, 0.25f).origin.x, 0.25f, 1e-6f);
    EXPECT_NEAR(camera.generateRay(24.0f, 24.0f, {0.5f, 0.5f}, 1.0f).origin.x, 1.0f, 1e-6f);
    desc.motionTransforms.pop_back();
    EXPECT_THROW(render::Camera(desc, kSize, kSize), std::invalid_argument);
}

// The motionvector AOV of a camera sliding sideways by kShift over the shutter, looking at a still
// plane kDistance away: every point of the plane moves by focal / distance * shift on the window
// at unit depth, the other way, which is -kShift / kDistance * (pixels per window unit) in pixels;
// a square that moves with the camera stays where it is on the image.
TEST(CameraMotionBlur, TheMotionVectorHoldsTheCamerasOwnMotion) {
    constexpr float kShift = 0.3f, kDistance = 5.0f;
    render::SceneDescription desc = squareUnderSky(squareFrom(-0.4f));
    desc.camera->projection = render::Projection::Perspective;
    desc.camera->horizontalAperture = desc.camera->verticalAperture = 36.0f;
    desc.camera->motionTransforms = {Matrix4::translate({0, 0, kDistance}), Matrix4::translate({kShift, 0, kDistance})};
    // The square rides along at depth 3, in front of a plane at depth 5.
    std::vector<Vec3f> riding = squareFrom(-0.4f), ridden = riding;
    for (Vec3f& p : riding) p.z = 2.0f;
    for (Vec3f& p : ridden) p = Vec3f(p.x + kShift, p.y, 2.0f);
    desc.meshes.front() = test::quadMesh("/square", {riding[0], riding[1], riding[2], riding[3]}, 0);
    desc.meshes.front().motionPositions = {riding, ridden};
    desc.meshes.push_back(test::quadMesh("/plane", {{{-9, -9, 0}, {9, -9, 0}, {9, 9, 0}, {-9, 9, 0}}}, 0));
    const render::RenderScene scene(desc);
    const render::Camera camera(*desc.camera, kSize, kSize);
    RenderSettings settings;
    settings.samplesPerPixel = 4;
    Film film(kSize, kSize, camera.farClip());
    render(scene, camera, PathTracer{IntegratorSettings{}}, settings, film);
    const Image aov = renderFirstHitAovs(scene, camera, settings, film,
                                         {FirstHitAov{FirstHitSource::MotionVector, "", 2, PixelFilter::Max}});
    const float pixelsPerWindowUnit = kSize * desc.camera->focalLength / 36.0f;
    const float expected = -kShift / kDistance * pixelsPerWindowUnit;
    for (auto [x, y] : {std::pair(2, 2), std::pair(45, 40), std::pair(40, 5)}) {  // the plane
        EXPECT_NEAR(aov.pixel(x, y)[0], expected, 1e-3f * std::abs(expected)) << x << "," << y;
        EXPECT_NEAR(aov.pixel(x, y)[1], 0.0f, 1e-3f) << x << "," << y;
    }
    EXPECT_NEAR(aov.pixel(kSize / 2, kSize / 2)[0], 0.0f, 1e-3f);  // the square, riding along
    EXPECT_NEAR(aov.pixel(kSize / 2, kSize / 2)[1], 0.0f, 1e-3f);
}

}  // namespace
}  // namespace fluence::integrators
