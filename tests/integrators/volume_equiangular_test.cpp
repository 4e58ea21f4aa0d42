// The path tracer's equiangular strategy towards local lights in volumes
// (integrators/equiangular_strategy.h), combined with free-flight sampling by the spectral-MIS
// balance heuristic: unbiased with a point light (the light and equiangular strategies alone)
// against quadrature in smoke whose extinction differs per channel, and with sphere and rect
// lights, which phase sampling reaches too, against the naive reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "render/render_scene.h"
#include "tests/integrators/smoke_cube.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace fluence::integrators {
namespace {

// Comparisons in this file, each at z standard errors for a family-wide false-failure rate of 1%:
// 3 channels of the point light, 2 lights against the naive reference.
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(5));

// Smoke whose coefficients differ per channel: sigmaS = d c and sigmaT = d (c + (1 - c)(1 - a)) with
// albedo c and absorption colour a (volumes/grid_medium.h): sigmaS = 2 x (0.95, 0.5, 0.05) and
// sigmaT = 2 x (1, 0.55, 1) per unit, so that free-flight sampling's density of a scattering
// differs by up to 19x between channels.
render::SceneDescription chromaticSmoke(const std::string& file) {
    render::SceneDescription desc = test::smokeUnderAWhiteSky(file, 2.0f, RGB(0.95f, 0.5f, 0.05f));
    desc.volumes[0].params.absorptionColor = RGB(0.0f, 0.9f, 0.0f);
    return desc;
}

// A point light's light scattered once (maxDepth 1) along a ray that passes 0.1 from it, inside
// the smoke: next-event estimation from free flights' scatterings and from equiangular points
// combined. Against
//     L_c = integral T_c(0, t) sigmaS_c(t) / (4 pi) E_c(t) T_c(t -> light) dt,
// E the light's irradiance at x(t) (its own sample()), both transmittances and the integral by
// the midpoint rule on the medium's coefficients. The tolerance is kZ standard errors of the mean
// plus the quadrature's error, estimated as the difference between the rule at steps h and 2h.
// Spectral MIS: the three channels' extinctions differ (by 3x), so weighting either strategy by
// its hero channel's density alone where the other uses the average over channels would make the
// weights not sum to 1 and show as a bias here.
TEST(VolumeEquiangular, APointLightsSingleScatteringMatchesQuadratureInChromaticSmoke) {
    test::TempDir dir{"fluence_volume_equiangular"};
    render::SceneDescription desc = chromaticSmoke(test::writeSmokeCube(dir));
    const Vec3f lightAt(1.0f, 1.1f, 0.95f);
    desc.lights = {test::pointLight("/Bulb", RGB(40.0f), Vec3d(lightAt))};
    render::RenderScene scene(desc);
    const media::Medium& medium = *scene.medium();
    const Vec3f d(1.0f, 0.0f, 0.0f);
    const render::Ray ray{Vec3f(-4.0f, 1.0f, 0.95f), d};  // passes 0.1 below the light

    auto quadrature = [&](int steps) {  // over t in [0, 8]
        Vec3d sum(0.0), tau(0.0);
        const double h = 8.0 / steps;
        for (int i = 0; i < steps; ++i) {
            const Vec3f p = ray.origin + d * float(h * (i + 0.5));
            const media::MediumProperties m = medium.at(p);
            const Vec3d sigmaT(m.sigmaA + m.sigmaS), halfStep = sigmaT * (0.5 * h);
            if (m.sigmaS.x > 0.0f) {
                const render::LightSample ls = *scene.light(0).sample(p, Vec2f(0.5f));
                Vec3d toLight(0.0);
                const int n = steps / 4;
                for (int j = 0; j < n; ++j) {
                    const media::MediumProperties q = medium.at(p + ls.wi * float(ls.distance * (j + 0.5) / n));
                    toLight += Vec3d(q.sigmaA + q.sigmaS) * (double(ls.distance) / n);
                }
                for (int c = 0; c < 3; ++c)
                    sum[c] += std::exp(-(tau[c] + halfStep[c])) * m.sigmaS[c] * ls.Li[c] * std::exp(-toLight[c]) * h /
                              (4.0 * std::numbers::pi);
            }
            tau += sigmaT * h;
        }
        return sum;
    };
    const Vec3d exact = quadrature(4000), coarse = quadrature(2000);
    IntegratorSettings singleScattering;
    singleScattering.maxDepth = 1;
    const PathTracer path(singleScattering);
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate e = test::radianceAlong(scene, ray, 40000, path, false, c);
        const double quadratureError = std::abs(exact[c] - coarse[c]);
        std::printf("[ measured ] channel %d: %.5f +- %.5f, quadrature %.5f (error %.1e)\n", c, e.mean(),
                    e.standardError(), exact[c], quadratureError);
        EXPECT_GT(exact[c], 0.005);
        EXPECT_NEAR(e.mean(), exact[c], kZ * e.standardError() + quadratureError) << "channel " << c;
    }
}

// Sphere and rect lights inside chromatic smoke, every order of scattering: the path tracer's
// three strategies for each light-reaching medium vertex (free flight with light or phase
// sampling, equiangular with light sampling) against phase sampling alone (`naive`). A weight
// that leaves out the equiangular strategy's density where phase sampling reaches a light counts
// that light twice.
TEST(VolumeEquiangular, SphereAndRectLightsInSmokeAgreeWithTheNaiveReference) {
    test::TempDir dir{"fluence_volume_equiangular"};
    const std::string cube = test::writeSmokeCube(dir);
    const render::LightDesc lights[] = {
        test::sphereLight("/Ball", 0.2f, RGB(6.0f), Vec3d(1.0, 1.2, 0.9)),
        test::rectLight("/Panel", 0.5f, 0.4f, RGB(6.0f), Matrix4::translate({1.1, 0.9, 1.2}) * Matrix4::rotateX(30.0)),
    };
    const Vec3f d = normalize(Vec3f(1.0f, 0.15f, -0.1f));
    const render::Ray ray{Vec3f(1.0f, 1.0f, 1.0f) - d * 5.0f, d};
    for (const render::LightDesc& light : lights) {
        render::SceneDescription desc = chromaticSmoke(cube);
        desc.lights = {light};
        render::RenderScene scene(desc);
        const test::MeanEstimate path = test::radianceAlong(scene, ray, 40000);
        const test::MeanEstimate naive = test::radianceAlong(scene, ray, 200000, NaivePathTracer(IntegratorSettings{}));
        const double se = std::hypot(path.standardError(), naive.standardError());
        std::printf("[ measured ] %s: path %.5f +- %.5f, naive %.5f +- %.5f\n", light.name.c_str(), path.mean(),
                    path.standardError(), naive.mean(), naive.standardError());
        EXPECT_GT(path.mean(), 0.01);
        EXPECT_NEAR(path.mean(), naive.mean(), kZ * se) << light.name;
    }
}

}  // namespace
}  // namespace fluence::integrators
