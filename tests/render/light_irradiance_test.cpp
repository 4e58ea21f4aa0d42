// Irradiance from each light shape, estimated from the light's own samples, against its closed
// form (or, for the cylinder, a fine quadrature over its surface). Tolerances are five standard
// errors of the estimate (plus the reference's own error where it has one).
#include <gtest/gtest.h>

#include <cmath>

#include "render/lights/cylinder_light.h"
#include "render/lights/disk_light.h"
#include "render/lights/line_light.h"
#include "render/lights/point_light.h"
#include "render/lights/rect_light.h"
#include "render/lights/sphere_light.h"
#include "tests/render/light_test_support.h"

namespace fluence::render {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr int kSamples = 200000;

void expectIrradiance(const Light& light, const Vec3f& p, const Vec3f& n, double expected,
                      double referenceError = 0.0) {
    test::MeanEstimate e = test::irradianceEstimate(light, p, n, kSamples);
    EXPECT_NEAR(e.mean(), expected, 5.0 * e.standardError() + referenceError + 1e-12) << "expected " << expected;
}

TEST(LightIrradiance, RectMatchesLambertsPolygonFormula) {
    RectLight light(test::tiltedRectDesc());
    Vec3f p(0.1f, 0.0f, 0.2f), n = normalize(Vec3f(0.2f, 1.0f, -0.1f));
    expectIrradiance(light, p, n, test::polygonIrradiance(light.corners(), p, n, 3.0));
}

// A textured rect is a grid of uniform rects, one per texel, so the sum of Lambert's formula over
// them is its exact irradiance. The window texture's 1500:1 contrast puts most of it in a few
// texels, which the importance sampler must find: under the window and off to its side.
TEST(LightIrradiance, TexturedRectMatchesLambertsFormulaPerTexel) {
    LightDesc d = test::tiltedRectDesc();
    d.texture = test::windowTexture();
    RectLight light(d);
    const render::RgbImage& texture = *d.texture;
    auto c = light.corners();  // c[2] at the texture's top-left, c[3] top-right, c[1] bottom-left
    Vec3f across = (c[3] - c[2]) / float(texture.width), down = (c[1] - c[2]) / float(texture.height);
    for (const auto& [p, n] : {std::pair{Vec3f(-0.2f, 0.0f, 0.0f), Vec3f(0.0f, 1.0f, 0.0f)},
                               std::pair{Vec3f(2.5f, 0.5f, 1.0f), normalize(Vec3f(-1.0f, 1.0f, -0.3f))}}) {
        double expected = 0.0;
        for (int y = 0; y < texture.height; ++y)
            for (int x = 0; x < texture.width; ++x) {
                Vec3f o = c[2] + across * float(x) + down * float(y);
                expected += test::polygonIrradiance({o, o + across, o + across + down, o + down}, p, n,
                                                    3.0 * texture.at(x, y).x);
            }
        expectIrradiance(light, p, n, expected, 1e-5 * expected);
    }
}

TEST(LightIrradiance, DiskOnItsAxisIsPiLr2OverR2PlusD2) {
    LightDesc d;
    d.type = LightType::Disk;
    d.radius = 0.8f;
    d.radiance = RGB(2.5f);
    d.transform = Matrix4::translate({0, 0, 1.5}) * Matrix4::rotateZ(40);  // emits along -Z
    DiskLight light(d);
    expectIrradiance(light, Vec3f(0, 0, 0), Vec3f(0, 0, 1), 2.5 * kPiD * 0.64 / (0.64 + 2.25));
}

TEST(LightIrradiance, PointLightGivesTheSpheresIrradiance) {
    // E = pi L (r/d)^2 facing a sphere of radius r at distance d, and I / d^2 from the point
    // light standing for it: exact with one sample.
    LightDesc d;
    d.type = LightType::Sphere;
    d.radius = 0.3f;
    d.radiance = RGB(2.0f);
    d.transform = Matrix4::translate({0, 0, 3});
    d.treatAsPoint = true;
    auto s = PointLight(d).sample(Vec3f(0, 0, 0), Vec2f{0.5f, 0.5f});
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->Li.x * s->wi.z / s->pdf, kPiD * 2.0 * 0.09 / 9.0, 1e-7);
    d.treatAsPoint = false;
    expectIrradiance(SphereLight(d), Vec3f(0, 0, 0), Vec3f(0, 0, 1), kPiD * 2.0 * 0.09 / 9.0);
}

TEST(LightIrradiance, LineMatchesItsClosedForm) {
    // Linear intensity I = 2 r L towards the line's normal plane. At distance h on the
    // perpendicular bisector of a line of half-length a, facing it:
    // E = I h^2 int ds / (h^2 + s^2)^2 = I (a / (h^2 + a^2) + atan(a / h) / h).
    LightDesc d;
    d.type = LightType::Cylinder;
    d.length = 2.0f;
    d.radius = 0.1f;
    d.radiance = RGB(3.0f);
    d.treatAsLine = true;
    d.transform = Matrix4::translate({0.5, -0.2, 1.0}) * Matrix4::rotateZ(35);
    LineLight light(d);
    Vec3f centre(0.5f, -0.2f, 1.0f), across = normalize(Vec3f(Matrix4::rotateZ(35).transformVector({0, 1, 0})));
    const double h = 0.7, a = 1.0, intensity = 2.0 * 0.1 * 3.0;
    expectIrradiance(light, centre + across * float(h), -across,
                     intensity * (a / (h * h + a * a) + std::atan(a / h) / h));
}

// The cylinder's irradiance by the midpoint rule over its side, 2000 x 1000 points:
// E = int L cos(surface) cos(p) / d^2 dA over the points that face p.
double cylinderIrradiance(const CylinderLight& light, const Vec3f& p, const Vec3f& n, double radiance) {
    Frame frame = Frame::fromNormal(light.axis());
    const int kAround = 2000, kAlong = 1000;
    double sum = 0.0;
    for (int i = 0; i < kAround; ++i) {
        double phi = 2.0 * kPiD * (i + 0.5) / kAround;
        Vec3d normal = Vec3d(frame.s) * std::cos(phi) + Vec3d(frame.t) * std::sin(phi);
        for (int j = 0; j < kAlong; ++j) {
            double along = light.length() * ((j + 0.5) / kAlong - 0.5);
            Vec3d x = Vec3d(light.centre()) + Vec3d(light.axis()) * along + normal * double(light.radius());
            Vec3d toP = Vec3d(p) - x;
            double d2 = dot(toP, toP), d = std::sqrt(d2);
            sum += std::max(0.0, dot(normal, toP) / d) * std::max(0.0, -dot(Vec3d(n), toP) / d) / d2;
        }
    }
    return radiance * sum * (2.0 * kPiD * light.radius() / kAround) * (light.length() / kAlong);
}

TEST(LightIrradiance, CylinderMatchesAQuadratureOverItsSide) {
    LightDesc d;
    d.type = LightType::Cylinder;
    d.length = 1.6f;
    d.radius = 0.35f;
    d.radiance = RGB(2.0f);
    d.transform = Matrix4::translate({0.0, 1.2, 0.3}) * Matrix4::rotateY(25);
    CylinderLight light(d);
    for (const auto& [p, n] : {std::pair{Vec3f(0.2f, 0.0f, 0.0f), normalize(Vec3f(0.1f, 1.0f, 0.2f))},
                               std::pair{Vec3f(1.4f, 1.0f, 0.9f), normalize(Vec3f(-1.0f, 0.3f, -0.2f))}}) {
        double reference = cylinderIrradiance(light, p, n, 2.0);
        expectIrradiance(light, p, n, reference, 1e-4 * reference);
    }
}

}  // namespace
}  // namespace fluence::render
