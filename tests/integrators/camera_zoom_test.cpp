// A camera whose lens changes during the shutter (CameraDesc::motionLenses, render/camera_motion.h):
// its focal length, fStop and focus distance at a time are the steps' linear interpolation, and
// camera rays leave the lens of their own time. A zoom smears a small sphere light off the view
// axis radially, as the thin-lens geometry says: at time t the light's image is the ellipse the
// sphere projects to, centred k(t) (tan(theta - a) + tan(theta + a)) / 2 from the image's centre,
// semi-axes k(t) (tan(theta + a) - tan(theta - a)) / 2 radially and k(t) tan(a) / cos(theta) across
// (theta the light's angle off the axis, a its angular radius, k(t) = pixels per unit of the
// window at unit distance, proportional to the focal length). The image's light (the sum of its
// pixels: the light's radiance is 1), its radial centroid and its radial and tangential second
// moments are these ellipses' averaged over the shutter, weighted by their areas, plus the pixel's
// box (1/12 per axis). Tolerances are derived from the number of hits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrators/path_tracer.h"
#include "render/camera.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kSize = 64, kSpp = 256;
constexpr double kDepth = 10.0, kOffset = 1.8, kRadius = 0.3;  // the light, seen 10.3 degrees off the axis
constexpr float kWide = 35.0f, kLong = 70.0f, kAperture = 36.0f;

render::CameraDesc zoomingCamera() {
    render::CameraDesc c;
    c.horizontalAperture = c.verticalAperture = kAperture;
    c.nearClip = 0.01f;
    c.transform = Matrix4::translate({0.0, 0.0, kDepth});  // looking down -Z at the origin
    c.focalLength = 0.5f * (kWide + kLong);
    c.motionLenses = {{kWide, 0.0f, 0.0f}, {kLong, 0.0f, 0.0f}};
    return c;
}

struct Measured {
    double sum = 0.0, centre = 0.0, radial = 0.0, across = 0.0;
};

Measured measure(const Image& image) {
    double sum = 0.0, x1 = 0.0, x2 = 0.0, y1 = 0.0, y2 = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = image.pixel(x, y)[0], dx = x + 0.5 - 0.5 * kSize, dy = y + 0.5 - 0.5 * kSize;
            sum += v;
            x1 += v * dx;
            x2 += v * dx * dx;
            y1 += v * dy;
            y2 += v * dy * dy;
        }
    const double cx = x1 / sum, cy = y1 / sum;
    return {sum, cx, x2 / sum - cx * cx, y2 / sum - cy * cy};
}

Measured expected() {
    const double theta = std::atan(kOffset / kDepth);
    const double a = std::asin(kRadius / std::hypot(kOffset, kDepth));
    const double near = std::tan(theta - a), far = std::tan(theta + a), across = std::tan(a) / std::cos(theta);
    const int n = 4000;
    double area = 0.0, x1 = 0.0, x2 = 0.0, y2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n, focal = kWide + (kLong - kWide) * t;
        const double k = kSize * focal / kAperture;
        const double centre = 0.5 * k * (near + far), rr = 0.5 * k * (far - near), rt = k * across;
        const double w = kPi * rr * rt;
        area += w;
        x1 += w * centre;
        x2 += w * (centre * centre + rr * rr / 4.0);
        y2 += w * rt * rt / 4.0;
    }
    const double centre = x1 / area;
    return {area / n, centre, x2 / area - centre * centre + 1.0 / 12.0, y2 / area + 1.0 / 12.0};
}

TEST(CameraZoom, AZoomDuringTheShutterSmearsALightRadially) {
    render::SceneDescription s;
    s.lights.push_back(test::sphereLight("/bulb", float(kRadius), RGB(1.0f), {kOffset, 0.0, 0.0}));
    s.camera = zoomingCamera();
    const Image image = test_support::renderWith(PathTracer(IntegratorSettings{}), s, kSize, kSpp, 0, 5).image;
    const Measured m = measure(image), e = expected();
    const double hits = m.sum * kSpp;
    std::printf(
        "[ measured ] light %.3f (expected %.3f), centre %.3f (%.3f), radial %.3f (%.3f), across %.3f (%.3f), "
        "%.0f hits\n",
        m.sum, e.sum, m.centre, e.centre, m.radial, e.radial, m.across, e.across, hits);
    // Binomial hits; a second moment's estimate has at most a normal distribution's spread, sqrt(2 / hits).
    EXPECT_NEAR(m.sum, e.sum, 5.0 * std::sqrt(hits) / kSpp + 0.005 * e.sum);
    EXPECT_NEAR(m.centre, e.centre, 5.0 * std::sqrt(e.radial / hits) + 0.01);
    EXPECT_NEAR(m.radial, e.radial, 5.0 * e.radial * std::sqrt(2.0 / hits) + 0.005 * e.radial);
    EXPECT_NEAR(m.across, e.across, 5.0 * e.across * std::sqrt(2.0 / hits) + 0.005 * e.across);
    EXPECT_GT(m.radial, 4.0 * m.across) << "smeared along the radius, not across it";
}

TEST(CameraZoom, TheLensAtATimeInterpolatesItsSteps) {
    render::CameraDesc desc = zoomingCamera();
    desc.motionLenses = {{30.0f, 2.0f, 2.0f}, {70.0f, 4.0f, 6.0f}};
    const render::Camera camera(desc, kSize, kSize);
    const render::Camera half = camera.at(0.5f);
    EXPECT_FALSE(half.moves());
    EXPECT_NEAR(half.lens().focusDistance, 4.0f, 1e-6f);
    EXPECT_NEAR(half.lens().radius, 0.1f * 50.0f / (2.0f * 3.0f), 1e-6f);
    // Its rays are those of the still camera with that lens.
    render::CameraDesc still = desc;
    still.motionLenses.clear();
    still.focalLength = 50.0f;
    still.fStop = 3.0f;
    still.focusDistance = 4.0f;
    const render::Ray a = camera.generateRay(3.0f, 60.0f, {0.2f, 0.7f}, 0.5f);
    const render::Ray b = render::Camera(still, kSize, kSize).generateRay(3.0f, 60.0f, {0.2f, 0.7f});
    EXPECT_NEAR(length(a.origin - b.origin), 0.0f, 1e-6f);
    EXPECT_NEAR(length(a.direction - b.direction), 0.0f, 1e-6f);
    desc.motionLenses.front().focalLength = 0.0f;
    EXPECT_THROW(render::Camera(desc, kSize, kSize), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::integrators
