// Lights with an IES profile (UsdLux inputs:shaping:ies:*): the irradiance around a point light
// is the file's candela towards the point over d^2 times the light's intensity, with the profile's
// nadir along the light's -Z; emission directions are drawn by the density they claim (chi-square);
// normalize makes the emitted power independent of the profile's scale.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling.h"
#include "render/lights/point_light.h"
#include "tests/render/ies_test_table.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

// A point light (a SphereLight treatAsPoint) of intensity 2 x pi x 0.25^2, turned so that its
// local axes are not the world's, with the test table as its IES profile.
LightDesc profiledPoint(float tableScale, bool normalize, std::optional<float> coneDegrees = std::nullopt) {
    LightDesc d;
    d.name = "/Downlight";
    d.type = LightType::Sphere;
    d.treatAsPoint = true;
    d.radius = 0.25f;
    d.radiance = RGB(2.0f);
    d.transform = Matrix4::translate({0.5, 3.0, -1.0}) * Matrix4::rotateY(25) * Matrix4::rotateX(-70);
    LightShapingDesc s;
    s.coneAngleDegrees = coneDegrees.value_or(180.0f);
    s.coneSoftness = coneDegrees ? 0.3f : 0.0f;
    s.ies = std::make_shared<texture::IesTable>(test::quadrantTable(tableScale));
    s.iesNormalize = normalize;
    d.shaping = s;
    return d;
}

TEST(LightIes, PointLightIrradianceIsTheTablesCandelaOverDistanceSquared) {
    LightDesc d = profiledPoint(1.0f, false);
    PointLight light(d);
    const double intensity = 2.0 * M_PI * 0.25 * 0.25;
    Vec3d centre = d.transform.transformPoint({0, 0, 0});
    Vec3d x = d.transform.transformVector({1, 0, 0}), y = d.transform.transformVector({0, 1, 0}),
          z = d.transform.transformVector({0, 0, 1});
    texture::IesTable table = test::quadrantTable();
    int checked = 0;
    for (double a : {-2.0, -0.7, 0.3, 1.9})
        for (double b : {-1.5, 0.2, 2.5})
            for (double c : {-3.0, -0.4, 1.1}) {
                Vec3d p = centre + Vec3d(a, b, c);
                Vec3d e = normalize(p - centre);  // the direction light leaves in
                // UsdLux: theta from the light's -Z; phi of the reversed direction about Z from +X.
                double theta = std::acos(std::clamp(-dot(e, z), -1.0, 1.0));
                double phi = std::atan2(-dot(e, y), -dot(e, x));
                double expected = intensity * test::tableCandela(table, theta * 180.0 / M_PI, phi * 180.0 / M_PI) /
                                  lengthSquared(p - centre);
                auto s = light.sample(Vec3f(p), Vec2f{0.5f, 0.5f});
                ASSERT_TRUE(s);
                EXPECT_NEAR(s->Li.y, expected, 2e-4 * expected) << a << " " << b << " " << c;
                ++checked;
            }
    EXPECT_EQ(checked, 36);
}

TEST(LightIes, EmissionDirectionsFollowTheirDensity) {
    for (std::optional<float> cone : {std::optional<float>(), std::optional<float>(60.0f)}) {
        PointLight light(profiledPoint(1.0f, false, cone));
        SceneBounds bounds;
        auto r = test::chi2SphereTest(
            [&](Vec2f u) -> std::optional<Vec3f> {
                auto e = light.sampleEmission(Vec2f{0.5f, 0.5f}, u, bounds);
                return e ? std::optional(e->direction) : std::nullopt;
            },
            [&](const Vec3f& w) { return double(light.emissionDensity(Vec3f(0.0f), w, bounds).direction); });
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    }
}

// The power a point light emits: its intensity towards each direction (sample() from a point at
// distance 1 returns it as irradiance) integrated over the sphere by the midpoint rule.
double emittedPower(const PointLight& light, const Vec3f& centre) {
    const int n = 300;
    double power = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            float theta = (i + 0.5f) * kPi / n, phi = (j + 0.5f) * kPi / n;
            Vec3f w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            auto s = light.sample(centre + w, Vec2f{0.5f, 0.5f});
            power += s->Li.y * std::sin(theta) * (M_PI / n) * (M_PI / n);
        }
    return power;
}

TEST(LightIes, NormalizeMakesThePowerIndependentOfTheProfilesScale) {
    Vec3f centre(profiledPoint(1.0f, false).transform.transformPoint({0, 0, 0}));
    const double intensity = 2.0 * M_PI * 0.25 * 0.25;
    double one = emittedPower(PointLight(profiledPoint(1.0f, true)), centre);
    double seven = emittedPower(PointLight(profiledPoint(7.0f, true)), centre);
    // Normalized, the profile's mean over the sphere is 1: the light emits 4 pi I, as unshaped.
    EXPECT_NEAR(one, 4.0 * M_PI * intensity, 2e-3 * one);
    EXPECT_NEAR(seven, one, 1e-4 * one);
    double raw = emittedPower(PointLight(profiledPoint(1.0f, false)), centre);
    double rawSeven = emittedPower(PointLight(profiledPoint(7.0f, false)), centre);
    EXPECT_NEAR(rawSeven / raw, 7.0, 1e-4) << "without normalize the candela scale the light";
}

}  // namespace
}  // namespace fluence::render
