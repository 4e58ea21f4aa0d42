// Whether next-event estimation samples a dome light of constant radiance (the render setting
// `fluence:domeLightSampling`, the CLI's `--dome-sampling`; SceneDescription::domeLightSampling).
//
// auto    (default) a light whose radiance is the same from every direction (Light::
//         constantRadiance: a DomeLight without texture:file) is never chosen by next-event
//         estimation (RenderScene::chooseLight) and its light-strategy probability is 0
//         (RenderScene::lightProbability), so the BSDF- and phase-sampled rays that leave the scene
//         gather it at MIS weight 1. For a constant sky those samplers are its ideal importance
//         samplers (up to visibility), and the ray is traced anyway; the light samples next-event
//         estimation would have spent on it go to the other lights. A constant dome whose light
//         passes surfaces (shadows off, or shadow-linked away from some geometry:
//         RenderScene::lightPassesSurfaces) is still sampled: only next-event estimation finds
//         that light (render/shadow_rays.cpp). This is Cycles' rule (3.4,
//         scene/light.cpp, LightManager::test_enabled_lights: the background light is disabled,
//         "Background MIS has been disabled", unless the world shader varies over directions or a
//         portal exists).
// always  every light is chosen by next-event estimation, by the light tree's weights.
// The policy changes next-event estimation's choice only: the light's power, and with it the
// emission sampling of light subpaths and photons (bdpt, sppm) and radiosity's own light choice,
// is untouched, so every method still starts light from the dome.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "core/enum_names.h"

namespace fluence::render {

enum class DomeLightSampling { Auto, Always };

inline constexpr std::string_view kDomeLightSamplingNames = "auto or always";

inline constexpr std::array<EnumName<DomeLightSampling>, 2> kDomeLightSamplingTable{
    {{DomeLightSampling::Auto, "auto"}, {DomeLightSampling::Always, "always"}}};

constexpr std::string_view domeLightSamplingName(DomeLightSampling policy) {
    return nameIn(kDomeLightSamplingTable, policy);
}

// The policy called `name`, nullopt for none.
constexpr std::optional<DomeLightSampling> domeLightSamplingNamed(std::string_view name) {
    return valueNamed(kDomeLightSamplingTable, name);
}

}  // namespace fluence::render
