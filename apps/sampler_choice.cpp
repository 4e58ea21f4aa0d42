#include "apps/sampler_choice.h"

#include <string>
#include <string_view>

#include "core/enum_names.h"
#include "core/sampler_names.h"
#include "delegate/prim_reader.h"

namespace fluence::app {
namespace {

// `option` if given, else the value the render settings' token `token` (the attribute `attribute`)
// names in `table`, else `fallback`; a token that names nothing is a SceneError naming the settings
// prim and `what` the attribute should have named.
template <class E, std::size_t N>
E chosenByOptionOrSetting(const std::optional<E>& option, const std::optional<delegate::RenderSettingsDesc>& settings,
                          std::string delegate::RenderSettingsDesc::*token, std::string_view attribute,
                          const std::array<EnumName<E>, N>& table, std::string_view what, std::string_view names,
                          E fallback) {
    if (option) return *option;
    if (!settings || ((*settings).*token).empty()) return fallback;
    const std::string& value = (*settings).*token;
    if (const std::optional<E> named = valueNamed(table, value)) return *named;
    throw delegate::SceneError("render settings " + settings->path + ": " + std::string(attribute) + " '" + value +
                               "' is not a " + std::string(what) + " (available: " + std::string(names) + ")");
}

}  // namespace

SamplerKind chosenSampler(const RenderOptions& options, const std::optional<delegate::RenderSettingsDesc>& settings) {
    return chosenByOptionOrSetting(options.sampler, settings, &delegate::RenderSettingsDesc::sampler, "fluence:sampler",
                                   kSamplerTable, "sampler", kSamplerNames, SamplerKind::Sobol);
}

render::DomeLightSampling chosenDomeLightSampling(const RenderOptions& options,
                                                  const std::optional<delegate::RenderSettingsDesc>& settings) {
    return chosenByOptionOrSetting(options.domeSampling, settings, &delegate::RenderSettingsDesc::domeLightSampling,
                                   "fluence:domeLightSampling", render::kDomeLightSamplingTable, "dome light sampling",
                                   render::kDomeLightSamplingNames, render::DomeLightSampling::Auto);
}

}  // namespace fluence::app
