// Lights that move while the shutter is open (render/light_motion.h, RenderScene::lightAt): a small
// sphere light crossing a diffuse plane at constant speed lights it with the time average of its
// irradiance (an analytic profile); a moving emissive quad and a moving rect light of the same
// radiance smear to the box-filtered width of their motion when seen, and light a plane alike;
// images stay bit-identical across thread counts and tiles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"
#include "tests/support/statistics.h"

namespace fluence::integrators {
namespace {

using test_support::Rendered;
using test_support::renderWith;

constexpr int kSize = 64;
constexpr double kHalfWidth = 1.0;  // every camera here sees [-1, 1] in x and y where it looks

const PathTracer& tracer() {
    static const PathTracer t{IntegratorSettings{.maxDepth = 4, .parameters = {}, .lightPathAovs = {}}};
    return t;
}

const Bdpt& bdpt() {
    static const Bdpt b{IntegratorSettings{.maxDepth = 4, .parameters = {}, .lightPathAovs = {}}};
    return b;
}

double pixelCentre(int index) { return -kHalfWidth + (index + 0.5) * 2.0 * kHalfWidth / kSize; }
// Image rows run from +y (top) down.
double rowCentre(int row) { return -pixelCentre(row); }

// The mean of f(x, y) over the pixel (column, row) (a box filter), on a 16 x 16 grid of its points.
template <class F>
double pixelMean(int column, int row, F&& f) {
    const double pixel = 2.0 * kHalfWidth / kSize;
    constexpr int kGrid = 16;
    double sum = 0.0;
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j)
            sum += f(pixelCentre(column) + ((i + 0.5) / kGrid - 0.5) * pixel,
                     rowCentre(row) + ((j + 0.5) / kGrid - 0.5) * pixel);
    return sum / (kGrid * kGrid);
}

// ---- (a) A sphere light of radius r and radiance L crossing above a Lambertian plane z = 0 of
// albedo rho, its centre at height h going from x0 to x0 + v along y = 0 while the shutter is open.
// A sphere wholly above a point's horizon gives it the irradiance pi L (r/d)^2 cos(theta), so the
// plane's radiance is rho L r^2 h / d^3, whose time average is
//     rho L r^2 h / v * [F(x - x0) - F(x - x0 - v)],  F(u) = u / (b^2 sqrt(u^2 + b^2)),  b^2 = y^2 + h^2.
constexpr double kRho = 0.5, kRadiance = 200.0, kRadius = 0.05, kHeight = 0.5, kFrom = -0.5, kSpeed = 1.0;

double averagePlaneRadiance(double x, double y) {
    const double b2 = y * y + kHeight * kHeight;
    auto F = [&](double u) { return u / (b2 * std::sqrt(u * u + b2)); };
    return kRho * kRadiance * kRadius * kRadius * kHeight / kSpeed * (F(x - kFrom) - F(x - kFrom - kSpeed));
}

// The radiance of the plane under the light held still at x = xc.
double stillPlaneRadiance(double x, double y, double xc) {
    const double d = std::sqrt((x - xc) * (x - xc) + y * y + kHeight * kHeight);
    return kRho * kRadiance * kRadius * kRadius * kHeight / (d * d * d);
}

render::CameraDesc cameraAbove() {  // orthographic, looking down -Z
    render::CameraDesc c;
    c.name = "/camera";
    c.projection = render::Projection::Orthographic;
    c.horizontalAperture = c.verticalAperture = float(20.0 * kHalfWidth);
    c.transform = Matrix4::translate({0.0, 0.0, 5.0});
    c.nearClip = 0.1f;
    c.farClip = 100.0f;
    return c;
}

render::SceneDescription sphereCrossingAPlane() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/plane", RGB(float(kRho))));
    s.meshes.push_back(
        test::quadMesh("/plane", {Vec3f(-20, -20, 0), Vec3f(20, -20, 0), Vec3f(20, 20, 0), Vec3f(-20, 20, 0)}, 0));
    // Made at the frame (mid-shutter), moved by its steps: the frame's own place does not matter.
    render::LightDesc light =
        test::sphereLight("/bulb", float(kRadius), RGB(float(kRadiance)), {kFrom + 0.5 * kSpeed, 0.0, kHeight});
    light.motionTransforms = {Matrix4::translate({kFrom, 0.0, kHeight}),
                              Matrix4::translate({kFrom + kSpeed, 0.0, kHeight})};
    s.lights.push_back(light);
    s.camera = cameraAbove();
    return s;
}

// Rows that camera rays reach the plane on without passing the light (|y| well beyond its radius).
bool rowClearOfTheLight(int row) { return std::abs(rowCentre(row)) > 3.0 * kRadius; }

// Per column, the pixels' mean difference from `expected` over the rows clear of the light,
// within 5 standard errors of the residuals; returns the largest |mean difference| / standard error.
template <class Expected>
double expectColumnsMatch(const Image& image, Expected&& expected, const char* method) {
    double worst = 0.0;
    for (int column = 0; column < kSize; ++column) {
        test::MeanEstimate residual;
        for (int row = 0; row < kSize; ++row)
            if (rowClearOfTheLight(row)) residual.add(image.pixel(column, row)[0] - expected(column, row));
        const double error = residual.unbiasedStandardError() + 1e-9;
        EXPECT_NEAR(residual.mean(), 0.0, 5.0 * error) << method << ", column " << column;
        worst = std::max(worst, std::abs(residual.mean()) / error);
    }
    return worst;
}

TEST(LightMotionBlur, ASphereLightCrossingAPlaneLightsItWithTheTimeAverageOfItsIrradiance) {
    auto expected = [](int column, int row) { return pixelMean(column, row, averagePlaneRadiance); };
    const Rendered path = renderWith(tracer(), sphereCrossingAPlane(), kSize, 64, 0, 3);
    expectColumnsMatch(path.image, expected, "path");
    const Rendered light = renderWith(bdpt(), sphereCrossingAPlane(), kSize, 16, 0, 4);
    expectColumnsMatch(light.image, expected, "bdpt");
    // The test tells motion from stillness: under the light held where it is at the frame, the
    // plane's centre column would be far from the time average, by many times the noise.
    test::MeanEstimate noise;
    double gap = 0.0;
    int rows = 0;
    for (int row = 0; row < kSize; ++row)
        if (rowClearOfTheLight(row)) {
            const int column = kSize / 2;
            noise.add(path.image.pixel(column, row)[0] - expected(column, row));
            gap += pixelMean(column, row, [](double x, double y) { return stillPlaneRadiance(x, y, 0.0); }) -
                   expected(column, row);
            ++rows;
        }
    EXPECT_GT(gap / rows, 20.0 * noise.unbiasedStandardError());
}

// ---- (b) A square of side 0.5 and radiance 1, its left edge going from -0.5 to -0.25 along x
// while the shutter is open: an emissive quad (deformation blur) or a rect light (its transform
// at two steps).
constexpr float kSquare = 0.5f, kStart = -0.5f, kTravel = 0.25f;

std::array<Vec3f, 4> squareAt(float left, float z) {
    const float h = 0.5f * kSquare;
    return {Vec3f(left, -h, z), Vec3f(left + kSquare, -h, z), Vec3f(left + kSquare, h, z), Vec3f(left, h, z)};
}

enum class Emitter { Quad, RectLight };

// The moving square at height z, emitting towards -Z (the quad emits both ways).
void addMovingSquare(render::SceneDescription& s, Emitter emitter, float z) {
    if (emitter == Emitter::Quad) {
        s.materials.push_back(test::diffuseMaterial("/glow", RGB(0.0f), RGB(1.0f)));
        render::MeshDesc quad = test::quadMesh("/square", squareAt(kStart, z), int(s.materials.size()) - 1);
        for (float left : {kStart, kStart + kTravel}) {
            const auto corners = squareAt(left, z);
            quad.motionPositions.emplace_back(corners.begin(), corners.end());
        }
        s.meshes.push_back(quad);
        return;
    }
    const double centre = kStart + 0.5 * kSquare;
    render::LightDesc rect =
        test::rectLight("/square", kSquare, kSquare, RGB(1.0f), Matrix4::translate({centre, 0, z}));
    rect.motionTransforms = {Matrix4::translate({centre, 0.0, z}), Matrix4::translate({centre + kTravel, 0.0, z})};
    s.lights.push_back(rect);
}

// Seen from below by a pinhole camera at the origin looking up +Z, the square at z = 5 fills
// [-1, 1] in x and y of the image (focal length 50, aperture 20).
render::SceneDescription seenDirectly(Emitter emitter) {
    render::SceneDescription s;
    render::CameraDesc c;
    c.name = "/camera";
    c.focalLength = 50.0f;
    c.horizontalAperture = c.verticalAperture = 20.0f;
    c.transform = Matrix4::rotateX(180.0);
    c.nearClip = 0.1f;
    s.camera = c;
    addMovingSquare(s, emitter, 5.0f);
    return s;
}

// The fraction of the shutter in which the square covers x.
double coverage(double x) {
    const double lo = std::max(0.0, (x - kStart - kSquare) / kTravel), hi = std::min(1.0, (x - kStart) / kTravel);
    return std::max(0.0, hi - lo);
}

// Rows wholly inside the square's height (the camera's image runs down in y from the top, which
// the turn about X flips: symmetric here).
bool rowInsideTheSquare(int row) { return std::abs(rowCentre(row)) < 0.5 * kSquare - 0.05; }

TEST(LightMotionBlur, AMovingEmissiveQuadAndRectLightSmearToTheBoxFilteredWidthOfTheirMotion) {
    constexpr int kSpp = 64;
    const Rendered quad = renderWith(tracer(), seenDirectly(Emitter::Quad), kSize, kSpp, 0, 21);
    const Rendered rect = renderWith(tracer(), seenDirectly(Emitter::RectLight), kSize, kSpp, 0, 22);
    int partial = 0;
    for (int column = 0; column < kSize; ++column) {
        const double expected = pixelMean(column, 0, [](double x, double) { return coverage(x); });
        test::MeanEstimate seenQuad, seenRect;
        for (int row = 0; row < kSize; ++row)
            if (rowInsideTheSquare(row)) {
                seenQuad.add(quad.image.pixel(column, row)[0]);
                seenRect.add(rect.image.pixel(column, row)[0]);
            }
        // Each sample sees the square or not: a binomial mean over the column's samples.
        const double n = seenQuad.count() * double(kSpp);
        const double sigma = std::sqrt(std::max(expected * (1.0 - expected), 1.0 / n) / n);
        EXPECT_NEAR(seenQuad.mean(), expected, 5.0 * sigma + 1e-6) << "quad, column " << column;
        EXPECT_NEAR(seenRect.mean(), expected, 5.0 * sigma + 1e-6) << "rect light, column " << column;
        partial += expected > 0.0 && expected < 1.0;
    }
    EXPECT_EQ(partial, 2 * int(std::round(kTravel * kSize / (2.0 * kHalfWidth))));  // the two ramps
}

// The square at z = 1 lighting a Lambertian plane z = 0, seen from a pinhole camera between them at
// z = 0.5 looking down (the light behind it, out of view; focal length 10: [-0.5, 0.5] of the plane).
render::SceneDescription lightingAPlane(Emitter emitter) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/plane", RGB(0.5f)));
    s.meshes.push_back(
        test::quadMesh("/plane", {Vec3f(-20, -20, 0), Vec3f(20, -20, 0), Vec3f(20, 20, 0), Vec3f(-20, 20, 0)}, 0));
    render::CameraDesc c;
    c.name = "/camera";
    c.focalLength = 10.0f;
    c.horizontalAperture = c.verticalAperture = 20.0f;
    c.transform = Matrix4::translate({0.0, 0.0, 0.5});
    c.nearClip = 0.01f;
    s.camera = c;
    addMovingSquare(s, emitter, 1.0f);
    return s;
}

TEST(LightMotionBlur, AMovingEmissiveQuadAndRectLightLightAPlaneAlike) {
    const Rendered quad = renderWith(tracer(), lightingAPlane(Emitter::Quad), kSize, 32, 0, 31);
    const Rendered rect = renderWith(tracer(), lightingAPlane(Emitter::RectLight), kSize, 32, 0, 32);
    auto all = [](const float*) { return true; };
    const test::MeanEstimate byQuad = test_support::channelMean(quad.image, 0, all);
    const test::MeanEstimate byRect = test_support::channelMean(rect.image, 0, all);
    const double sigma = std::hypot(byQuad.standardError(), byRect.standardError());
    EXPECT_GT(byQuad.mean(), 20.0 * byQuad.standardError());  // lit
    EXPECT_NEAR(byQuad.mean(), byRect.mean(), 5.0 * sigma);
    // Column by column too: the blurred light's footprint moves with the motion alike.
    for (int column = 0; column < kSize; column += 8) {
        test::MeanEstimate q, r;
        for (int c = column; c < column + 8; ++c)
            for (int row = 0; row < kSize; ++row) {
                q.add(quad.image.pixel(c, row)[0]);
                r.add(rect.image.pixel(c, row)[0]);
            }
        EXPECT_NEAR(q.mean(), r.mean(), 5.0 * std::hypot(q.unbiasedStandardError(), r.unbiasedStandardError()))
            << "columns from " << column;
    }
}

// ---- (c) Moving lights of every kind that has a shape, bit for bit at 1 and 2 threads and in a tile.
TEST(LightMotionBlur, ImagesAreBitIdenticalAcrossThreadCountsAndTiles) {
    render::SceneDescription s = lightingAPlane(Emitter::RectLight);
    addMovingSquare(s, Emitter::Quad, 1.5f);
    render::LightDesc sphere = sphereCrossingAPlane().lights.front();
    s.lights.push_back(sphere);
    render::LightDesc disk = test::diskLight("/disk", 0.2f, RGB(2.0f), Matrix4::translate({0.0, 0.3, 1.2}));
    disk.motionTransforms = {Matrix4::translate({-0.2, 0.3, 1.2}),
                             Matrix4::translate({0.2, 0.3, 1.2}) * Matrix4::rotateY(20.0)};
    s.lights.push_back(disk);
    for (SamplerKind sampler : test_support::kSamplers)
        test_support::expectBitIdenticalAcrossThreadCountsAndTiles(tracer(), s, kSize, sampler);
}

}  // namespace
}  // namespace fluence::integrators
