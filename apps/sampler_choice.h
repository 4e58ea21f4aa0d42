// Which sampler (core/random.h) a render draws its camera samples from.
#pragma once

#include <optional>

#include "apps/cli_options.h"
#include "core/random.h"
#include "delegate/render_settings_adapter.h"

namespace fluence::app {

// --sampler, else the render settings' fluence:sampler, else sobol. Throws delegate::SceneError
// naming the settings prim when fluence:sampler names no sampler.
SamplerKind chosenSampler(const RenderOptions& options, const std::optional<delegate::RenderSettingsDesc>& settings);

}  // namespace fluence::app
