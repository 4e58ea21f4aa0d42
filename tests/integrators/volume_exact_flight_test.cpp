// `path` with exact flights (the "exact-flights" levels, integrators/path_tracer.h, EXACT FLIGHTS)
// against the naive reference (delta tracking and phase sampling alone) and against its own
// delta-tracked flights: in smoke whose extinction differs per channel, with emission, under a
// sky (phase sampling and light sampling of the sky weighted against each other), under a delta
// sun (level 3: exact shadow rays to it), and with a sphere light, where the equiangular strategy
// samples and the flights it is weighted against stay tracked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

// Comparisons in this file, each at z standard errors of the difference of two independent means
// for a family-wide false-failure rate of 1%: 3 levels x (sky, sun, sphere light).
const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(9));

IntegratorSettings exactFlights(int level, int maxDepth = 64) {
    IntegratorSettings s;
    s.maxDepth = maxDepth;
    s.parameters["exact-flights"] = level;
    return s;
}

// sigmaS = 2 d (0.9, 0.6, 0.3) and sigmaT = 2 d (1, 0.8, 0.44) (absorption colour (0, 0.5, 0.8)),
// emitting Le = (0.6, 0.3, 0.1) per unit absorption.
render::SceneDescription chromaticEmittingSmoke(const std::string& file) {
    render::SceneDescription desc = test::smokeUnderAWhiteSky(file, 2.0f, RGB(0.9f, 0.6f, 0.3f));
    desc.volumes[0].params.absorptionColor = RGB(0.0f, 0.5f, 0.8f);
    desc.volumes[0].params.emissionScale = 1.0f;
    desc.volumes[0].params.emissionColor = RGB(0.6f, 0.3f, 0.1f);
    return desc;
}

void expectAgree(const test::MeanEstimate& a, const test::MeanEstimate& b, const char* what, int level) {
    const double se = std::hypot(a.standardError(), b.standardError());
    std::printf("[ measured ] %s, level %d: %.5f +- %.5f against %.5f +- %.5f\n", what, level, a.mean(),
                a.standardError(), b.mean(), b.standardError());
    EXPECT_GT(a.mean(), 0.01) << what;
    EXPECT_NEAR(a.mean(), b.mean(), kZ * se) << what << ", level " << level;
}

TEST(VolumeExactFlight, ChromaticEmittingSmokeUnderASkyAgreesWithTheNaiveReference) {
    test::TempDir dir{"fluence_volume_exact"};
    render::RenderScene scene(chromaticEmittingSmoke(test::writeSmokeCube(dir)));
    ASSERT_TRUE(scene.medium()->hasExactExtinction());
    const Vec3f d = normalize(Vec3f(1.0f, 0.3f, 0.2f));
    const render::Ray ray{Vec3f(1.0f) - d * 5.0f, d};
    const test::MeanEstimate naive = test::radianceAlong(scene, ray, 100000, NaivePathTracer(IntegratorSettings{}));
    for (int level = 1; level <= 3; ++level)
        expectAgree(test::radianceAlong(scene, ray, 20000, PathTracer(exactFlights(level))), naive, "sky", level);
}

// Single scattering of a delta sun (only next-event estimation reaches it): exact flights with
// ray-marched (levels 1, 2) or exact (level 3) shadow rays against delta tracking.
TEST(VolumeExactFlight, ADeltaSunsSingleScatteringAgreesWithDeltaTracking) {
    test::TempDir dir{"fluence_volume_exact"};
    render::SceneDescription desc = chromaticEmittingSmoke(test::writeSmokeCube(dir));
    desc.volumes[0].params.emissionScale = 0.0f;
    const Matrix4 sunTransform = Matrix4::rotateY(35.0) * Matrix4::rotateX(-25.0);
    desc.lights = {test::lightDesc("/Sun", render::LightType::Distant, RGB(3.0f, 2.0f, 1.0f), sunTransform)};
    render::RenderScene scene(desc);
    const Vec3f d = normalize(Vec3f(1.0f, 0.3f, 0.2f));
    const render::Ray ray{Vec3f(1.0f) - d * 5.0f, d};
    const test::MeanEstimate tracked = test::radianceAlong(scene, ray, 40000, PathTracer(exactFlights(0, 1)));
    for (int level = 1; level <= 3; ++level)
        expectAgree(test::radianceAlong(scene, ray, 40000, PathTracer(exactFlights(level, 1))), tracked, "sun", level);
}

// A sphere light inside the smoke: the equiangular strategy samples each stretch, so the flights
// stay tracked where it does; every level must still agree with phase sampling alone.
TEST(VolumeExactFlight, ASphereLightInSmokeAgreesWithTheNaiveReference) {
    test::TempDir dir{"fluence_volume_exact"};
    render::SceneDescription desc = chromaticEmittingSmoke(test::writeSmokeCube(dir));
    desc.lights = {test::sphereLight("/Ball", 0.2f, RGB(6.0f), Vec3d(1.0, 1.2, 0.9))};
    render::RenderScene scene(desc);
    const Vec3f d = normalize(Vec3f(1.0f, 0.15f, -0.1f));
    const render::Ray ray{Vec3f(1.0f) - d * 5.0f, d};
    const test::MeanEstimate naive = test::radianceAlong(scene, ray, 200000, NaivePathTracer(IntegratorSettings{}));
    for (int level = 1; level <= 3; ++level)
        expectAgree(test::radianceAlong(scene, ray, 40000, PathTracer(exactFlights(level))), naive, "sphere light",
                    level);
}

}  // namespace
}  // namespace fluence::integrators
