// Lights in motion in the render scene (render/light_motion.h, RenderScene::lightAt): a light with
// several motion steps follows each segment (not the straight line from the first step to the
// last); its shape is met where sampling puts it at the same time; its bounds hold it over the
// whole shutter; a turning dome turns; a moving emissive triangle is sampled where it is.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_scene.h"
#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

// A sphere light of radius 0.1 at height 0 whose three steps go from x = 0 to x = 1 and back:
// the straight line from its first step to its last never moves.
SceneDescription outAndBack() {
    SceneDescription s;
    LightDesc light = test::sphereLight("/bulb", 0.1f, RGB(1.0f));
    light.motionTransforms = {Matrix4::translate({0.0, 0.0, 0.0}), Matrix4::translate({1.0, 0.0, 0.0}),
                              Matrix4::translate({0.0, 0.0, 0.0})};
    s.lights.push_back(light);
    return s;
}

// Where light samples land from p at `time`: the mean of the sampled points.
Vec3f meanSampledPoint(const RenderScene& scene, const Vec3f& p, float time) {
    Vec3f sum(0.0f);
    int n = 0;
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) {
            const std::optional<LightSample> s = scene.lightAt(0, time).sample(p, {(i + 0.5f) / 16, (j + 0.5f) / 16});
            if (!s) continue;
            sum += p + s->wi * s->distance;
            ++n;
        }
    return n > 0 ? sum / float(n) : Vec3f(NAN);
}

TEST(LightMotion, ALightWithSeveralStepsFollowsEachSegment) {
    const RenderScene scene(outAndBack());
    const Vec3f p(0.5f, 0.0f, 3.0f);
    for (const auto& [time, x] : {std::pair{0.0f, 0.0f}, {0.25f, 0.5f}, {0.5f, 1.0f}, {0.75f, 0.5f}, {1.0f, 0.0f}}) {
        // Samples lie on the sphere, nearer the viewer: their mean is within the radius of the centre.
        const Vec3f mean = meanSampledPoint(scene, p, time);
        EXPECT_NEAR(mean.x, x, 0.1f) << "time " << time;
        EXPECT_NEAR(mean.y, 0.0f, 0.1f) << "time " << time;
    }
    // A ray straight down through x = 1 meets the light at mid-shutter only, on its top.
    Ray down{Vec3f(1.0f, 0.0f, 3.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 100.0f};
    down.time = 0.5f;
    const std::optional<SurfaceHit> hit = scene.intersect(down);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit->lightShape);
    EXPECT_NEAR(hit->point.z, 0.1f, 1e-4f);
    EXPECT_NEAR(hit->geometricNormal.z, 1.0f, 1e-4f);
    for (float time : {0.0f, 1.0f}) {
        down.time = time;
        EXPECT_FALSE(scene.intersect(down)) << "time " << time;
    }
    // Next-event estimation's density for that ray is the sphere's where it is then: uniform over
    // the cone it subtends from 3 units away (from sqrt(10) at the opening, a smaller cone).
    auto coneDensity = [](double distance) {
        const double sine = 0.1 / distance;
        return 1.0 / (2.0 * M_PI * (1.0 - std::sqrt(1.0 - sine * sine)));
    };
    const LightHit onTop{hit->point, hit->geometricNormal};
    EXPECT_NEAR(scene.lightAt(0, 0.5f).pdf(down.origin, down.direction, onTop), coneDensity(3.0),
                1e-3 * coneDensity(3.0));
    EXPECT_NEAR(scene.lightAt(0, 0.0f).pdf(down.origin, down.direction, onTop), coneDensity(std::sqrt(10.0)),
                1e-3 * coneDensity(std::sqrt(10.0)));
}

// A moving sphere light emits outwards only, as a still one does
// (LightRenderScene.RaysFromInsideASphereLightPassThroughItsSurface): at any time of the shutter a
// ray from inside it passes through its surface, and one from outside meets it.
TEST(LightMotion, ARayFromInsideAMovingSphereLightPassesThroughItAsThroughAStillOne) {
    SceneDescription moving = outAndBack(), still = outAndBack();
    still.lights[0].motionTransforms.clear();
    for (const SceneDescription& s : {moving, still}) {
        const RenderScene scene(s);
        const float x = s.lights[0].motionTransforms.empty() ? 0.0f : 0.5f;  // its centre at time 0.25
        for (const Vec3f& d : {Vec3f(0.0f, 0.0f, 1.0f), Vec3f(0.0f, -1.0f, 0.0f), normalize(Vec3f(1.0f, 1.0f, 1.0f))}) {
            Ray fromInside{Vec3f(x, 0.0f, 0.0f), d, 0.0f, 100.0f};
            fromInside.time = 0.25f;
            EXPECT_FALSE(scene.intersect(fromInside)) << "moving " << !s.lights[0].motionTransforms.empty();
            Ray fromOutside{Vec3f(x, 0.0f, 0.0f) - d * 2.0f, d, 0.0f, 100.0f};
            fromOutside.time = 0.25f;
            const std::optional<SurfaceHit> hit = scene.intersect(fromOutside);
            ASSERT_TRUE(hit);
            EXPECT_TRUE(hit->lightShape);
            EXPECT_NEAR(hit->t, 1.9f, 1e-4f);
        }
    }
}

TEST(LightMotion, ItsBoundsHoldItOverTheWholeShutter) {
    const RenderScene scene(outAndBack());
    const std::optional<LightBounds> b = scene.light(0).bounds();
    ASSERT_TRUE(b);
    EXPECT_LE(b->lo.x, -0.1f + 1e-5f);
    EXPECT_GE(b->hi.x, 1.1f - 1e-5f);
    // A shading point that only the light's mid-shutter place reaches well is not culled.
    EXPECT_GT(scene.lightProbability(Vec3f(1.0f, 0.0f, 1.0f), Vec3f(0.0f, 0.0f, -1.0f), 0), 0.0f);
}

TEST(LightMotion, ARectLightIsMetWhereSamplingPutsItAndTurnsWithItsSteps) {
    SceneDescription s;
    // A 1 x 1 rect facing down (-Z) at height 2, turned about X by 0, 30 and 60 degrees over three steps.
    LightDesc rect = test::rectLight("/panel", 1.0f, 1.0f, RGB(1.0f), Matrix4::translate({0.0, 0.0, 2.0}));
    for (double degrees : {0.0, 30.0, 60.0})
        rect.motionTransforms.push_back(Matrix4::translate({0.0, 0.0, 2.0}) * Matrix4::rotateX(degrees));
    s.lights.push_back(rect);
    const RenderScene scene(s);
    const Vec3f p(0.0f, 0.0f, 0.0f);
    for (float time : {0.0f, 0.3f, 0.5f, 0.9f}) {
        // At the step times exactly 0, 30 and 60 degrees; between them the polar factor of the
        // interpolated transform, which stays within the two steps' angles.
        const std::optional<LightSample> sample = scene.lightAt(0, time).sample(p, {0.7f, 0.2f});
        ASSERT_TRUE(sample);
        Ray ray{p, sample->wi, 0.0f, 100.0f};
        ray.time = time;
        const std::optional<SurfaceHit> hit = scene.intersect(ray);
        ASSERT_TRUE(hit) << "time " << time;
        EXPECT_TRUE(hit->lightShape);
        EXPECT_NEAR(hit->t, sample->distance, 1e-4f * sample->distance) << "time " << time;
        // The emitting normal (local -Z) turned about X by the angle at that time.
        const float angle = std::atan2(-hit->geometricNormal.y, -hit->geometricNormal.z) * 180.0f / float(M_PI);
        EXPECT_NEAR(std::abs(angle), 60.0f * time, time == 0.0f || time == 0.5f ? 1e-3f : 2.0f) << "time " << time;
    }
}

TEST(LightMotion, ATurningDomeTurnsThroughItsSteps) {
    SceneDescription s;
    // Bright on its +X half (longitudes 0 to pi are the image's left half), dark on the other.
    LightDesc dome = test::domeLight("/sky", RGB(1.0f));
    auto image = std::make_shared<RgbImage>();
    image->width = 4;
    image->height = 2;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) image->texels.push_back(RGB(x < 2 ? 1.0f : 0.0f));
    dome.texture = image;
    // Half a turn about Y in three steps (two steps could not say which way it turns).
    dome.motionTransforms = {Matrix4::rotateY(0.0), Matrix4::rotateY(90.0), Matrix4::rotateY(180.0)};
    s.lights.push_back(dome);
    const RenderScene scene(s);
    const Vec3f east(1.0f, 0.1f, 0.05f), west(-1.0f, 0.1f, -0.05f);
    EXPECT_GT(luminance(scene.lightAt(0, 0.0f).escaped(normalize(east))), 0.5f);
    EXPECT_EQ(luminance(scene.lightAt(0, 0.0f).escaped(normalize(west))), 0.0f);
    EXPECT_EQ(luminance(scene.lightAt(0, 1.0f).escaped(normalize(east))), 0.0f);
    EXPECT_GT(luminance(scene.lightAt(0, 1.0f).escaped(normalize(west))), 0.5f);
    // A quarter turn at mid-shutter: +X went to -Z.
    EXPECT_GT(luminance(scene.lightAt(0, 0.5f).escaped(normalize(Vec3f(0.05f, 0.1f, -1.0f)))), 0.5f);
    EXPECT_EQ(luminance(scene.lightAt(0, 0.5f).escaped(normalize(Vec3f(-0.05f, 0.1f, 1.0f)))), 0.0f);
}

TEST(LightMotion, AMovingEmissiveTriangleIsSampledWhereItIsAtTheRayTime) {
    SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/glow", RGB(0.0f), RGB(1.0f)));
    MeshDesc quad = test::quadMesh("/glow", {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)}, 0);
    for (float x : {0.0f, 4.0f, 2.0f}) {
        std::vector<Vec3f> step;
        for (const Vec3f& p : quad.positions) step.push_back(p + Vec3f(x, 0.0f, 0.0f));
        quad.motionPositions.push_back(step);
    }
    s.meshes.push_back(quad);
    const RenderScene scene(s);
    ASSERT_GE(scene.lightCount(), 1u);
    const Vec3f p(2.0f, 0.5f, 3.0f);
    for (const auto& [time, shift] : {std::pair{0.0f, 0.0f}, {0.25f, 2.0f}, {0.5f, 4.0f}, {1.0f, 2.0f}}) {
        for (std::size_t light = 0; light < scene.lightCount(); ++light) {
            const std::optional<LightSample> sample = scene.lightAt(light, time).sample(p, {0.3f, 0.6f});
            ASSERT_TRUE(sample);
            const Vec3f q = p + sample->wi * sample->distance;
            EXPECT_GE(q.x, shift - 1e-4f) << "time " << time;
            EXPECT_LE(q.x, shift + 1.0f + 1e-4f) << "time " << time;
        }
        // The bounds of each triangle hold all its places.
        EXPECT_LE(scene.light(0).bounds()->lo.x, 0.0f);
        EXPECT_GE(scene.light(0).bounds()->hi.x, 4.0f);
    }
    EXPECT_TRUE(scene.warnings().empty());
}

}  // namespace
}  // namespace fluence::render
