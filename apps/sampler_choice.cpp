#include "apps/sampler_choice.h"

#include <string>

#include "core/sampler_names.h"
#include "delegate/prim_reader.h"

namespace fluence::app {

SamplerKind chosenSampler(const RenderOptions& options, const std::optional<delegate::RenderSettingsDesc>& settings) {
    if (options.sampler) return *options.sampler;
    if (!settings || settings->sampler.empty()) return SamplerKind::Sobol;
    if (const std::optional<SamplerKind> kind = samplerNamed(settings->sampler)) return *kind;
    throw delegate::SceneError("render settings " + settings->path + ": fluence:sampler '" + settings->sampler +
                               "' is not a sampler (available: " + std::string(kSamplerNames) + ")");
}

}  // namespace fluence::app
