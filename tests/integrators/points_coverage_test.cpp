// UsdGeomPoints' primitives (render/point_geometry.h) against their known projected area: N
// spheres or discs of radius r seen by an orthographic camera along their axis cover N pi r^2
// (a disc tilted by theta from the view, pi r^2 cos theta), measured as the image's alpha. Each
// pixel's alpha is a mean of spp hit-or-miss samples, so the summed alpha has variance
// sum p (1 - p) / spp <= (pixels the outlines cross) / (4 spp): the tolerance is 5 such standard
// deviations.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSize = 96, kSpp = 64;
constexpr double kView = 6.0;  // the orthographic window's width and height, in scene units
constexpr float kRadius = 0.4f;

// Points on a 3 x 2 grid in the plane z = 0, seen from +z.
render::SceneDescription pointGrid(render::PointStyle style, const Vec3f& normal) {
    render::SceneDescription s;
    render::PointsDesc p;
    p.name = "/particles";
    p.style = style;
    for (int i = 0; i < 6; ++i) {
        p.positions.emplace_back(-1.8f + 1.8f * float(i % 3), -0.9f + 1.8f * float(i / 3), 0.0f);
        p.radii.push_back(kRadius);
        if (style == render::PointStyle::OrientedDisc) p.normals.push_back(normal);
    }
    s.points.push_back(p);
    render::CameraDesc c;
    c.projection = render::Projection::Orthographic;
    c.horizontalAperture = c.verticalAperture = float(10.0 * kView);  // tenths of a scene unit
    c.transform = Matrix4::translate({0, 0, 10});
    c.nearClip = 0.1f;
    c.farClip = 100.0f;
    s.camera = c;
    s.lights.push_back(test::domeLight("/sky", RGB(1.0f)));
    return s;
}

void expectCoverage(const render::SceneDescription& s, double expected, const char* what) {
    PathTracer path(IntegratorSettings{});
    const Image image = test_support::renderWith(path, s, kSize, kSpp, 0, 11).image;
    double alpha = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) alpha += image.pixel(x, y)[3];
    const double pixel = kView / kSize;
    const double area = alpha * pixel * pixel;
    const double outlinePixels =
        6.0 * 2.0 * kPi * kRadius / pixel * 2.0;  // generous: two pixels per pixel of perimeter
    const double sd = std::sqrt(outlinePixels / (4.0 * kSpp)) * pixel * pixel;
    EXPECT_NEAR(area, expected, 5.0 * sd) << what;
}

TEST(Points, SpheresAndDiscsCoverNPiRSquared) {
    const double covered = 6.0 * kPi * kRadius * kRadius;
    expectCoverage(pointGrid(render::PointStyle::Sphere, {}), covered, "spheres");
    expectCoverage(pointGrid(render::PointStyle::Disc, {}), covered, "discs facing the camera");
    expectCoverage(pointGrid(render::PointStyle::OrientedDisc, {0, 0, 1}), covered, "discs along +z");
    const float c = 0.5f, s = std::sqrt(0.75f);  // tilted 60 degrees from the view axis
    expectCoverage(pointGrid(render::PointStyle::OrientedDisc, {s, 0, c}), covered * 0.5, "discs tilted 60 degrees");
}

TEST(Points, HitsShadeWithTheSphereNormalColourAndPrimvars) {
    render::SceneDescription s = pointGrid(render::PointStyle::Sphere, {});
    render::PointsDesc& p = s.points.front();
    for (int i = 0; i < 6; ++i) p.colors.push_back(RGB(0.1f * float(i), 0.5f, 0.2f));
    render::PointPrimvar id{"particleId", 1, {}};
    for (int i = 0; i < 6; ++i) id.values.push_back(float(100 + i));
    p.primvars.push_back(id);
    const render::RenderScene scene(s);
    // Straight down onto point 4 (x 0, y 0.9), off its centre by half the radius in x.
    const render::Ray ray{{0.2f, 0.9f, 5.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 100.0f};
    const std::optional<render::SurfaceHit> hit = scene.intersect(ray);
    ASSERT_TRUE(hit);
    const float z = std::sqrt(kRadius * kRadius - 0.04f);
    EXPECT_NEAR(hit->point.z, z, 1e-4f);
    EXPECT_NEAR(hit->geometricNormal.x, 0.2f / kRadius, 1e-4f);
    EXPECT_NEAR(hit->geometricNormal.z, z / kRadius, 1e-4f);
    EXPECT_NEAR(hit->material.diffuse.x, 0.4f, 1e-6f);
    float value[4];
    ASSERT_EQ(scene.primvarAt(*hit, "particleId", value), 1);
    EXPECT_EQ(value[0], 104.0f);
    render::SceneDescription bad = s;
    bad.points.front().radii.pop_back();
    EXPECT_THROW(render::RenderScene{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace fluence::integrators
