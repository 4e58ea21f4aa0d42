// Motion blur in the render core (render/motion_geometry.h): a square moving at known speed
// while the shutter is open, seen through an orthographic camera, covers each pixel for the
// fraction of the shutter the square spends over it, so its alpha ramps across the box-filtered
// width of the motion; deformation blur (time-stepped positions) and transformation blur
// (time-stepped instance transforms) of the same motion agree within noise; images stay
// bit-identical across thread counts and tiles; hits are shaded where the ray's time puts them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "integrators/first_hit_aovs.h"
#include "integrators/path_tracer.h"
#include "render/motion_geometry.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using test_support::Rendered;
using test_support::renderWith;

constexpr int kSize = 64;
constexpr float kHalfWidth = 1.0f;  // the camera sees x and y in [-1, 1]: 32 pixels per unit
constexpr float kSquare = 0.5f;     // the square's side
constexpr float kStart = -0.5f;     // its left edge at the shutter's opening
constexpr float kTravel = 0.25f;    // how far it moves along +x while the shutter is open
constexpr float kDepth = -5.0f;

render::CameraDesc orthographicCamera() {
    render::CameraDesc c;
    c.name = "/camera";
    c.projection = render::Projection::Orthographic;
    c.horizontalAperture = c.verticalAperture = 20.0f * kHalfWidth;  // tenths of a unit
    c.nearClip = 0.1f;
    c.farClip = 100.0f;
    return c;
}

// The square with its left edge at x = left, in the plane z = kDepth.
std::array<Vec3f, 4> squareAt(float left) {
    const float h = 0.5f * kSquare;
    return {Vec3f(left, -h, kDepth), Vec3f(left + kSquare, -h, kDepth), Vec3f(left + kSquare, h, kDepth),
            Vec3f(left, h, kDepth)};
}

render::SceneDescription sceneWith(render::MeshDesc square) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.5f)));
    s.lights.push_back(test::domeLight("/sky", RGB(1.0f)));
    s.camera = orthographicCamera();
    s.meshes.push_back(std::move(square));
    return s;
}

// Deformation blur: the square's positions at `steps` evenly spaced times.
render::SceneDescription deformingSquare(int steps) {
    render::MeshDesc square = test::quadMesh("/square", squareAt(kStart), 0);
    for (int k = 0; k < steps; ++k) {
        const auto corners = squareAt(kStart + kTravel * float(k) / float(steps - 1));
        square.motionPositions.emplace_back(corners.begin(), corners.end());
    }
    return sceneWith(std::move(square));
}

// Transformation blur: a prototype square at the origin, its instance translated over the shutter.
render::SceneDescription translatedSquare() {
    render::SceneDescription s = sceneWith(test::quadMesh("/proto/square", squareAt(0.0f), 0));
    s.prototypes.push_back({"/proto", {std::move(s.meshes.front())}});
    s.meshes.clear();
    render::InstanceDesc instance;
    instance.prototype = 0;
    instance.transform = Matrix4::translate({kStart, 0.0, 0.0});
    instance.name = "/instance";
    instance.motionTransforms = {Matrix4::translate({kStart, 0.0, 0.0}),
                                 Matrix4::translate({kStart + kTravel, 0.0, 0.0})};
    s.instances.push_back(instance);
    return s;
}

const PathTracer& tracer() {
    static const PathTracer t{IntegratorSettings{.maxDepth = 2, .parameters = {}, .lightPathAovs = {}}};
    return t;
}

// The fraction of the shutter in which the square covers the point x (uniform motion).
double coverage(double x) {
    // Covered while kStart + kTravel t <= x <= kStart + kTravel t + kSquare, t in [0, 1].
    const double lo = std::max(0.0, (x - kStart - kSquare) / kTravel), hi = std::min(1.0, (x - kStart) / kTravel);
    return std::max(0.0, hi - lo);
}

// The expected alpha of pixel column `column`: coverage averaged over the pixel's width (box filter).
double expectedAlpha(int column) {
    const double pixel = 2.0 * kHalfWidth / kSize, x0 = -kHalfWidth + column * pixel;
    constexpr int kSteps = 2000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) sum += coverage(x0 + (i + 0.5) * pixel / kSteps);
    return sum / kSteps;
}

// The mean alpha of pixel column `column` over the rows the square covers.
double columnAlpha(const Image& image, int column) {
    const int alpha = image.channelIndex("A");
    double sum = 0.0;
    int rows = 0;
    for (int y = 0; y < kSize; ++y) {
        const double yCentre = kHalfWidth - (y + 0.5) * 2.0 * kHalfWidth / kSize;
        if (std::abs(yCentre) > 0.5 * kSquare - 0.05) continue;  // rows wholly inside the square's height
        sum += image.pixel(column, y)[alpha];
        ++rows;
    }
    return sum / rows;
}

TEST(MotionBlur, AMovingSquareSmearsToTheBoxFilteredWidthOfItsMotion) {
    constexpr int kSpp = 64;
    const Rendered r = renderWith(tracer(), deformingSquare(2), kSize, kSpp, 0, 7);
    int partial = 0;
    for (int column = 0; column < kSize; ++column) {
        const double expected = expectedAlpha(column);
        // Each sample covers or not: a binomial mean over the column's samples (rows x spp).
        const double n = 6.0 * kSpp, sigma = std::sqrt(std::max(expected * (1.0 - expected), 1.0 / n) / n);
        EXPECT_NEAR(columnAlpha(r.image, column), expected, 5.0 * sigma + 1e-6) << "column " << column;
        partial += expected > 0.0 && expected < 1.0;
    }
    // The ramps: kTravel at each edge, 8 pixels each, the columns between covered the whole time.
    EXPECT_EQ(partial, 2 * int(std::round(kTravel * kSize / (2.0f * kHalfWidth))));
}

TEST(MotionBlur, DeformationAndTransformationBlurOfTheSameMotionAgree) {
    constexpr int kSpp = 64;
    const Rendered deformed = renderWith(tracer(), deformingSquare(2), kSize, kSpp, 0, 11);
    const Rendered threeSteps = renderWith(tracer(), deformingSquare(3), kSize, kSpp, 0, 12);
    const Rendered moved = renderWith(tracer(), translatedSquare(), kSize, kSpp, 0, 13);
    for (int column = 0; column < kSize; ++column) {
        const double p = expectedAlpha(column), n = 6.0 * kSpp;
        const double sigma = std::sqrt(2.0 * std::max(p * (1.0 - p), 1.0 / n) / n);  // of a difference of two means
        EXPECT_NEAR(columnAlpha(deformed.image, column), columnAlpha(moved.image, column), 5.0 * sigma + 1e-6)
            << column;
        EXPECT_NEAR(columnAlpha(deformed.image, column), columnAlpha(threeSteps.image, column), 5.0 * sigma + 1e-6)
            << column;
    }
}

TEST(MotionBlur, ImagesAreBitIdenticalAcrossThreadCountsAndTiles) {
    for (SamplerKind sampler : test_support::kSamplers)
        test_support::expectBitIdenticalAcrossThreadCountsAndTiles(tracer(), translatedSquare(), kSize, sampler);
}

TEST(MotionBlur, HitsAreShadedWhereTheRayTimePutsThem) {
    const render::SceneDescription desc = translatedSquare();
    const render::RenderScene scene(desc);
    // A ray down the view axis 0.1 right of the square's right edge at the opening: the edge
    // reaches it at time 0.1 / kTravel = 0.4, so earlier rays miss and later ones hit.
    render::Ray ray{Vec3f(kStart + kSquare + 0.1f, 0.0f, 0.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 100.0f};
    ray.time = 0.2f;  // the right edge is then at kStart + kSquare + 0.05: missed
    EXPECT_FALSE(scene.intersect(ray));
    ray.time = 0.6f;  // at kStart + kSquare + 0.15: hit
    const std::optional<render::SurfaceHit> hit = scene.intersect(ray);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.x, kStart + kSquare + 0.1f, 1e-5f);
    EXPECT_NEAR(hit->point.z, kDepth, 1e-5f);
    EXPECT_FLOAT_EQ(hit->time, 0.6f);
    // The same point of the square at the shutter's ends: moved by the whole travel between them.
    EXPECT_NEAR(scene.pointAt(*hit, 1.0f).x - scene.pointAt(*hit, 0.0f).x, kTravel, 1e-5f);
    EXPECT_NEAR(scene.pointAt(*hit, 0.6f).x, hit->point.x, 1e-5f);
    // Shadow rays see it where their time puts it too.
    EXPECT_FALSE(scene.occluded(ray.origin, ray.direction, 100.0f, 0.2f));
    EXPECT_TRUE(scene.occluded(ray.origin, ray.direction, 100.0f, 0.6f));
}

TEST(MotionBlur, TheMotionVectorAovIsTheScreenSpaceTravel) {
    const render::SceneDescription desc = deformingSquare(2);
    const render::RenderScene scene(desc);
    const render::Camera camera(*desc.camera, kSize, kSize);
    RenderSettings settings;
    settings.samplesPerPixel = 4;
    Film film(kSize, kSize, camera.farClip());
    render(scene, camera, tracer(), settings, film);
    const Image aov = renderFirstHitAovs(scene, camera, settings, film,
                                         {FirstHitAov{FirstHitSource::MotionVector, "", 2, PixelFilter::Max}});
    // Where the square is the whole shutter long (columns 24 to 31, rows inside it): kTravel to the
    // right, in pixels, and nothing vertically; where nothing is, zero.
    const float pixels = kTravel * kSize / (2.0f * kHalfWidth);
    EXPECT_NEAR(aov.pixel(28, 32)[0], pixels, 1e-3f);
    EXPECT_NEAR(aov.pixel(28, 32)[1], 0.0f, 1e-3f);
    EXPECT_EQ(aov.pixel(2, 2)[0], 0.0f);
}

TEST(MotionBlur, MotionStepsInterpolateAsEmbreeDoes) {
    const std::vector<std::vector<Vec3f>> steps{{Vec3f(0.0f)}, {Vec3f(1.0f, 0.0f, 0.0f)}, {Vec3f(1.0f, 2.0f, 0.0f)}};
    EXPECT_EQ(render::positionAt(steps, 0, 0.0f).x, 0.0f);
    EXPECT_NEAR(render::positionAt(steps, 0, 0.25f).x, 0.5f, 1e-6f);
    EXPECT_NEAR(render::positionAt(steps, 0, 0.75f).y, 1.0f, 1e-6f);
    EXPECT_EQ(render::positionAt(steps, 0, 1.0f).y, 2.0f);
    EXPECT_THROW(render::checkMotionPositions("/m", {{Vec3f(0.0f)}}, 1), std::invalid_argument);
    EXPECT_THROW(render::checkMotionPositions("/m", {{Vec3f(0.0f)}, {}}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::integrators
