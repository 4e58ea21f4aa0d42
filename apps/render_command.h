// `fluence render`: USD file -> stage -> scene delegate -> render scene -> integrator -> EXR.
#pragma once

#include "apps/cli_options.h"
#include "apps/scene_loading.h"

namespace fluence::app {

// Runs a render; prints progress, warnings and the summary; returns the exit code.
int runRender(const RenderOptions& options);

}  // namespace fluence::app
