// Depth of field against the thin lens's geometry. A small sphere light (radius rho, at distance
// d on the view axis) seen by a camera focused at F < d through an aperture of radius R is blurred
// into the aperture's shape scaled by (d - F) / d on the plane of focus: on the image (the window
// at unit distance) a shape of circumradius c = R (d - F) / (d F), convolved with the light's own
// disk (radius tan(asin(rho / d))) and the pixel's box filter. The light's radiance is 1, so a
// pixel's value is the fraction of its rays that hit the light, and the image's moments follow
// from the shapes': the second moment about the centre of a convolution is the sum of the parts'
// (a disk of radius r: r^2 / 2; a regular n-gon of circumradius c: c^2 (2 + cos(2 pi / n)) / 6;
// the box filter: 1/12 per axis). The brightness inside the blur is the light's area spread over
// the blur's, which gives the aperture's area. Tolerances are derived from the number of hits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSize = 64, kSpp = 1024;
constexpr double kDistance = 10.0, kFocus = 5.0, kLightRadius = 0.3;

render::SceneDescription defocusedLight(int blades, float rotation) {
    render::SceneDescription s;
    s.lights.push_back(test::sphereLight("/bulb", float(kLightRadius), RGB(1.0f)));
    s.camera = test::lookAtOriginCamera(float(kDistance));
    s.camera->fStop = 2.0f;
    s.camera->focusDistance = float(kFocus);
    s.camera->apertureBlades = blades;
    s.camera->apertureRotation = rotation;
    return s;
}

struct Moments {
    double sum = 0.0;     // sum of pixel values: the light's image area, in pixels
    double second = 0.0;  // mean squared distance from the image's centre, in pixels^2
    double centre = 0.0;  // the mean value of the pixels within `inner` of the centre
};

Moments moments(const Image& image, double inner) {
    Moments m;
    double weighted = 0.0, centreSum = 0.0;
    int centrePixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = image.pixel(x, y)[0];
            const double dx = x + 0.5 - 0.5 * kSize, dy = y + 0.5 - 0.5 * kSize, r2 = dx * dx + dy * dy;
            m.sum += v;
            weighted += v * r2;
            if (r2 < inner * inner) {
                centreSum += v;
                ++centrePixels;
            }
        }
    m.second = weighted / m.sum;
    m.centre = centreSum / centrePixels;
    return m;
}

struct Expected {
    double pixelsPerUnit;  // pixels per unit of the window at unit distance
    double blur;           // the blur's circumradius c, in pixels
    double light;          // the light's own image radius, in pixels
};

Expected expected(const render::SceneDescription& s) {
    const render::CameraDesc& c = *s.camera;
    const double pixelsPerUnit = kSize / (c.horizontalAperture / c.focalLength);
    const double aperture = 0.1 * c.focalLength / (2.0 * c.fStop);  // focal length in tenths of a scene unit
    const double blur = aperture * (kDistance - kFocus) / (kDistance * kFocus) * pixelsPerUnit;
    const double light = std::tan(std::asin(kLightRadius / kDistance)) * pixelsPerUnit;
    return {pixelsPerUnit, blur, light};
}

Image render(const render::SceneDescription& s) {
    PathTracer path(IntegratorSettings{});
    return test_support::renderWith(path, s, kSize, kSpp, 0, 7).image;
}

TEST(DepthOfField, DefocusedLightMakesTheCircleOfConfusion) {
    const render::SceneDescription s = defocusedLight(0, 0.0f);
    const Expected e = expected(s);
    ASSERT_GT(e.blur, 3.0 * e.light) << "the blur must dominate the light's own size";
    const Moments m = moments(render(s), 0.5 * e.blur);
    const double box = 2.0 / 12.0;
    const double diameter = 2.0 * std::sqrt(2.0 * (m.second - box) - e.light * e.light);
    // A hit's squared radius over a disk of radius c: mean c^2/2, sd c^2/sqrt(12); m.sum * spp hits.
    const double hits = m.sum * kSpp;
    const double sdSecond = e.blur * e.blur / std::sqrt(12.0) / std::sqrt(hits);
    const double sdDiameter = 2.0 * sdSecond / diameter * 2.0;  // d(2 sqrt(2 s)) / ds = 2 / diameter * 2
    EXPECT_NEAR(diameter, 2.0 * e.blur, 5.0 * sdDiameter + 0.01 * e.blur) << "hits " << hits;
    // Far out of focus the light is a disk: its brightness is its area spread over the blur's.
    const double area = kPi * e.blur * e.blur;
    EXPECT_NEAR(m.sum / m.centre, area, 0.08 * area);
    // Focused on the light, it is only its own disk.
    render::SceneDescription focused = s;
    focused.camera->focusDistance = float(kDistance);
    const Moments f = moments(render(focused), 0.5 * e.light);
    EXPECT_NEAR(f.second, e.light * e.light / 2.0 + box, 0.1 * e.light * e.light);
}

TEST(DepthOfField, BladesMakeARegularPolygon) {
    for (int blades : {5, 6}) {
        const render::SceneDescription s = defocusedLight(blades, 90.0f);
        const Expected e = expected(s);
        const double n = blades, c = e.blur;
        const double inradius = c * std::cos(kPi / n);
        const Moments m = moments(render(s), 0.5 * inradius);
        const double polygon = c * c * (2.0 + std::cos(2.0 * kPi / n)) / 6.0;
        const double second = m.second - 2.0 / 12.0 - e.light * e.light / 2.0;
        const double sd = c * c / std::sqrt(12.0) / std::sqrt(m.sum * kSpp);
        EXPECT_NEAR(second, polygon, 5.0 * sd + 0.01 * polygon) << blades << " blades";
        EXPECT_GT(std::abs(second - c * c / 2.0), 10.0 * sd) << "a polygon, not the round aperture";
        const double area = 0.5 * n * c * c * std::sin(2.0 * kPi / n);
        EXPECT_NEAR(m.sum / m.centre, area, 0.08 * area) << blades << " blades";
    }
}

TEST(DepthOfField, ImagesAreTheSameOnAnyThreadCount) {
    const render::SceneDescription s = defocusedLight(6, 15.0f);
    PathTracer path(IntegratorSettings{});
    const Image one = test_support::renderWith(path, s, 32, 4, 1, 3).image;
    const Image many = test_support::renderWith(path, s, 32, 4, 0, 3).image;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(one.pixel(x, y)[0], many.pixel(x, y)[0]) << x << "," << y;
}

}  // namespace
}  // namespace fluence::integrators
