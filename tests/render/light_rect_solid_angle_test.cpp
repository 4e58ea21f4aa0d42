// Solid angle sampling of rect lights (render/lights/spherical_rectangle.h, RectLight::sample): the
// solid angle against the closed form, directions against pdf() by chi-square from points near the
// rect, at grazing angles, off its axis and far away (area sampling there), on a sheared rect
// (area sampling: a parallelogram), the density integrating to 1 over the sphere, and which of the
// two samplers a point gets.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"
#include "render/lights/rect_light.h"
#include "render/lights/spherical_rectangle.h"
#include "tests/render/light_test_support.h"
#include "tests/support/chi2.h"

namespace fluence::render {
namespace {

// The solid angle of [x0, x1] x [y0, y1] at height z > 0, as the sum over its corners of
// +-atan(x y / (z |(x, y, z)|)) (the solid angle of the rectangle from the foot of the
// perpendicular to a corner), in long double.
double closedFormSolidAngle(double x0, double x1, double y0, double y1, double z) {
    auto corner = [z](long double x, long double y) {
        return std::atan(x * y / (z * std::sqrt(x * x + y * y + (long double)(z)*z)));
    };
    return double(corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0));
}

// The solid angle is a sum of two angles each good to a few ulps of double (1.1e-16) of its size
// (at most pi), so its absolute error is about 1e-15 at most; the relative bound covers the
// long double reference's own rounding and the float-free inputs' conversions.
constexpr double kSolidAngleError = 1e-15, kSolidAngleTolerance = 1e-12;

TEST(SphericalRectangle, SolidAngleMatchesTheClosedFormNearFarAndGrazing) {
    // The rectangle [x0, x0 + w] x [y0, y0 + h] in the plane z = 0, seen from (0, 0, z).
    struct View {
        double x0, y0, w, h, z;
    };
    for (const View& v : {View{-1.0, -0.5, 2.0, 1.0, 1e-3},    // just above its middle: nearly 2 pi
                          View{-1.0, -0.5, 2.0, 1.0, 1.0},     // near
                          View{0.5, 0.2, 2.0, 1.0, 1e-2},      // beside it, grazing
                          View{1000.0, 3.0, 1.0, 0.5, 1.0},    // far off its axis: about 5e-10 sr
                          View{-0.5, -0.5, 1.0, 1.0, 300.0}})  // far along its axis: about 1e-5 sr
    {
        const Vec3d ex(1, 0, 0), ey(0, 1, 0);
        auto r = SphericalRectangle::seenFrom(Vec3d(0, 0, v.z), Vec3d(v.x0, v.y0, 0), ex, ey, v.w, v.h);
        ASSERT_TRUE(r);
        double expected = closedFormSolidAngle(v.x0, v.x0 + v.w, v.y0, v.y0 + v.h, v.z);
        EXPECT_NEAR(r->solidAngle(), expected, kSolidAngleTolerance * expected + kSolidAngleError)
            << "x0 " << v.x0 << " z " << v.z;
        // The same from below the plane (the frame flips z).
        auto below = SphericalRectangle::seenFrom(Vec3d(0, 0, -v.z), Vec3d(v.x0, v.y0, 0), ex, ey, v.w, v.h);
        ASSERT_TRUE(below);
        EXPECT_NEAR(below->solidAngle(), expected, kSolidAngleTolerance * expected + kSolidAngleError);
    }
    EXPECT_FALSE(SphericalRectangle::seenFrom(Vec3d(3, 0, 0), Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0), 1, 1))
        << "a point in the rectangle's plane sees no solid angle";
}

// The tilted 2 x 1 rect of light_test_support.h: its centre, emitting normal and edge directions.
struct RectFrame {
    Vec3f centre, normal, alongU, alongV;
    float halfDiagonal;
};
RectFrame frameOf(const RectLight& light) {
    auto c = light.corners();
    return {(c[0] + c[2]) * 0.5f, -normalize(cross(c[1] - c[0], c[3] - c[0])), normalize(c[1] - c[0]),
            normalize(c[3] - c[0]), 0.5f * length(c[2] - c[0])};
}

// Points in front of the tilted rect: height above its plane, and offsets along its edges.
std::vector<std::pair<const char*, Vec3f>> viewpoints(const RectLight& light) {
    RectFrame f = frameOf(light);
    return {
        {"near its middle", f.centre + f.normal * 0.05f + f.alongU * 0.2f},
        {"beside it, grazing", f.centre + f.normal * 0.03f + f.alongU * 1.6f + f.alongV * 0.3f},
        {"off its axis", f.centre + f.normal * 1.0f + f.alongU * 3.0f},
        {"far away (area sampling)", f.centre + f.normal * (1.5f * RectLight::kAreaSamplingHeight * f.halfDiagonal)}};
}

std::function<double(const Vec3f&)> pdfFrom(const RectLight& light, const Vec3f& p) {
    return test::pdfOf(light, p,
                       [&light](const Vec3f& from, const Vec3f& wi) { return test::hitRect(light, from, wi); });
}

TEST(RectLightSolidAngle, SamplingMatchesPdfFromNearGrazingAndFarPoints) {
    RectLight light(test::tiltedRectDesc());
    for (const auto& [where, p] : viewpoints(light)) {
        auto r = test::chi2SphereTest(test::directionsOf(light, p), pdfFrom(light, p));
        EXPECT_GT(r.pValue, test::kChi2Alpha) << where << "\n" << r.report;
        test::expectSamplesMatchPdf(
            light, p, [&light](const Vec3f& from, const Vec3f& wi) { return test::hitRect(light, from, wi); });
    }
}

TEST(RectLightSolidAngle, PdfIntegratesToOneOverTheSphere) {
    RectLight light(test::tiltedRectDesc());
    for (const auto& [where, p] : viewpoints(light)) {
        test::SphereIntegral integral = test::integrateOverSphere(pdfFrom(light, p), 1e-5);
        EXPECT_NEAR(integral.value, 1.0, 5.0 * integral.error + 1e-3) << where;
    }
}

TEST(RectLightSolidAngle, NearPointsDrawEveryDirectionWithOneDensityFarPointsByArea) {
    RectLight light(test::tiltedRectDesc());
    auto densities = [&light](const Vec3f& p) {
        std::vector<float> pdfs;
        for (int n = 0; n < 64; ++n)
            if (auto s = light.sample(p, SampleStream(5, 0, n).next2D())) pdfs.push_back(s->pdf);
        return pdfs;
    };
    auto points = viewpoints(light);
    for (int i = 0; i < 3; ++i) {
        std::vector<float> pdfs = densities(points[i].second);
        ASSERT_EQ(pdfs.size(), 64u) << points[i].first;
        for (float pdf : pdfs) EXPECT_EQ(pdf, pdfs[0]) << points[i].first;
    }
    std::vector<float> far = densities(points[3].second);
    ASSERT_EQ(far.size(), 64u);
    EXPECT_NE(*std::min_element(far.begin(), far.end()), *std::max_element(far.begin(), far.end()))
        << "area sampling far away: the density varies with the distance and the cosine at the light";
}

TEST(RectLightSolidAngle, AShearedRectIsAParallelogramSampledByArea) {
    LightDesc d = test::tiltedRectDesc();
    Matrix4 shear = Matrix4::identity();
    shear.m[0][1] = 0.6;  // x += 0.6 y: the local Y edge leans along X
    d.transform = d.transform * shear;
    RectLight light(d);
    auto c = light.corners();
    ASSERT_GT(std::abs(dot(normalize(c[1] - c[0]), normalize(c[3] - c[0]))), 0.3f) << "not a rectangle";
    RectFrame f = frameOf(light);
    for (const Vec3f& p : {f.centre + f.normal * 0.1f, f.centre + f.normal * 0.04f + f.alongU * 1.8f}) {
        auto r = test::chi2SphereTest(test::directionsOf(light, p), pdfFrom(light, p));
        EXPECT_GT(r.pValue, test::kChi2Alpha) << r.report;
        test::SphereIntegral integral = test::integrateOverSphere(pdfFrom(light, p), 1e-5);
        EXPECT_NEAR(integral.value, 1.0, 5.0 * integral.error + 1e-3);
    }
}

TEST(RectLightSolidAngle, NothingFromBehindOrInItsPlane) {
    LightDesc d = test::tiltedRectDesc();
    d.transform = Matrix4::translate({0.0, 0.0, 2.0});  // in the plane z = 2 exactly, emitting along -Z
    RectLight light(d);
    // Behind it, in its plane beside it, in its plane within its extent.
    for (const Vec3f& p : {Vec3f(0.2f, 0.1f, 2.1f), Vec3f(2.5f, 0.2f, 2.0f), Vec3f(0.3f, 0.1f, 2.0f)}) {
        for (int n = 0; n < 64; ++n) EXPECT_FALSE(light.sample(p, SampleStream(6, 0, n).next2D()));
        Vec3f centre(0.0f, 0.0f, 2.0f);
        EXPECT_EQ(light.pdf(p, normalize(centre - p), LightHit{centre, Vec3f(0, 0, -1)}), 0.0f);
    }
}

}  // namespace
}  // namespace fluence::render
