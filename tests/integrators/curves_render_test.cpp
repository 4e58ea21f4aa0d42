// Curves rendered end to end (render/curve_geometry.h): a straight curve crossing an orthographic
// frame covers exactly its projected band, width x the frame's length, in every style and basis;
// and white hair in a white furnace (the hair BSDF with no absorption, under a dome of radiance 1)
// shows radiance 1 wherever it is, through every bounce in and out of its fibres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

// Four statistical checks per test family, Sidak-corrected to a 1% family rate.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(8));

// Looks down -Z at the origin, 4 x 4 scene units (orthographic apertures are in tenths of a unit).
render::CameraDesc orthographicTopView() {
    render::CameraDesc c;
    c.projection = render::Projection::Orthographic;
    c.horizontalAperture = c.verticalAperture = 40.0f;
    c.nearClip = 0.01f;
    c.transform = Matrix4::translate({0, 0, 10});
    return c;
}

// A straight curve along x from -10 to 10 (well past the frame), of radius r, control points
// spaced as its basis wants them.
render::CurvesDesc straightCurve(render::CurveBasis basis, render::CurveStyle style, float r) {
    render::CurvesDesc c;
    c.name = "/curve";
    c.basis = basis;
    c.style = style;
    const int points = basis == render::CurveBasis::Linear ? 2 : 4;
    for (int i = 0; i < points; ++i) {
        c.points.emplace_back(-10.0f + 20.0f * i / (points - 1), 0.3f, 0.0f);
        c.radii.push_back(r);
        if (style == render::CurveStyle::Oriented) c.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
    c.segments.push_back(0);
    return c;
}

TEST(CurvesRender, AStraightCurveCoversItsProjectedBand) {
    struct Case {
        const char* name;
        render::CurveBasis basis;
        render::CurveStyle style;
    };
    const Case cases[] = {{"round linear", render::CurveBasis::Linear, render::CurveStyle::Round},
                          {"round bezier", render::CurveBasis::Bezier, render::CurveStyle::Round},
                          {"flat catmull-rom", render::CurveBasis::CatmullRom, render::CurveStyle::Flat},
                          {"oriented linear", render::CurveBasis::Linear, render::CurveStyle::Oriented}};
    constexpr float kRadius = 0.07f;
    constexpr int kSize = 128, kSpp = 16;
    for (const Case& c : cases) {
        render::SceneDescription s;
        s.curves.push_back(straightCurve(c.basis, c.style, kRadius));
        s.lights.push_back(test::domeLight("/dome", RGB(1.0f)));
        s.lights.back().visibleToCamera = false;
        s.camera = orthographicTopView();
        const Image image = test_support::renderWith(PathTracer(IntegratorSettings{}), s, kSize, kSpp).image;
        const int a = image.channelIndex("A");
        // The covered fraction of the frame, and its standard error: each pixel's alpha is a mean of
        // kSpp coverage samples, of variance at most alpha (1 - alpha) / kSpp.
        double covered = 0.0, variance = 0.0;
        for (std::size_t p = 0; p < image.pixels.size(); p += image.channels.size()) {
            const double alpha = image.pixels[p + std::size_t(a)];
            covered += alpha;
            variance += alpha * (1.0 - alpha) / kSpp;
        }
        const double pixels = double(kSize) * kSize;
        const double fraction = covered / pixels, error = std::sqrt(variance) / pixels;
        const double expected = 2.0 * kRadius * 4.0 / 16.0;  // the band 2r x 4 in the 4 x 4 frame
        std::printf("[ measured ] %s: covers %.5f of the frame +- %.5f (band: %.5f)\n", c.name, fraction, error,
                    expected);
        EXPECT_NEAR(fraction, expected, kZ * error + 1e-4) << c.name;
    }
}

TEST(CurvesRender, WhiteHairInAWhiteFurnaceShowsTheFurnace) {
    // A tuft of white curves (no absorption) in a dome of radiance 1: the hair BSDF scatters all
    // the light it receives, so every pixel that sees hair reads 1 within its noise.
    render::SceneDescription s;
    render::MaterialDesc white;
    white.name = "/white";
    white.diffuse = RGB(1.0f);
    white.roughness = 0.4f;
    s.materials.push_back(white);
    for (int i = 0; i < 40; ++i) {
        render::CurvesDesc c = straightCurve(render::CurveBasis::BSpline, render::CurveStyle::Round, 0.06f);
        for (std::size_t k = 0; k < c.points.size(); ++k) {
            const float t = float(k) / 3.0f;
            c.points[k] =
                Vec3f(-1.5f + 3.0f * t, 0.08f * float(i % 8) - 0.3f + 0.2f * t * t, 0.06f * float(i / 8) - 0.1f * t);
        }
        c.material = 0;
        s.curves.push_back(c);
    }
    s.lights.push_back(test::domeLight("/dome", RGB(1.0f)));
    s.camera = orthographicTopView();
    const Image image = test_support::renderWith(PathTracer(IntegratorSettings{}), s, 64, 64).image;
    const int a = image.channelIndex("A");
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate hair =
            test_support::channelMean(image, c, [&](const float* px) { return px[a] == 1.0f; });
        std::printf("[ measured ] channel %d: hair pixels %.5f +- %.5f over %d pixels (expected 1)\n", c, hair.mean(),
                    hair.standardError(), hair.count());
        ASSERT_GT(hair.count(), 100);
        EXPECT_NEAR(hair.mean(), 1.0, kZ * hair.standardError() + 1e-4) << "channel " << c;
    }
}

}  // namespace
}  // namespace fluence::integrators
