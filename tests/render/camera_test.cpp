#include "render/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace fluence::render {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

CameraDesc cornellCamera() {
    CameraDesc d;
    d.focalLength = 35;
    d.horizontalAperture = 25;
    d.verticalAperture = 25;
    d.nearClip = 10;
    d.farClip = 100000;
    d.transform = Matrix4::translate({278, 273, -800}) * Matrix4::rotateY(180);
    return d;
}

TEST(Camera, CentreRayLooksDownTheCameraAxis) {
    Camera cam(cornellCamera(), 64, 64);
    Ray r = cam.generateRay(32, 32);
    EXPECT_NEAR(r.direction.x, 0.0f, 1e-6f);
    EXPECT_NEAR(r.direction.y, 0.0f, 1e-6f);
    EXPECT_NEAR(r.direction.z, 1.0f, 1e-6f);
    EXPECT_NEAR(r.origin.z, -800.0f, 1e-3f);
    EXPECT_NEAR(r.tMin, 10.0f, 1e-4f);
}

TEST(Camera, FieldOfViewFollowsFocalLengthAndAperture) {
    // Vertical FOV of the Cornell camera: 2 atan(12.5 / 35) = 39.3077 degrees.
    Camera cam(cornellCamera(), 64, 64);
    Ray top = cam.generateRay(32, 0);
    double halfAngle = std::acos(double(top.direction.z)) * kDegrees;
    EXPECT_NEAR(2.0 * halfAngle, 39.3077, 1e-3);
    EXPECT_GT(top.direction.y, 0.0f) << "row 0 is the top of the image";
    // Image right is -X for a camera turned to look along +Z.
    EXPECT_LT(cam.generateRay(64, 32).direction.x, 0.0f);
}

TEST(Camera, ExpandApertureKeepsTheFramedRegion) {
    // A wide image of a square aperture widens the horizontal field, keeping the vertical one.
    Camera wide(cornellCamera(), 128, 64);
    double vertical = 2.0 * std::acos(double(wide.generateRay(64, 0).direction.z)) * kDegrees;
    double horizontal = 2.0 * std::acos(double(wide.generateRay(0, 32).direction.z)) * kDegrees;
    EXPECT_NEAR(vertical, 39.3077, 1e-3);
    EXPECT_NEAR(horizontal, 2.0 * std::atan(25.0 / 35.0) * kDegrees, 1e-3);
    // A tall image widens the vertical field instead.
    Camera tall(cornellCamera(), 64, 128);
    EXPECT_NEAR(2.0 * std::acos(double(tall.generateRay(0, 64).direction.z)) * kDegrees, 39.3077, 1e-3);
}

TEST(Camera, ApertureOffsetShiftsTheWindow) {
    CameraDesc d = cornellCamera();
    d.verticalApertureOffset = 12.5;  // half the aperture: the centre ray now points up by atan(12.5/35)
    Camera cam(d, 64, 64);
    Ray centre = cam.generateRay(32, 32);
    EXPECT_NEAR(std::atan2(double(centre.direction.y), double(centre.direction.z)) * kDegrees,
                std::atan(12.5 / 35.0) * kDegrees, 1e-3);
}

TEST(Camera, ClippingPlanesArePerpendicularToTheViewAxis) {
    Camera cam(cornellCamera(), 64, 64);
    Ray corner = cam.generateRay(0, 0);
    float cosView = corner.direction.z;
    EXPECT_NEAR(corner.tMin * cosView, 10.0f, 1e-3f);
    EXPECT_NEAR(corner.tMax * cosView, 100000.0f, 1.0f);
    EXPECT_NEAR(cam.viewDepth(corner.origin + corner.direction * corner.tMin), 10.0f, 1e-3f);
}

TEST(Camera, OrthographicUsesTenthsOfASceneUnit) {
    CameraDesc d;
    d.projection = Projection::Orthographic;
    d.horizontalAperture = 20;  // 2 scene units wide
    d.verticalAperture = 20;
    Camera cam(d, 10, 10);
    Ray left = cam.generateRay(0, 5), right = cam.generateRay(10, 5);
    EXPECT_NEAR(right.origin.x - left.origin.x, 2.0f, 1e-5f);
    EXPECT_EQ(left.direction, Vec3f(0, 0, -1));
}

// worldToNdc takes every point of the ray through film position (x, y) to (x / width, y / height),
// for both projections, with aperture offsets, a non-square pixel aspect ratio and a rotated camera;
// and worldToCamera puts the point ahead of the eye on +z, at its view depth.
TEST(Camera, WorldToNdcAndWorldToCameraFollowTheRays) {
    for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
        CameraDesc d = cornellCamera();
        d.projection = projection;
        d.horizontalApertureOffset = 3;
        d.verticalApertureOffset = -2;
        Camera cam(d, 40, 30, {1.5f, ApertureConform::ExpandAperture});
        const Matrix4 toNdc = cam.worldToNdc(), toCamera = cam.worldToCamera();
        for (auto [x, y] : {std::pair{0.0f, 0.0f}, {40.0f, 30.0f}, {13.5f, 7.25f}, {20.0f, 15.0f}})
            for (float t : {20.0f, 400.0f}) {
                const Ray ray = cam.generateRay(x, y);
                const Vec3d p(ray.origin + ray.direction * t);
                double h[4];
                for (int i = 0; i < 4; ++i)
                    h[i] = toNdc.m[std::size_t(i)][0] * p.x + toNdc.m[std::size_t(i)][1] * p.y +
                           toNdc.m[std::size_t(i)][2] * p.z + toNdc.m[std::size_t(i)][3];
                EXPECT_NEAR(h[0] / h[3], x / 40.0, 1e-4) << int(projection) << " " << x << "," << y << " t " << t;
                EXPECT_NEAR(h[1] / h[3], y / 30.0, 1e-4) << int(projection) << " " << x << "," << y << " t " << t;
                EXPECT_NEAR(toCamera.transformPoint(p).z, cam.viewDepth(Vec3f(p)), 1e-2);
            }
    }
}

// Every aspectRatioConformPolicy, on a square orthographic aperture 2 units wide and a 20x10 image.
TEST(Camera, ConformPoliciesAndPixelAspectRatioFrameTheApertureAsUsdSays) {
    CameraDesc d;
    d.projection = Projection::Orthographic;
    d.horizontalAperture = d.verticalAperture = 20;
    struct Case {
        ImageFraming framing;
        float width, height, pixelAspectRatio;
    };
    const Case cases[] = {
        {{1.0f, ApertureConform::ExpandAperture}, 4, 2, 1},
        {{1.0f, ApertureConform::CropAperture}, 2, 1, 1},
        {{1.0f, ApertureConform::AdjustApertureWidth}, 4, 2, 1},
        {{1.0f, ApertureConform::AdjustApertureHeight}, 2, 1, 1},
        {{1.0f, ApertureConform::AdjustPixelAspectRatio}, 2, 2, 0.5f},
        {{0.5f, ApertureConform::ExpandAperture}, 2, 2, 0.5f},  // 20 half-width pixels: a square image
        {{4.0f, ApertureConform::CropAperture}, 2, 0.25f, 4},
    };
    for (const Case& c : cases) {
        Camera cam(d, 20, 10, c.framing);
        EXPECT_NEAR(cam.generateRay(20, 5).origin.x - cam.generateRay(0, 5).origin.x, c.width, 1e-5f)
            << int(c.framing.conform) << " PAR " << c.framing.pixelAspectRatio;
        EXPECT_NEAR(cam.generateRay(10, 0).origin.y - cam.generateRay(10, 10).origin.y, c.height, 1e-5f)
            << int(c.framing.conform) << " PAR " << c.framing.pixelAspectRatio;
        EXPECT_FLOAT_EQ(cam.pixelAspectRatio(), c.pixelAspectRatio);
    }
    EXPECT_THROW(Camera(d, 20, 10, {0.0f, ApertureConform::ExpandAperture}), std::invalid_argument);
}

TEST(Camera, PixelsPerUnitAndVisibilityForDicing) {
    // cornellCamera: 64 pixels across a 25/35 half-width window at unit distance.
    Camera cam(cornellCamera(), 64, 64);
    const Vec3f eye = cam.position();
    const float pixelsPerUnitAtOne = 64.0f / (2.0f * 12.5f / 35.0f);
    EXPECT_NEAR(cam.pixelsPerUnitAt(eye + Vec3f(0, 0, 10)), pixelsPerUnitAtOne / 10.0f, 1e-3f);
    EXPECT_NEAR(cam.pixelsPerUnitAt(eye + Vec3f(0, 0, -10)), pixelsPerUnitAtOne / 10.0f, 1e-3f)
        << "behind: by distance";
    EXPECT_NEAR(cam.pixelsPerUnitAt(eye), pixelsPerUnitAtOne / 10.0f, 1e-3f) << "clamped at the near plane (10)";
    EXPECT_TRUE(cam.sees(eye + Vec3f(0, 0, 100), 0.0f));
    EXPECT_FALSE(cam.sees(eye + Vec3f(0, 0, -100), 0.5f)) << "behind the camera";
    // 40 units to the side at depth 100 is outside the 12.5/35 * 100 = 35.7 half-width ...
    EXPECT_FALSE(cam.sees(eye + Vec3f(40, 0, 100), 0.0f));
    // ... and inside once the image grows by 10% on each side (42.9).
    EXPECT_TRUE(cam.sees(eye + Vec3f(40, 0, 100), 0.1f));
}

TEST(Camera, RejectsDegenerateSettings) {
    CameraDesc d = cornellCamera();
    d.focalLength = 0;
    EXPECT_THROW(Camera(d, 8, 8), std::invalid_argument);
    EXPECT_THROW(Camera(cornellCamera(), 0, 8), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::render
