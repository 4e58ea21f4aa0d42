// The dome light with a lat-long texture: importance sampling against its pdf, agreement with
// the constant dome, the OpenEXR lat-long orientation, the light's transform, and what
// importance sampling buys.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <cmath>

#include "core/sampling.h"
#include "render/lights/dome_light.h"
#include "tests/render/light_test_support.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

using test::image;

constexpr double kPiD = 3.14159265358979323846;

LightDesc domeDesc(std::shared_ptr<RgbImage> texture, const Matrix4& transform = Matrix4::identity()) {
    LightDesc d;
    d.name = "/dome";
    d.type = LightType::Dome;
    d.radiance = RGB(0.7f);
    d.texture = std::move(texture);
    d.transform = transform;
    return d;
}

// A sky with a bright, smooth patch (about 40 times the rest).
std::shared_ptr<RgbImage> patchySky() {
    return image(64, 32, [](int x, int y) {
        float d2 = float((x - 40) * (x - 40) + (y - 10) * (y - 10));
        return RGB(0.1f + 4.0f * std::exp(-d2 / 30.0f), 0.1f + 2.0f * std::exp(-d2 / 30.0f), 0.1f);
    });
}

TEST(DomeLight, ImportanceSamplingMatchesPdf) {
    DomeLight light(domeDesc(patchySky(), Matrix4::rotateY(30) * Matrix4::rotateX(10)));
    Vec3f p(0, 0, 0);
    auto r = test::chi2SphereTest(test::directionsOf(light, p),
                                  [&](const Vec3f& wi) { return double(light.pdf(p, wi, LightHit{})); });
    EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    for (int n = 0; n < 2000; ++n) {
        auto s = light.sample(p, SampleStream(3, 0, n).next2D());
        ASSERT_TRUE(s);
        EXPECT_NEAR(light.pdf(p, s->wi, LightHit{}), s->pdf, 1e-3f * s->pdf) << "sample " << n;
        EXPECT_EQ(light.escaped(s->wi), s->Li) << "sample " << n;
    }
}

TEST(DomeLight, ConstantTextureGivesTheConstantDome) {
    DomeLight constant(domeDesc(nullptr));
    DomeLight textured(domeDesc(image(32, 16, [](int, int) { return RGB(1.0f); })));
    Vec3f n = normalize(Vec3f(0.3f, 0.8f, -0.2f));
    for (const Light* light : {static_cast<const Light*>(&constant), static_cast<const Light*>(&textured)}) {
        test::MeanEstimate e = test::irradianceEstimate(*light, Vec3f(0, 0, 0), n, 200000);
        EXPECT_NEAR(e.mean(), kPiD * 0.7, 5.0 * e.standardError()) << light->name();
        EXPECT_EQ(light->escaped(n), RGB(0.7f));
    }
    EXPECT_NEAR(textured.power({Vec3f(0.0f), 2.0f}), constant.power({Vec3f(0.0f), 2.0f}),
                1e-3f * constant.power({Vec3f(0.0f), 2.0f}));
}

TEST(DomeLight, NonFiniteAndNegativeTexelsWeighNothing) {
    // One infinite and one negative texel in a grey sky: the dome still builds, samples only
    // the grey texels, and has the grey sky's power.
    DomeLight grey(domeDesc(image(32, 16, [](int, int) { return RGB(0.5f); })));
    DomeLight broken(domeDesc(image(32, 16, [](int x, int y) {
        if (x == 10 && y == 5) return RGB(std::numeric_limits<float>::infinity());
        if (x == 20 && y == 8) return RGB(-3.0f);
        return RGB(0.5f);
    })));
    const SceneBounds bounds{Vec3f(0.0f), 2.0f};
    EXPECT_TRUE(std::isfinite(broken.power(bounds)));
    EXPECT_NEAR(broken.power(bounds), grey.power(bounds), 0.01f * grey.power(bounds));
    for (int i = 0; i < 1000; ++i) {
        SampleStream rng(5, 0, std::uint64_t(i));
        std::optional<LightSample> s = broken.sample(Vec3f(0.0f), rng.next2D());
        ASSERT_TRUE(s);
        EXPECT_TRUE(std::isfinite(s->Li.x) && s->Li.x >= 0.0f);
    }
}

// OpenEXR (and UsdLux): top row latitude +pi/2 = +Y; left column longitude +pi; longitude 0 is
// +Z and longitude +pi/2 is +X.
TEST(DomeLight, LatLongOrientationFollowsOpenExr) {
    DomeLight light(domeDesc(image(8, 4, [](int, int) { return RGB(1.0f); })));
    auto near = [](Vec2f a, Vec2f b) { return std::abs(a.x - b.x) < 1e-5f && std::abs(a.y - b.y) < 1e-5f; };
    EXPECT_TRUE(near(light.imageCoordinates(Vec3f(0, 0, 1)), {0.5f, 0.5f}));
    EXPECT_TRUE(near(light.imageCoordinates(Vec3f(1, 0, 0)), {0.25f, 0.5f}));
    EXPECT_TRUE(near(light.imageCoordinates(Vec3f(-1, 0, 0)), {0.75f, 0.5f}));
    EXPECT_NEAR(light.imageCoordinates(Vec3f(0, 1, 0)).y, 0.0f, 1e-6f);
    EXPECT_NEAR(light.imageCoordinates(Vec3f(0, -1, 0)).y, 1.0f, 1e-6f);

    // One bright texel, column 2 of 8 and row 1 of 4: longitude pi - 2 pi [2/8, 3/8] = [pi/4, pi/2],
    // polar angle from +Y pi [1/4, 2/4]. Every sample lands there, computed here from the direction.
    DomeLight spot(domeDesc(image(8, 4, [](int x, int y) { return RGB(x == 2 && y == 1 ? 5.0f : 0.0f); })));
    for (int n = 0; n < 1000; ++n) {
        auto s = spot.sample(Vec3f(0, 0, 0), SampleStream(8, 0, n).next2D());
        ASSERT_TRUE(s);
        double longitude = std::atan2(s->wi.x, s->wi.z), polar = std::acos(s->wi.y);
        EXPECT_GE(longitude, kPiD / 4 - 1e-5);
        EXPECT_LE(longitude, kPiD / 2 + 1e-5);
        EXPECT_GE(polar, kPiD / 4 - 1e-5);
        EXPECT_LE(polar, kPiD / 2 + 1e-5);
        EXPECT_EQ(s->Li, RGB(3.5f));
    }
    EXPECT_EQ(spot.escaped(normalize(Vec3f(1.0f, 0.4f, 0.3f))), RGB(3.5f));  // longitude 73 deg, polar 69 deg
    EXPECT_EQ(spot.escaped(Vec3f(0, 0, 1)), RGB(0.0f));
}

TEST(DomeLight, TransformTurnsTheDome) {
    // The middle column (longitude 0, the dome's +Z) is bright; turned 90 degrees about Y it faces +X.
    DomeLight light(domeDesc(image(8, 4, [](int x, int) { return RGB(x == 4 ? 1.0f : 0.0f); }), Matrix4::rotateY(90)));
    EXPECT_EQ(light.escaped(normalize(Vec3f(1.0f, 0.1f, 0.05f))), RGB(0.7f));
    EXPECT_EQ(light.escaped(Vec3f(0, 0, 1)), RGB(0.0f));
    EXPECT_NEAR(dot(light.direction({0.5f + 1.0f / 16, 0.5f}), Vec3f(1, 0, 0)), std::cos(kPiD / 8), 1e-5);
}

// A small sun 10,000 times brighter than the sky: the irradiance of a surface facing up,
// estimated with the dome's sampler and with uniform directions.
TEST(DomeLight, ImportanceSamplingLowersTheVariance) {
    DomeLight light(
        domeDesc(image(128, 64, [](int x, int y) { return RGB(x / 2 == 20 && y / 2 == 10 ? 1e4f : 1.0f); })));
    Vec3f n(0, 1, 0);
    test::MeanEstimate importance = test::irradianceEstimate(light, Vec3f(0, 0, 0), n, 100000), uniform;
    for (int i = 0; i < 100000; ++i) {
        Vec3f wi = sampleUniformSphere(SampleStream(11, 0, i).next2D());
        uniform.add(double(light.escaped(wi).x) * std::max(0.0f, dot(n, wi)) / kUniformSpherePdf);
    }
    EXPECT_NEAR(importance.mean(), uniform.mean(),
                5.0 * std::hypot(importance.standardError(), uniform.standardError()));
    EXPECT_LT(importance.standardError() * 10.0, uniform.standardError());
}

}  // namespace
}  // namespace fluence::render
