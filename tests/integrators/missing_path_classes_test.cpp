// Each integrator's missing path classes, shown by a scene that needs them: where its registry entry
// says it does not cover a class (integrators/path_classes.h) that scenePathClasses() finds in the
// scene, its image is wrong against `path`, which covers it.
//   radiosity, LD*E: a clear coat's mirror reflection is not there (kSpecularSeen).
// (sppm and bdpt cover media now; sppm misses no class. direct, whitted and naive are shown in
// their own tests: direct_whitted_test.cpp, reference_agreement_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrators/path_tracer.h"
#include "integrators/radiosity.h"
#include "integrators/scene_path_classes.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

const double kZ = test::normalQuantile(0.5 * test::sidakAlpha(2));

// The green channel's mean over the pixels that see the sphere of furnaceScene(), from `path` and
// from `other`; `other` must be wrong there: off path's by more than kZ combined standard errors.
void expectMissedLight(const render::SceneDescription& scene, const Integrator& other, const char* name,
                       unsigned missing) {
    ASSERT_TRUE(scenePathClasses(scene) & missing) << "the scene must hold the class " << name << " misses";
    const IntegratorInfo* info = findIntegrator(name);
    ASSERT_NE(info, nullptr);
    EXPECT_FALSE(info->covers & missing) << name << " declares it covers what it misses";
    auto onSphere = [](const test_support::Rendered& r) {
        const int a = r.image.channelIndex("A");
        return test_support::channelMean(r.image, 1, [&](const float* p) { return p[a] == 1.0f; });
    };
    test::MeanEstimate path = onSphere(test_support::renderWith(PathTracer(IntegratorSettings{}), scene, 32, 64));
    test::MeanEstimate lacking = onSphere(test_support::renderWith(other, scene, 32, 16));
    std::printf("[ measured ] %s: %.5f +- %.5f where path reads %.5f +- %.5f\n", name, lacking.mean(),
                lacking.standardError(), path.mean(), path.standardError());
    EXPECT_GT(std::abs(path.mean() - lacking.mean()), kZ * std::hypot(path.standardError(), lacking.standardError()))
        << name;
}

TEST(MissingPathClasses, RadiositySeesNoClearCoatReflection) {
    // A black ball under a smooth clear coat, in a dome of radiance 1: path shows the coat's mirror
    // reflection of the sky (Fresnel, about a tenth of it); radiosity sees only the black base.
    render::SceneDescription scene = test::furnaceScene(0.0f);
    render::MaterialParams& m = scene.materials[0];
    m.coat = 1.0f;
    m.coatRoughness = 0.0f;
    expectMissedLight(scene, Radiosity(), "radiosity", kSpecularSeen);
}

}  // namespace
}  // namespace fluence::integrators
