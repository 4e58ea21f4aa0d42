// Motion blur of curves and points (CurvesDesc::motionPoints, PointsDesc::motionPositions; render/
// curve_geometry.h, render/point_geometry.h), seen from above through an orthographic camera: a
// straight curve moving across its own axis covers each row of pixels for the fraction of the
// shutter it spends over it, so its blur spans its width plus its displacement; a curve whose
// width grows covers its time-averaged width; a moving sphere point smears over its path and
// covers, in all, its disc's area; hits and motion vectors follow the ray's time; images are
// bit-identical at any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "integrators/first_hit_aovs.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr int kPixels = 64;
constexpr float kFrame = 4.0f;  // the camera sees x and y in [-2, 2]: 16 pixels per unit
constexpr float kRadius = 0.1f;
constexpr float kFromY = -0.5f;   // the curve's axis at the shutter's opening
constexpr float kTravelY = 0.6f;  // how far it moves along +y while the shutter is open
constexpr int kSpp = 32;

render::CameraDesc topView() {
    render::CameraDesc c;
    c.name = "/top";
    c.projection = render::Projection::Orthographic;
    c.horizontalAperture = c.verticalAperture = 10.0f * kFrame;  // tenths of a unit
    c.nearClip = 0.01f;
    c.transform = Matrix4::translate({0, 0, 10});
    return c;
}

// A straight curve along x across the whole frame at height y, in the plane z = 0.
std::vector<Vec3f> axisAt(render::CurveBasis basis, float y) {
    const int points = basis == render::CurveBasis::Linear ? 2 : 4;
    std::vector<Vec3f> out;
    for (int i = 0; i < points; ++i) out.emplace_back(-10.0f + 20.0f * float(i) / float(points - 1), y, 0.0f);
    return out;
}

render::CurvesDesc movingCurve(render::CurveBasis basis, render::CurveStyle style, int steps) {
    render::CurvesDesc c;
    c.name = "/hair";
    c.basis = basis;
    c.style = style;
    c.points = axisAt(basis, kFromY);
    c.radii.assign(c.points.size(), kRadius);
    if (style == render::CurveStyle::Oriented) c.normals.assign(c.points.size(), Vec3f(0.0f, 0.0f, 1.0f));
    c.segments.push_back(0);
    for (int k = 0; k < steps; ++k)
        c.motionPoints.push_back(axisAt(basis, kFromY + kTravelY * float(k) / float(steps - 1)));
    return c;
}

render::SceneDescription skyAbove(render::SceneDescription s) {
    s.lights.push_back(test::domeLight("/dome", RGB(1.0f)));
    s.lights.back().visibleToCamera = false;
    s.camera = topView();
    return s;
}

const PathTracer& tracer() {
    static const PathTracer t{IntegratorSettings{.maxDepth = 1, .parameters = {}, .lightPathAovs = {}}};
    return t;
}

// The image row whose centre is at height y of the frame, and the height of a row's centre.
float rowCentre(int row) { return 0.5f * kFrame - (float(row) + 0.5f) * kFrame / kPixels; }

// The fraction of the shutter during which a band of half-width kRadius around y0 + travel t
// covers height y, averaged over the pixel row `row` (exact integral of a piecewise-linear function
// by fine midpoint sums).
double sweptRowCoverage(int row, float y0, float travel) {
    const double height = kFrame / kPixels, bottom = rowCentre(row) - 0.5 * height;
    auto fractionAt = [&](double y) {
        const double enter = std::clamp((y - kRadius - y0) / travel, 0.0, 1.0);
        const double leave = std::clamp((y + kRadius - y0) / travel, 0.0, 1.0);
        return leave - enter;
    };
    constexpr int kSlices = 1000;
    double sum = 0.0;
    for (int i = 0; i < kSlices; ++i) sum += fractionAt(bottom + (i + 0.5) * height / kSlices);
    return sum / kSlices;
}

// The mean alpha of a pixel row.
double rowAlpha(const Image& image, int row) {
    const int a = image.channelIndex("A");
    double sum = 0.0;
    for (int x = 0; x < kPixels; ++x) sum += image.pixel(x, row)[a];
    return sum / kPixels;
}

// Each pixel's coverage samples hit or miss: the standard error of a row's mean of kPixels * kSpp.
double rowSigma(double p) {
    const double n = double(kPixels) * kSpp;
    return std::sqrt(std::max(p * (1.0 - p), 1.0 / n) / n);
}

TEST(CurveMotionBlur, AMovingCurveCoversRowsForTheShutterFractionItSpendsOverThem) {
    struct Case {
        const char* name;
        render::CurveBasis basis;
        render::CurveStyle style;
        int steps;
    };
    const Case cases[] = {{"round linear", render::CurveBasis::Linear, render::CurveStyle::Round, 2},
                          {"flat bspline, 3 steps", render::CurveBasis::BSpline, render::CurveStyle::Flat, 3},
                          {"oriented linear", render::CurveBasis::Linear, render::CurveStyle::Oriented, 2}};
    for (const Case& c : cases) {
        render::SceneDescription s;
        s.curves.push_back(movingCurve(c.basis, c.style, c.steps));
        const Image image = test_support::renderWith(tracer(), skyAbove(std::move(s)), kPixels, kSpp, 0, 3).image;
        int blurred = 0;
        for (int row = 0; row < kPixels; ++row) {
            const double expected = sweptRowCoverage(row, kFromY, kTravelY), measured = rowAlpha(image, row);
            if (expected == 0.0) {
                EXPECT_EQ(measured, 0.0) << c.name << " row " << row;
            }
            EXPECT_NEAR(measured, expected, 5.0 * rowSigma(expected)) << c.name << " row " << row;
            blurred += measured > 0.0;
        }
        // The blur spans the width plus the displacement, (2 r + travel) * 16 = 12.8 rows: 13 or 14
        // rows as the band's ends cut them (the end rows are barely covered, so 12 may show).
        const float extent = (2.0f * kRadius + kTravelY) * kPixels / kFrame;
        EXPECT_GE(blurred, int(std::floor(extent))) << c.name;
        EXPECT_LE(blurred, int(std::ceil(extent)) + 1) << c.name;
    }
}

TEST(CurveMotionBlur, AGrowingWidthCoversItsTimeAverage) {
    render::SceneDescription s;
    render::CurvesDesc curve = movingCurve(render::CurveBasis::Linear, render::CurveStyle::Round, 2);
    curve.motionPoints = {curve.points, curve.points};  // still, but widening from r to 3 r
    curve.motionRadii = {std::vector<float>(2, kRadius), std::vector<float>(2, 3.0f * kRadius)};
    s.curves.push_back(curve);
    const Image image = test_support::renderWith(tracer(), skyAbove(std::move(s)), kPixels, kSpp, 0, 4).image;
    double covered = 0.0, variance = 0.0;
    for (int row = 0; row < kPixels; ++row) {
        const double alpha = rowAlpha(image, row);
        covered += alpha * kFrame / kPixels;  // units of height
        variance += std::pow(rowSigma(alpha) * kFrame / kPixels, 2.0);
    }
    // The band's mean width over the shutter: 2 (r + 3 r) / 2 = 4 r.
    EXPECT_NEAR(covered, 4.0 * kRadius, 5.0 * std::sqrt(variance));
}

TEST(CurveMotionBlur, AMovingPointSmearsAlongItsPath) {
    render::SceneDescription s;
    render::PointsDesc points;
    points.name = "/sparks";
    points.positions = {Vec3f(-0.8f, 0.0f, 0.0f)};
    points.radii = {0.25f};
    points.motionPositions = {{Vec3f(-0.8f, 0.0f, 0.0f)}, {Vec3f(0.8f, 0.0f, 0.0f)}};
    s.points.push_back(points);
    const Image image = test_support::renderWith(tracer(), skyAbove(std::move(s)), kPixels, kSpp, 0, 5).image;
    const int a = image.channelIndex("A");
    double covered = 0.0, variance = 0.0;
    for (std::size_t p = 0; p < image.pixels.size(); p += image.channels.size()) {
        const double alpha = image.pixels[p + std::size_t(a)];
        covered += alpha;
        variance += alpha * (1.0 - alpha) / kSpp;
    }
    const double unitsPerPixel = std::pow(kFrame / kPixels, 2.0);
    // Area is conserved by the smear: the disc's pi r^2 in all.
    EXPECT_NEAR(covered * unitsPerPixel, M_PI * 0.25 * 0.25, 5.0 * std::sqrt(variance) * unitsPerPixel + 1e-4);
    // At the middle of its path, where the sphere never is at rest: covered for 2 r / travel of the
    // shutter (the pixel at x = 0, y = 0); beyond its path's ends, never.
    const auto alphaAt = [&](float x) {
        const int column = int((x + 0.5f * kFrame) / kFrame * kPixels), row = kPixels / 2;
        return image.pixel(column, row)[a];
    };
    EXPECT_GT(alphaAt(0.0f), 0.0f);
    EXPECT_EQ(alphaAt(-1.2f), 0.0f);
    EXPECT_EQ(alphaAt(1.2f), 0.0f);
}

TEST(CurveMotionBlur, HitsAndMotionVectorsFollowTheRayTime) {
    render::SceneDescription s;
    s.curves.push_back(movingCurve(render::CurveBasis::Bezier, render::CurveStyle::Round, 2));
    const render::SceneDescription desc = skyAbove(std::move(s));
    const render::RenderScene scene(desc);
    // Straight down at y = kFromY + 0.3: the axis is there at time 0.5, the tube from 0.5 - r / travel.
    render::Ray ray{Vec3f(0.0f, kFromY + 0.3f, 5.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 100.0f};
    ray.time = 0.1f;
    EXPECT_FALSE(scene.intersect(ray));
    ray.time = 0.5f;
    const std::optional<render::SurfaceHit> hit = scene.intersect(ray);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.z, kRadius, 1e-4f);  // the top of the tube, where the axis is now
    EXPECT_NEAR(hit->geometricNormal.z, 1.0f, 1e-3f);
    EXPECT_NEAR(scene.pointAt(*hit, 1.0f).y - scene.pointAt(*hit, 0.0f).y, kTravelY, 1e-5f);

    const render::Camera camera(*desc.camera, kPixels, kPixels);
    RenderSettings settings;
    settings.samplesPerPixel = 4;
    Film film(kPixels, kPixels, camera.farClip());
    render(scene, camera, tracer(), settings, film);
    const Image aov = renderFirstHitAovs(scene, camera, settings, film,
                                         {FirstHitAov{FirstHitSource::MotionVector, "", 2, PixelFilter::Max}});
    // Every hit moves by the travel: up the image (motion vectors count y upwards), 16 kTravelY pixels.
    const int row = int((0.5f * kFrame - (kFromY + 0.3f)) / kFrame * kPixels);
    EXPECT_NEAR(aov.pixel(kPixels / 2, row)[1], kTravelY * kPixels / kFrame, 1e-3f);
    EXPECT_NEAR(aov.pixel(kPixels / 2, row)[0], 0.0f, 1e-3f);
}

TEST(CurveMotionBlur, ImagesAreBitIdenticalAcrossThreadCounts) {
    render::SceneDescription s;
    s.curves.push_back(movingCurve(render::CurveBasis::CatmullRom, render::CurveStyle::Round, 3));
    const render::SceneDescription desc = skyAbove(std::move(s));
    const Image one = test_support::renderWith(tracer(), desc, kPixels, 4, 1, 9).image;
    const Image two = test_support::renderWith(tracer(), desc, kPixels, 4, 2, 9).image;
    ASSERT_EQ(one.pixels.size(), two.pixels.size());
    EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)));
}

}  // namespace
}  // namespace fluence::integrators
