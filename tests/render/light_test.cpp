#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"
#include "render/lights/distant_light.h"
#include "render/lights/dome_light.h"
#include "render/lights/rect_light.h"
#include "render/lights/sphere_light.h"
#include "render/lights/triangle_light.h"
#include "tests/render/light_test_support.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

using test::directionsOf;
using test::hitRect;

constexpr double kPiD = 3.14159265358979323846;

TEST(RectLight, SamplingMatchesPdf) {
    RectLight light(test::tiltedRectDesc());
    Vec3f p(0.1f, 0.0f, 0.2f);
    auto r = test::chi2SphereTest(directionsOf(light, p), [&](const Vec3f& wi) {
        auto h = hitRect(light, p, wi);
        return h ? double(light.pdf(p, wi, *h)) : 0.0;
    });
    EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
}

TEST(RectLight, EmitsFromItsFrontOnlyAndNormalizeDividesByArea) {
    RectLight light(test::tiltedRectDesc());
    EXPECT_NEAR(light.area(), 2.0f, 1e-5f);
    LightHit h{Vec3f(0.3f, 2.0f, -0.2f), Vec3f(0, -1, 0)};
    EXPECT_EQ(light.emitted(h, Vec3f(0, -1, 0)), RGB(3.0f));
    EXPECT_EQ(light.emitted(h, Vec3f(0, 1, 0)), RGB(0.0f));
    EXPECT_FALSE(light.sample(Vec3f(0, 3, 0), Vec2f{0.5f, 0.5f})) << "no light reaches the back side";
    LightDesc d = test::tiltedRectDesc();
    d.normalize = true;
    d.transform = d.transform * Matrix4::scale({2, 2, 1});  // world area 8
    RectLight normalized(d);
    EXPECT_NEAR(normalized.area(), 8.0f, 1e-4f);
    EXPECT_NEAR(normalized.emitted(h, Vec3f(0, -1, 0)).x, 3.0f / 8.0f, 1e-6f);
}

TEST(SphereLight, SamplingMatchesPdf) {
    LightDesc d;
    d.type = LightType::Sphere;
    d.radius = 0.5f;
    d.transform = Matrix4::translate({1, 2, 3});
    SphereLight light(d);
    for (const Vec3f& p : {Vec3f(0, 0, 0), Vec3f(1.2f, 2.0f, 3.9f)}) {
        auto r = test::chi2SphereTest(directionsOf(light, p), [&](const Vec3f& wi) {
            // Inside the subtended cone the density is uniform; outside it is zero.
            Vec3f toCentre = light.centre() - p;
            float d2 = lengthSquared(toCentre);
            float cosMax = std::sqrt(std::max(0.0f, 1.0f - light.radius() * light.radius() / d2));
            return dot(wi, normalize(toCentre)) >= cosMax ? double(light.pdf(p, wi, LightHit{})) : 0.0;
        });
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    }
}

TEST(SphereLight, IrradianceMatchesTheClosedForm) {
    // A sphere of radiance L and radius r at distance d gives irradiance E = pi L (r/d)^2 on a
    // surface facing it (any d > r). Estimate it from light samples; tolerance = 5 standard errors.
    LightDesc desc;
    desc.type = LightType::Sphere;
    desc.radius = 0.75f;
    desc.radiance = RGB(2.0f);
    desc.transform = Matrix4::translate({0, 0, 3});
    SphereLight light(desc);
    constexpr int kN = 200000;
    test::MeanEstimate irradiance;
    for (int n = 0; n < kN; ++n) {
        auto s = light.sample(Vec3f(0, 0, 0), SampleStream(11, 0, n).next2D());
        ASSERT_TRUE(s);
        irradiance.add(double(s->Li.x) * std::max(0.0f, s->wi.z) / s->pdf);
    }
    double expected = kPiD * 2.0 * (0.75 * 0.75) / (3.0 * 3.0);
    EXPECT_NEAR(irradiance.mean(), expected, 5 * irradiance.standardError() + 1e-12);
}

TEST(SphereLight, SampledPointsLieOnTheSphere) {
    LightDesc desc;
    desc.type = LightType::Sphere;
    desc.radius = 1.0f;
    desc.transform = Matrix4::translate({0, 5, 0});
    SphereLight light(desc);
    for (int n = 0; n < 1000; ++n) {
        auto s = light.sample(Vec3f(0.2f, 0, 0.1f), SampleStream(3, 1, n).next2D());
        ASSERT_TRUE(s);
        Vec3f q = Vec3f(0.2f, 0, 0.1f) + s->wi * s->distance;
        EXPECT_NEAR(length(q - light.centre()), 1.0f, 1e-4f);
    }
}

TEST(DistantLight, DeltaLightDeliversItsValueAsIrradiance) {
    LightDesc d;
    d.type = LightType::Distant;
    d.angleDegrees = 0.0f;
    d.radiance = RGB(4.0f);
    d.transform = Matrix4::rotateX(-30);  // emits along rotated -Z
    DistantLight light(d);
    auto s = light.sample(Vec3f(0, 0, 0), Vec2f{0.3f, 0.7f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
    EXPECT_EQ(s->Li, RGB(4.0f));
    EXPECT_NEAR(dot(s->wi, Vec3f(Matrix4::rotateX(-30).transformVector({0, 0, 1}))), 1.0f, 1e-6f);
    EXPECT_EQ(light.escaped(s->wi), RGB(0.0f)) << "a delta light cannot be hit";
}

TEST(DistantLight, DiskSamplingMatchesPdfAndNormalizeGivesIrradiance) {
    LightDesc d;
    d.type = LightType::Distant;
    d.angleDegrees = 30.0f;
    d.radiance = RGB(1.0f);
    d.normalize = true;
    DistantLight light(d);
    auto r = test::chi2SphereTest(directionsOf(light, Vec3f(0, 0, 0)),
                                  [&](const Vec3f& wi) { return double(light.pdf(Vec3f(0, 0, 0), wi, LightHit{})); });
    EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    // Normalized: the irradiance on a surface facing the light is the authored value, 1.
    constexpr int kN = 100000;
    double sum = 0;
    for (int n = 0; n < kN; ++n) {
        auto s = light.sample(Vec3f(0, 0, 0), SampleStream(4, 0, n).next2D());
        sum += double(s->Li.x) * s->wi.z / s->pdf;
    }
    // Each sample's value lies in [cos 15deg, 1] x E/(pi sin^2 15deg) x omega; sd < 0.02.
    EXPECT_NEAR(sum / kN, 1.0, 5 * 0.02 / std::sqrt(double(kN)));
}

TEST(DomeLight, UniformSphereSampling) {
    LightDesc d;
    d.type = LightType::Dome;
    d.radiance = RGB(0.5f);
    DomeLight light(d);
    auto r = test::chi2SphereTest(directionsOf(light, Vec3f(0, 0, 0)),
                                  [&](const Vec3f& wi) { return double(light.pdf(Vec3f(), wi, LightHit{})); });
    EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    EXPECT_EQ(light.escaped(Vec3f(0, 1, 0)), RGB(0.5f));
}

TEST(TriangleLight, SamplingMatchesPdfFromEitherSide) {
    Vec3f a(-1, 1, -1), b(1, 1, -1), c(0, 1.5f, 1);
    TriangleLight light("/tri", a, b, c, RGB(1.0f));
    for (const Vec3f& p : {Vec3f(0, 0, 0), Vec3f(0, 3, 0)}) {
        auto r = test::chi2SphereTest(directionsOf(light, p), [&](const Vec3f& wi) {
            // Moller-Trumbore intersection for the pdf callback.
            Vec3f e1 = b - a, e2 = c - a, pv = cross(wi, e2);
            float det = dot(e1, pv);
            if (std::abs(det) < 1e-9f) return 0.0;
            Vec3f tv = p - a;
            float u = dot(tv, pv) / det;
            Vec3f qv = cross(tv, e1);
            float v = dot(wi, qv) / det, t = dot(e2, qv) / det;
            if (u < 0 || v < 0 || u + v > 1 || t <= 0) return 0.0;
            return double(light.pdf(p, wi, LightHit{p + wi * t, normalize(cross(e1, e2))}));
        });
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
    }
}

// A mesh light's triangle (EmittingSides::Front) emits from the side cross(b - a, c - a) points
// to: sampled as the two-sided triangle in front, nothing behind, half the power, and emission
// directions on its front with density cos / pi.
TEST(TriangleLight, AFrontOnlyTriangleEmitsFromItsFrontAlone) {
    Vec3f a(-1, 1, -1), b(1, 1, -1), c(0, 1, 1);  // front: cross(b - a, c - a) along -Y
    TriangleLight both("/tri", a, b, c, RGB(1.0f)), front("/tri", a, b, c, RGB(1.0f), EmittingSides::Front);
    const Vec3f below(0.1f, 0, 0.2f), above(0.1f, 2, 0.2f);
    for (int i = 0; i < 64; ++i) {
        const Vec2f u = SampleStream(3, 0, std::uint64_t(i)).next2D();
        auto s = front.sample(below, u), t = both.sample(below, u);
        ASSERT_TRUE(s && t);
        EXPECT_EQ(s->wi, t->wi);
        EXPECT_EQ(s->pdf, t->pdf);
        EXPECT_EQ(s->Li, RGB(1.0f));
        EXPECT_FALSE(front.sample(above, u));
        const LightHit hit{s->wi * s->distance + below, Vec3f(0, -1, 0)};
        EXPECT_NEAR(front.pdf(below, s->wi, hit), s->pdf, 1e-4f * s->pdf);  // the hit point rounded
        EXPECT_EQ(front.pdf(above, -s->wi, hit), 0.0f);
        EXPECT_EQ(front.emitted(hit, -s->wi), RGB(1.0f));
        EXPECT_EQ(front.emitted(hit, s->wi), RGB(0.0f));
        auto e = front.sampleEmission(u, SampleStream(3, 1, std::uint64_t(i)).next2D(), {});
        ASSERT_TRUE(e);
        EXPECT_LT(e->direction.y, 0.0f);
        const float cosine = -e->direction.y;
        EXPECT_NEAR(e->density.direction, cosine / float(kPiD), 1e-5f);
        EXPECT_EQ(front.emissionDensity(e->point, e->direction, {}).direction, e->density.direction);
        EXPECT_EQ(front.emissionDensity(e->point, -e->direction, {}).direction, 0.0f);
    }
    EXPECT_FLOAT_EQ(front.power({}), 0.5f * both.power({}));
    EXPECT_FALSE(front.bounds()->twoSided);
    EXPECT_EQ(front.bounds()->axis, Vec3f(0, -1, 0));
}

}  // namespace
}  // namespace fluence::render
