// Rendering a frame, step 1 (apps/render_command.cpp runs the steps): the stage, through the
// delegate, into the render scene, and the integrator the render uses.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "apps/cli_options.h"
#include "apps/render_products.h"
#include "apps/warning_log.h"
#include "color/color_management.h"
#include "delegate/scene_delegate.h"
#include "integrators/integrator.h"
#include "render/render_scene.h"
#include "scene/stage.h"

namespace fluence::app {

struct BuiltFrame {
    std::optional<delegate::DelegateResult> populated;
    std::unique_ptr<render::RenderScene> scene;
    const integrators::IntegratorInfo* integrator = nullptr;  // --integrator, else fluence:integrator, else path
    std::map<std::string, double> parameters;                 // its parameters (apps/integrator_parameters.h)
    SamplerKind sampler = SamplerKind::Sobol;                 // apps/sampler_choice.h
    double seconds = 0.0;                                     // the build's time
};

// Builds the stage at time code `time` for `planned` (its camera, resolution and framing);
// `primvars`: those the frame's primvar RenderVars read. Warns of a scene without lights and of
// the light paths the integrator misses. Returns the exit code: kExitOk, else the error printed.
int buildFrame(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors, double time,
               const PlannedRender& planned, const std::set<std::string>& primvars, WarningLog& warnings,
               BuiltFrame& built);

}  // namespace fluence::app
