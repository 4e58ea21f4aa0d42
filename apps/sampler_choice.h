// Which sampler (core/random.h) a render draws its camera samples from, and whether its
// next-event estimation samples a constant dome (render/dome_light_sampling.h): each the
// command-line option, else the render settings' token, else the default.
#pragma once

#include <optional>

#include "apps/cli_options.h"
#include "core/random.h"
#include "delegate/render_settings_adapter.h"
#include "render/dome_light_sampling.h"

namespace fluence::app {

// --sampler, else the render settings' fluence:sampler, else sobol. Throws delegate::SceneError
// naming the settings prim when fluence:sampler names no sampler.
SamplerKind chosenSampler(const RenderOptions& options, const std::optional<delegate::RenderSettingsDesc>& settings);

// --dome-sampling, else the render settings' fluence:domeLightSampling, else auto. Throws
// delegate::SceneError naming the settings prim when the attribute names no policy.
render::DomeLightSampling chosenDomeLightSampling(const RenderOptions& options,
                                                  const std::optional<delegate::RenderSettingsDesc>& settings);

}  // namespace fluence::app
