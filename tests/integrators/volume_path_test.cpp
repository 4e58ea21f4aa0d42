// The path tracer through OpenVDB volumes (media/ tracking, volumes/ GridMedium): Beer-Lambert
// through a pure absorber against its closed form, a white furnace of albedo-1 smoke that
// neither loses nor gains light, with next-event estimation and MIS at every scattering event,
// and a delta sun's single scattering against quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "render/render_scene.h"
#include "tests/integrators/smoke_cube.h"
#include "tests/support/scenes.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace fluence::integrators {
namespace {

using test::radianceAlong;
using test::smokeUnderAWhiteSky;
constexpr double kVoxel = test::kSmokeVoxel;

TEST(VolumePath, PureAbsorberTransmitsBeerLambert) {
    test::TempDir dir{"fluence_volume_path"};
    // Optical depth along the centre line: densityScale * 2 units = 1.
    render::RenderScene scene(smokeUnderAWhiteSky(test::writeSmokeCube(dir), 0.5f, RGB(0.0f)));
    ASSERT_TRUE(scene.medium());
    const float centre = 20 * kVoxel;
    test::MeanEstimate e = radianceAlong(scene, render::Ray{{-5.0f, centre, centre}, {1.0f, 0.0f, 0.0f}}, 20000);
    EXPECT_NEAR(e.mean(), std::exp(-1.0), 4.0 * e.standardError() + 1e-4) << e.mean() << " +- " << e.standardError();
    // A camera sample counts as covered where its first event is in the volume: alpha estimates
    // the opacity 1 - T.
    test::MeanEstimate alpha = radianceAlong(scene, render::Ray{{-5.0f, centre, centre}, {1.0f, 0.0f, 0.0f}}, 20000,
                                             PathTracer(IntegratorSettings{}), true);
    EXPECT_NEAR(alpha.mean(), 1.0 - std::exp(-1.0), 4.0 * alpha.standardError());
}

TEST(VolumePath, AlbedoOneSmokeInAWhiteFurnaceVanishes) {
    test::TempDir dir{"fluence_volume_path"};
    render::RenderScene scene(
        smokeUnderAWhiteSky(test::writeSmokeCube(dir), 4.0f, RGB(1.0f)));  // optical depth 8 across
    const float centre = 20 * kVoxel;
    for (const Vec3f& d : {Vec3f(1, 0, 0), normalize(Vec3f(1, 0.4f, -0.3f))}) {
        test::MeanEstimate e = radianceAlong(scene, render::Ray{Vec3f(centre) - d * 5.0f, d}, 4000);
        EXPECT_NEAR(e.mean(), 1.0, 4.0 * e.standardError() + 1e-4) << e.mean() << " +- " << e.standardError();
    }
}

TEST(VolumePath, PathAgreesWithTheNaiveReferenceInChromaticSmoke) {
    // Coloured albedo (each channel scatters and absorbs differently; the extinction itself is
    // grey, so chromatic extinction is left to tests/media/), optical depth 4 across: next-event
    // estimation and MIS must give what phase sampling alone gives.
    test::TempDir dir{"fluence_volume_path"};
    render::RenderScene scene(smokeUnderAWhiteSky(test::writeSmokeCube(dir), 2.0f, RGB(0.9f, 0.6f, 0.3f)));
    const float centre = 20 * kVoxel;
    const Vec3f d = normalize(Vec3f(1, 0.3f, 0.2f));
    const render::Ray ray{Vec3f(centre) - d * 5.0f, d};
    test::MeanEstimate path = radianceAlong(scene, ray, 20000);
    test::MeanEstimate naive = radianceAlong(scene, ray, 20000, NaivePathTracer(IntegratorSettings{}));
    const double se =
        std::sqrt(path.standardError() * path.standardError() + naive.standardError() * naive.standardError());
    EXPECT_NEAR(path.mean(), naive.mean(), 4.0 * se) << path.mean() << " vs " << naive.mean();
}

// A delta sun's light scattered once (maxDepth 1) in chromatic smoke, which only next-event
// estimation at the free flights' scatterings reaches (ray-marched shadow rays), against
//     L_c = integral T_c(0, t) sigmaS_c(t) E_c / (4 pi) T_c(t -> sun) dt,
// both transmittances and the integral by the midpoint rule on the medium's own coefficients.
// The tolerance is 4 standard errors of the mean plus the quadrature's error, estimated as the
// difference between the rule at steps h and 2h.
TEST(VolumePath, ADeltaSunsSingleScatteringMatchesQuadrature) {
    test::TempDir dir{"fluence_volume_path"};
    render::SceneDescription desc = smokeUnderAWhiteSky(test::writeSmokeCube(dir), 1.5f, RGB(0.8f, 0.6f, 0.4f));
    const Matrix4 sunTransform = Matrix4::rotateY(35.0) * Matrix4::rotateX(-25.0);
    desc.lights = {test::lightDesc("/Sun", render::LightType::Distant, RGB(3.0f, 2.0f, 1.0f), sunTransform)};
    render::RenderScene scene(desc);
    const media::Medium& medium = *scene.medium();
    const Vec3f toSun = normalize(Vec3f(sunTransform.transformVector({0.0, 0.0, 1.0})));
    const float centre = 20 * kVoxel;
    const Vec3f d = normalize(Vec3f(1.0f, 0.3f, 0.2f));
    const render::Ray ray{Vec3f(centre) - d * 5.0f, d};

    auto quadrature = [&](int steps) {  // over t in [0, 10], the sun's ray over 4 units
        auto depth = [&](const Vec3f& o, const Vec3f& w, double length, int n) {
            Vec3d tau(0.0);
            for (int i = 0; i < n; ++i) {
                const media::MediumProperties m = medium.at(o + w * float(length * (i + 0.5) / n));
                tau += Vec3d(m.sigmaA + m.sigmaS) * (length / n);
            }
            return tau;
        };
        Vec3d sum(0.0), tau(0.0);
        const double h = 10.0 / steps;
        for (int i = 0; i < steps; ++i) {
            const Vec3f p = ray.origin + d * float(h * (i + 0.5));
            const media::MediumProperties m = medium.at(p);
            const Vec3d sigmaT(m.sigmaA + m.sigmaS);
            const Vec3d halfStep = sigmaT * (0.5 * h);
            if (m.sigmaS.x > 0.0f) {
                const Vec3d sunDepth = depth(p, toSun, 4.0, steps * 2 / 5);
                for (int c = 0; c < 3; ++c)
                    sum[c] += std::exp(-(tau[c] + halfStep[c])) * m.sigmaS[c] * std::exp(-sunDepth[c]) * h;
            }
            tau += sigmaT * h;
        }
        const Vec3d sun(3.0, 2.0, 1.0);
        return (sum.x * sun.x + sum.y * sun.y + sum.z * sun.z) / (3.0 * 4.0 * std::numbers::pi);
    };
    const double exact = quadrature(2000), quadratureError = std::abs(exact - quadrature(1000));
    IntegratorSettings singleScattering;
    singleScattering.maxDepth = 1;
    const test::MeanEstimate e = radianceAlong(scene, ray, 20000, PathTracer(singleScattering));
    std::printf("[ measured ] single scattering %.5f +- %.5f, quadrature %.5f (error %.1e)\n", e.mean(),
                e.standardError(), exact, quadratureError);
    EXPECT_GT(exact, 0.01);
    EXPECT_NEAR(e.mean(), exact, 4.0 * e.standardError() + quadratureError);
}

}  // namespace
}  // namespace fluence::integrators
