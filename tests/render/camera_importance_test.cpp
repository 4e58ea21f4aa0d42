// The perspective camera's importance (render/camera.h, "Importance"; render/camera_importance.cpp):
// its direction density integrates to one over the sphere (a quadrature independent of the
// formula's Jacobian), equals the share of the image a small patch of pixels covers divided by the
// patch's solid angle (from generateRay's own rays), raster positions invert generateRay, points
// outside the image or the clipping range land nowhere, connections point at the pinhole, and an
// orthographic camera has no importance. Under a plain, an offset, non-square one with a pixel
// aspect ratio, and a non-uniformly scaled transform; and through a thin lens, from each aperture
// point.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "render/camera.h"

namespace fluence::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Case {
    std::string name;
    CameraDesc desc;
    int width, height;
    ImageFraming framing;
};

std::vector<Case> cameras() {
    CameraDesc plain;
    plain.focalLength = 35.0f;
    plain.horizontalAperture = 25.0f;
    plain.verticalAperture = 25.0f;
    plain.nearClip = 0.1f;
    plain.farClip = 1000.0f;
    plain.transform = Matrix4::translate({1, 2, 3}) * Matrix4::rotateY(30);
    CameraDesc offset = plain;
    offset.focalLength = 20.0f;
    offset.horizontalApertureOffset = 3.0f;
    offset.verticalApertureOffset = -2.0f;
    CameraDesc scaled = plain;  // the transform stretches the window unevenly (importance follows its Jacobian)
    scaled.transform = Matrix4::translate({-2, 0, 1}) * Matrix4::rotateX(-20) * Matrix4::scale({2.0, 0.5, 1.5});
    return {{"plain", plain, 48, 48, {}},
            {"offset", offset, 64, 36, {1.25f, ApertureConform::ExpandAperture}},
            {"scaled", scaled, 40, 30, {}}};
}

Vec3f rayPoint(const Ray& r, float t) { return r.origin + r.direction * t; }

// The integral of We cos = directionDensity over the sphere, by the midpoint rule in (cos theta,
// phi) about the view axis, over the cone that holds the image.
TEST(CameraImportance, IntegratesToOneOverTheImage) {
    for (const Case& c : cameras()) {
        const Camera camera(c.desc, c.width, c.height, c.framing);
        const Vec3f forward = camera.generateRay(0.5f * c.width, 0.5f * c.height)
                                  .direction;  // not the axis with offsets: any pole will do
        double minCos = 1.0;
        for (float x : {0.0f, float(c.width)})
            for (float y : {0.0f, float(c.height)})
                minCos = std::min(minCos, double(dot(camera.generateRay(x, y).direction, forward)));
        minCos = std::max(-1.0, minCos - 0.05);
        const Vec3f a = normalize(cross(forward, std::abs(forward.x) < 0.9f ? Vec3f(1, 0, 0) : Vec3f(0, 1, 0)));
        const Vec3f b = cross(forward, a);
        const int n = 1200;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double cosTheta = 1.0 - (1.0 - minCos) * (i + 0.5) / n;
            const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
            for (int j = 0; j < n; ++j) {
                const double phi = 2.0 * kPi * (j + 0.5) / n;
                const Vec3f w = normalize(forward * float(cosTheta) + a * float(sinTheta * std::cos(phi)) +
                                          b * float(sinTheta * std::sin(phi)));
                sum += camera.directionDensity(w);
            }
        }
        const double integral = sum * (1.0 - minCos) * 2.0 * kPi / (double(n) * n);
        EXPECT_NEAR(integral, 1.0, 3e-3) << c.name;
    }
}

// Spherical triangle a b c's solid angle (Van Oosterom & Strackee).
double solidAngle(const Vec3f& a, const Vec3f& b, const Vec3f& c) {
    const double num = std::abs(double(dot(a, cross(b, c))));
    const double den = 1.0 + double(dot(a, b)) + double(dot(b, c)) + double(dot(c, a));
    return 2.0 * std::atan2(num, den);
}

// A patch of h x h pixels covers h^2 / (width height) of the image: its solid angle (from
// generateRay's rays at its corners) times the density at its centre is that share.
TEST(CameraImportance, DensityIsTheImageShareOfEachPixelsSolidAngle) {
    const float h = 0.25f;
    for (const Case& c : cameras()) {
        const Camera camera(c.desc, c.width, c.height, c.framing);
        for (auto [x, y] : {std::pair(0.5f, 0.5f), std::pair(0.5f * c.width, 0.5f * c.height),
                            std::pair(c.width - 1.0f, 3.0f), std::pair(7.3f, c.height - 0.5f)}) {
            auto dir = [&](float dx, float dy) { return camera.generateRay(x + dx, y + dy).direction; };
            const Vec3f p00 = dir(-h / 2, -h / 2), p10 = dir(h / 2, -h / 2), p11 = dir(h / 2, h / 2),
                        p01 = dir(-h / 2, h / 2);
            const double omega = solidAngle(p00, p10, p11) + solidAngle(p00, p11, p01);
            const double share = double(h) * h / (double(c.width) * c.height);
            EXPECT_NEAR(camera.directionDensity(dir(0, 0)) * omega / share, 1.0, 2e-3)
                << c.name << " at " << x << ", " << y;
        }
    }
}

// We(w) cos(theta) is the direction density, theta from the view axis (the centre ray without
// aperture offsets).
TEST(CameraImportance, ImportanceTimesTheAxisCosineIsTheDensity) {
    const Case c = cameras().front();
    const Camera camera(c.desc, c.width, c.height, c.framing);
    const Vec3f axis = camera.generateRay(0.5f * c.width, 0.5f * c.height).direction;
    for (auto [x, y] : {std::pair(1.0f, 2.0f), std::pair(30.0f, 40.0f)}) {
        const Vec3f w = camera.generateRay(x, y).direction;
        EXPECT_NEAR(camera.importance(w) * dot(w, axis), camera.directionDensity(w), 1e-5 * camera.directionDensity(w));
    }
}

TEST(CameraImportance, RasterPositionInvertsGenerateRay) {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const Case& c : cameras()) {
        const Camera camera(c.desc, c.width, c.height, c.framing);
        for (int i = 0; i < 200; ++i) {
            const float x = unit(random) * c.width, y = unit(random) * c.height;
            const Ray r = camera.generateRay(x, y);
            const float t = r.tMin + (0.5f + 20.0f * unit(random));
            const std::optional<Vec2f> raster = camera.rasterPosition(rayPoint(r, t));
            ASSERT_TRUE(raster.has_value()) << c.name;
            EXPECT_NEAR(raster->x, x, 2e-3f * c.width) << c.name;
            EXPECT_NEAR(raster->y, y, 2e-3f * c.height) << c.name;
        }
        const Ray centre = camera.generateRay(0.5f * c.width, 0.5f * c.height);
        EXPECT_FALSE(camera.rasterPosition(rayPoint(centre, -5.0f))) << c.name << ": behind the camera";
        EXPECT_FALSE(camera.rasterPosition(rayPoint(centre, 0.5f * centre.tMin)))
            << c.name << ": before the near plane";
        EXPECT_FALSE(camera.rasterPosition(rayPoint(centre, 2.0f * centre.tMax))) << c.name << ": beyond the far plane";
        const Ray beyond = camera.generateRay(-0.5f, -0.5f);  // a ray just outside the image
        EXPECT_TRUE(camera.rasterPosition(rayPoint(camera.generateRay(0.5f, 0.5f), 5.0f))) << c.name;
        EXPECT_FALSE(camera.rasterPosition(rayPoint(beyond, 5.0f))) << c.name << ": outside the image";
        EXPECT_EQ(camera.directionDensity(beyond.direction), 0.0f) << c.name;
        EXPECT_GT(camera.directionDensity(camera.generateRay(0.5f, 0.5f).direction), 0.0f) << c.name;
    }
}

TEST(CameraImportance, ConnectionsPointAtThePinhole) {
    for (const Case& c : cameras()) {
        const Camera camera(c.desc, c.width, c.height, c.framing);
        const Ray r = camera.generateRay(0.3f * c.width, 0.6f * c.height);
        const Vec3f p = rayPoint(r, 7.0f);
        const std::optional<Camera::Connection> k = camera.connect(p);
        ASSERT_TRUE(k.has_value()) << c.name;
        EXPECT_NEAR(k->raster.x, 0.3f * c.width, 1e-2f) << c.name;
        EXPECT_NEAR(k->raster.y, 0.6f * c.height, 1e-2f) << c.name;
        EXPECT_NEAR(length(k->direction + r.direction), 0.0f, 1e-5f) << c.name;
        EXPECT_NEAR(k->distance, 7.0f, 1e-4f) << c.name;
        EXPECT_NEAR(k->nearDistance, r.tMin, 1e-5f) << c.name;  // where camera rays start
        EXPECT_FLOAT_EQ(k->density, camera.directionDensity(r.direction)) << c.name;
        EXPECT_NEAR(k->importance, k->density / 49.0f, 1e-6f * k->density) << c.name;
        EXPECT_FALSE(camera.connect(rayPoint(r, -1.0f))) << c.name;
    }
}

// Through a thin lens (a hexagonal aperture, a scaled transform): from the aperture point a camera
// ray left, the raster position inverts generateRay, the connection ends at the ray's origin along
// it, and the direction density is the image share of a patch of pixels over its solid angle (rays
// from one aperture point); a point on the plane of focus lands at the same pixel from every
// aperture point, one off it does not.
TEST(CameraImportance, ThroughAThinLensFromEachAperturePoint) {
    Case c = cameras().back();
    c.desc.fStop = 1.4f;
    c.desc.focusDistance = 4.0f;
    c.desc.apertureBlades = 6;
    const Camera camera(c.desc, c.width, c.height, c.framing);
    ASSERT_FALSE(camera.lens().isPinhole());
    ASSERT_TRUE(camera.hasImportance());
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 200; ++i) {
        const float x = unit(random) * c.width, y = unit(random) * c.height;
        const Vec2f u{unit(random), unit(random)};
        const Ray r = camera.generateRay(x, y, u);
        const Vec2f a = camera.apertureOf(r.origin);
        const Vec2f sampled = camera.lens().sampleAperture(u);
        EXPECT_NEAR(a.x, sampled.x, 1e-5f);
        EXPECT_NEAR(a.y, sampled.y, 1e-5f);
        const float t = r.tMin + 0.5f + 20.0f * unit(random);
        const std::optional<Camera::Connection> k = camera.connect(rayPoint(r, t), a);
        ASSERT_TRUE(k.has_value());
        EXPECT_NEAR(k->raster.x, x, 2e-3f * c.width);
        EXPECT_NEAR(k->raster.y, y, 2e-3f * c.height);
        EXPECT_NEAR(length(k->lensPoint - r.origin), 0.0f, 1e-5f);
        EXPECT_NEAR(length(k->direction + r.direction), 0.0f, 1e-4f);
        EXPECT_NEAR(k->distance, t, 1e-3f * t);
        EXPECT_NEAR(k->nearDistance, r.tMin, 1e-3f * r.tMin);
        EXPECT_NEAR(k->density, camera.directionDensity(r.direction, a), 1e-3f * k->density);
        EXPECT_NEAR(k->importance, k->density / (k->distance * k->distance), 1e-5f * k->importance);
    }
    const float h = 0.25f;
    for (const Vec2f u : {Vec2f{0.1f, 0.2f}, Vec2f{0.9f, 0.6f}}) {
        const Vec2f a = camera.lens().sampleAperture(u);
        for (auto [x, y] : {std::pair(0.5f * c.width, 0.5f * c.height), std::pair(3.0f, c.height - 2.0f)}) {
            auto dir = [&](float dx, float dy) { return camera.generateRay(x + dx, y + dy, u).direction; };
            const Vec3f p00 = dir(-h / 2, -h / 2), p10 = dir(h / 2, -h / 2), p11 = dir(h / 2, h / 2),
                        p01 = dir(-h / 2, h / 2);
            const double omega = solidAngle(p00, p10, p11) + solidAngle(p00, p11, p01);
            const double share = double(h) * h / (double(c.width) * c.height);
            EXPECT_NEAR(camera.directionDensity(dir(0, 0), a) * omega / share, 1.0, 2e-3) << x << ", " << y;
        }
    }
    // The plane of focus, 4 along the view axis in camera space: the ray's point there, and one
    // twice as far.
    const Ray centre = camera.generateRay(0.3f * c.width, 0.4f * c.height);
    const auto toFocus = float(4.0 / camera.worldToCamera().transformPoint(Vec3d(rayPoint(centre, 1.0f))).z);
    const Vec3f sharp = rayPoint(centre, toFocus), blurred = rayPoint(centre, 2.0f * toFocus);
    const Vec2f left = camera.lens().sampleAperture({0.25f, 0.5f}), right = camera.lens().sampleAperture({0.75f, 0.5f});
    const auto apart = [&](const Vec3f& p) {
        const Vec2f a = *camera.rasterPosition(p, left), b = *camera.rasterPosition(p, right);
        return std::hypot(a.x - b.x, a.y - b.y);
    };
    EXPECT_NEAR(apart(sharp), 0.0f, 1e-2f);
    EXPECT_GT(apart(blurred), 1.0f);
}

TEST(CameraImportance, OrthographicCamerasHaveNone) {
    CameraDesc d;
    d.projection = Projection::Orthographic;
    const Camera camera(d, 16, 16);
    const Ray r = camera.generateRay(8, 8);
    EXPECT_FALSE(camera.hasImportance());
    EXPECT_EQ(camera.directionDensity(r.direction), 0.0f);
    EXPECT_FALSE(camera.rasterPosition(rayPoint(r, 10.0f)));
    EXPECT_FALSE(camera.connect(rayPoint(r, 10.0f)));
}

}  // namespace
}  // namespace fluence::render
