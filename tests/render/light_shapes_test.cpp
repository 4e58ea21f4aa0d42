// Disk, cylinder, point and line lights, and rect light textures: sampling against pdf()
// (chi-square and per-sample consistency), exact intersection, emission sides, normalization.
#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling.h"
#include "render/lights/cylinder_light.h"
#include "render/lights/disk_light.h"
#include "render/lights/line_light.h"
#include "render/lights/point_light.h"
#include "render/lights/rect_light.h"
#include "tests/render/light_test_support.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

using test::directionsOf;
using test::expectSamplesMatchPdf;
using test::pdfOf;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

LightDesc diskDesc() {
    LightDesc d;
    d.name = "/disk";
    d.type = LightType::Disk;
    d.radius = 0.7f;
    d.radiance = RGB(2.0f);
    // Emits downwards (-Y) from y = 2, tilted a little.
    d.transform = Matrix4::translate({0.2, 2.0, -0.1}) * Matrix4::rotateZ(15) * Matrix4::rotateX(-90);
    return d;
}

LightDesc cylinderDesc() {
    LightDesc d;
    d.name = "/tube";
    d.type = LightType::Cylinder;
    d.length = 2.0f;
    d.radius = 0.4f;
    d.radiance = RGB(1.5f);
    d.transform = Matrix4::translate({0.5, 1.0, 0.0}) * Matrix4::rotateY(30) * Matrix4::rotateZ(20);
    return d;
}

// pdf() needs where the ray reached the light: the light's own exact intersection.
test::HitFunction hitsOf(const AnalyticLightShape& shape) {
    return [&shape](const Vec3f& p, const Vec3f& wi) -> std::optional<LightHit> {
        auto h = shape.intersect(p, wi, 0.0f, kInfinity);
        return h ? std::optional(LightHit{p + wi * h->t, h->normal}) : std::nullopt;
    };
}

TEST(DiskLight, SamplingMatchesPdf) {
    DiskLight light(diskDesc());
    for (const Vec3f& p : {Vec3f(0, 0, 0), Vec3f(1.5f, 1.2f, 0.3f)}) {
        auto r = test::chi2SphereTest(directionsOf(light, p), pdfOf(light, p, hitsOf(light)));
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
        expectSamplesMatchPdf(light, p, hitsOf(light));
    }
}

TEST(DiskLight, IsHitWithinItsRadiusAndEmitsFromItsFront) {
    LightDesc d;
    d.type = LightType::Disk;
    d.radius = 0.5f;
    d.radiance = RGB(3.0f);
    d.transform = Matrix4::translate({0, 0, 2});  // in the plane z = 2, emitting along -Z
    DiskLight light(d);
    auto hit = light.intersect(Vec3f(0.3f, 0.3f, 0), Vec3f(0, 0, 1), 0.0f, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0f, 1e-6f);
    EXPECT_EQ(hit->normal, Vec3f(0, 0, -1));
    EXPECT_FALSE(light.intersect(Vec3f(0.4f, 0.4f, 0), Vec3f(0, 0, 1), 0.0f, kInfinity)) << "0.57 from the centre";
    EXPECT_FALSE(light.intersect(Vec3f(0, 0, 0), Vec3f(0, 0, 1), 0.0f, 1.9f)) << "beyond tMax";
    LightHit h{Vec3f(0, 0, 2), Vec3f(0, 0, -1)};
    EXPECT_EQ(light.emitted(h, Vec3f(0, 0, -1)), RGB(3.0f));
    EXPECT_EQ(light.emitted(h, Vec3f(0, 0, 1)), RGB(0.0f));
    EXPECT_FALSE(light.sample(Vec3f(0, 0, 3), Vec2f{0.5f, 0.5f})) << "no light reaches the back";
}

TEST(DiskLight, NormalizeDividesByTheWorldArea) {
    LightDesc d = diskDesc();
    d.normalize = true;
    d.transform = d.transform * Matrix4::scale({2, 3, 1});  // an ellipse of area 6 pi r^2: the disk keeps it
    DiskLight light(d);
    float area = 6.0f * kPi * 0.49f;
    EXPECT_NEAR(kPi * light.radius() * light.radius(), area, 1e-4f);
    EXPECT_NEAR(light.emitted({light.centre(), light.normal()}, light.normal()).x, 2.0f / area, 1e-6f);
}

TEST(CylinderLight, SamplingMatchesPdf) {
    CylinderLight light(cylinderDesc());
    // Beside it, past one end (outside the radius), and far off at an angle.
    Vec3f beyondEnd = light.centre() + light.axis() * 1.5f + Vec3f(0.0f, 0.0f, 0.6f);
    for (const Vec3f& p : {Vec3f(0.3f, 0.0f, 0.2f), beyondEnd, Vec3f(3.0f, -2.0f, 1.0f)}) {
        auto r = test::chi2SphereTest(directionsOf(light, p), pdfOf(light, p, hitsOf(light)));
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
        expectSamplesMatchPdf(light, p, hitsOf(light));
    }
}

TEST(CylinderLight, SamplesOnlyTheSideFacingThePoint) {
    CylinderLight light(cylinderDesc());
    Vec3f p(0.3f, 0.0f, 0.2f);
    for (int n = 0; n < 1000; ++n) {
        auto s = light.sample(p, SampleStream(5, 0, n).next2D());
        ASSERT_TRUE(s) << "sample " << n << ": none of the visible arc is wasted";
        auto h = light.intersect(p, s->wi, 0.0f, kInfinity);
        ASSERT_TRUE(h);
        EXPECT_LT(dot(h->normal, s->wi), 0.0f);
    }
    // On the axis past an end cap, only the (dark, open) end is in view.
    Vec3f onAxis = light.centre() + light.axis() * 3.0f;
    EXPECT_FALSE(light.sample(onAxis, Vec2f{0.5f, 0.5f}));
    EXPECT_EQ(light.pdf(onAxis, -light.axis(), LightHit{light.centre(), Vec3f(0, 1, 0)}), 0.0f);
}

TEST(CylinderLight, EmitsOutwardsFromItsSideOnly) {
    LightDesc d;
    d.type = LightType::Cylinder;
    d.length = 2.0f;
    d.radius = 0.5f;
    d.radiance = RGB(4.0f);
    CylinderLight light(d);  // along X through the origin
    auto side = light.intersect(Vec3f(0.3f, 0, 3), Vec3f(0, 0, -1), 0.0f, kInfinity);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->t, 2.5f, 1e-5f);
    EXPECT_NEAR(dot(side->normal, Vec3f(0, 0, 1)), 1.0f, 1e-6f);
    EXPECT_EQ(light.emitted({Vec3f(0.3f, 0, 0.5f), side->normal}, Vec3f(0, 0, 1)), RGB(4.0f));
    EXPECT_FALSE(light.intersect(Vec3f(1.2f, 0, 3), Vec3f(0, 0, -1), 0.0f, kInfinity)) << "past the end";
    // A ray into the open end meets the inside of the far wall, which is dark.
    Vec3f dir = normalize(Vec3f(-1.0f, 0.0f, -0.6f));  // in at x = 1, z = 0; meets z = -0.5 at x = 0.17
    auto inside = light.intersect(Vec3f(1.5f, 0, 0.3f), dir, 0.0f, kInfinity);
    ASSERT_TRUE(inside);
    EXPECT_EQ(light.emitted({Vec3f(1.5f, 0, 0.3f) + dir * inside->t, inside->normal}, -dir), RGB(0.0f));
}

TEST(PointLight, IsADeltaLightAtTheSpheresCentre) {
    LightDesc d;
    d.type = LightType::Sphere;
    d.radius = 0.5f;
    d.radiance = RGB(2.0f);
    d.treatAsPoint = true;
    d.transform = Matrix4::translate({1, 2, 2});
    PointLight light(d);
    auto s = light.sample(Vec3f(0, 0, 0), Vec2f{0.3f, 0.9f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->delta);
    EXPECT_EQ(s->pdf, 1.0f);
    EXPECT_NEAR(s->distance, 3.0f, 1e-6f);
    EXPECT_NEAR(dot(s->wi, Vec3f(1, 2, 2) / 3.0f), 1.0f, 1e-6f);
    EXPECT_EQ(light.pdf(Vec3f(0, 0, 0), s->wi, LightHit{}), 0.0f);
    EXPECT_NEAR(light.intensity().x, 2.0f * kPi * 0.25f, 1e-6f) << "the sphere's power: L pi r^2";
    d.normalize = true;
    EXPECT_NEAR(PointLight(d).intensity().x, 0.5f, 1e-7f) << "normalized: L / 4, whatever the radius";
}

// The line light picks points uniformly in the angle the line subtends: a chi-square test of the
// angles of 200,000 samples over 40 equal bins.
TEST(LineLight, SamplesUniformlyInTheSubtendedAngle) {
    LightDesc d;
    d.type = LightType::Cylinder;
    d.length = 3.0f;
    d.radius = 0.1f;
    d.treatAsLine = true;
    LineLight light(d);  // from x = -1.5 to 1.5
    Vec3f p(-0.4f, 0.8f, 0.0f);
    float phi0 = std::atan2(-1.5f + 0.4f, 0.8f), phi1 = std::atan2(1.5f + 0.4f, 0.8f);
    constexpr int kBins = 40, kN = 200000;
    std::vector<double> counts(kBins, 0.0);
    for (int n = 0; n < kN; ++n) {
        auto s = light.sample(p, SampleStream(9, 0, n).next2D());
        ASSERT_TRUE(s && s->delta);
        Vec3f q = p + s->wi * s->distance;
        EXPECT_NEAR(q.y, 0.0f, 1e-4f) << "on the line";
        float phi = std::atan2(q.x - p.x, 0.8f);
        counts[std::min(kBins - 1, int((phi - phi0) / (phi1 - phi0) * kBins))] += 1.0;
    }
    double chi2 = 0.0, expected = double(kN) / kBins;
    for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_GT(test::upperIncompleteGammaQ(0.5 * (kBins - 1), 0.5 * chi2), test::kChi2Alpha) << "chi2 = " << chi2;
    EXPECT_NEAR(light.linearIntensity().x, 0.2f, 1e-7f) << "2 r L";
}

// A 2x2 texture on a 2x2 rect in the plane z = 0 (identity transform, emitting along -Z).
TEST(RectLight, TextureTopLeftTexelSitsAtLocalPlusXPlusY) {
    auto texture = std::make_shared<RgbImage>();
    texture->width = texture->height = 2;
    texture->texels = {RGB(1, 0, 0), RGB(0, 1, 0), RGB(0, 0, 1), RGB(1, 1, 0)};  // top row: red, green
    LightDesc d;
    d.width = d.height = 2.0f;
    d.radiance = RGB(2.0f);
    d.texture = texture;
    RectLight light(d);
    auto seen = [&](float x, float y) { return light.emitted({Vec3f(x, y, 0), Vec3f(0, 0, -1)}, Vec3f(0, 0, -1)); };
    EXPECT_EQ(seen(0.5f, 0.5f), RGB(2, 0, 0));
    EXPECT_EQ(seen(-0.5f, 0.5f), RGB(0, 2, 0));
    EXPECT_EQ(seen(0.5f, -0.5f), RGB(0, 0, 2));
    EXPECT_EQ(seen(-0.5f, -0.5f), RGB(2, 2, 0));
    // Samples carry the texel they landed on, and the mean texel sets the power.
    for (int n = 0; n < 100; ++n) {
        auto s = light.sample(Vec3f(0, 0, -1), SampleStream(2, 0, n).next2D());
        ASSERT_TRUE(s);
        Vec3f q = Vec3f(0, 0, -1) + s->wi * s->distance;
        EXPECT_EQ(s->Li, seen(q.x, q.y));
    }
    EXPECT_NEAR(light.power({}), luminance(RGB(2.0f) * RGB(0.5f, 0.5f, 0.25f)) * 4.0f * kPi, 1e-4f);
}

}  // namespace
}  // namespace fluence::render
