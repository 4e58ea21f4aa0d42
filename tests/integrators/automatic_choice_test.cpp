// `--integrator auto` (integrators/automatic_choice.h): the cheapest method that covers the scene's
// path classes, and the least-missing one when none covers them all.
#include "integrators/automatic_choice.h"

#include <gtest/gtest.h>

namespace fluence::integrators {
namespace {

std::string chosen(unsigned classes) { return chooseIntegrator(classes).integrator->name; }

TEST(AutomaticChoice, TakesTheCheapestMethodThatCoversTheScene) {
    EXPECT_EQ(chosen(kEmitterSeen | kDirect), "direct") << "a lit flat floor";
    EXPECT_EQ(chosen(kEmitterSeen | kDirect | kSpecularSeen | kDeltaLights), "whitted") << "a mirror over a floor";
    EXPECT_EQ(chosen(kEmitterSeen | kDirect | kIndirect), "path") << "a Cornell box";
    EXPECT_EQ(chosen(kEmitterSeen | kDirect | kIndirect | kVolumes | kSubsurface), "path");
    EXPECT_EQ(chosen(kDirect | kSpecularSeen | kIndirect | kCaustics | kDeltaLights | kDeltaLightCaustics), "sppm")
        << "a point light's caustic through glass";
    const AutomaticChoice choice = chooseIntegrator(kDirect | kIndirect);
    EXPECT_NE(choice.reason.find("cheapest"), std::string::npos) << choice.reason;
}

TEST(AutomaticChoice, CausticsFromDeltaLightsInAVolumeTakeSppm) {
    // path misses the point light's caustic; sppm covers it and the volume.
    const AutomaticChoice choice = chooseIntegrator(kDirect | kIndirect | kDeltaLightCaustics | kVolumes);
    EXPECT_EQ(choice.integrator->name, "sppm");
    EXPECT_NE(choice.reason.find("caustics from delta lights"), std::string::npos) << choice.reason;
}

TEST(AutomaticChoice, SppmCoversEveryPathClassSoThereIsAlwaysAChoice) {
    EXPECT_EQ(findIntegrator("sppm")->covers & kAllPathClasses, kAllPathClasses);
}

}  // namespace
}  // namespace fluence::integrators
