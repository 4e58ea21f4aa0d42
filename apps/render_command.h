// `fluence render`: USD file -> stage -> scene delegate -> render scene -> integrator -> EXR.
#pragma once

#include "apps/cli_options.h"

namespace fluence::app {

// Exit codes (documented in `fluence --help` and docs/CLI.md).
enum ExitCode : int {
    kExitOk = 0,
    kExitInternal = 1,
    kExitUsage = 2,
    kExitScene = 3,
    kExitMissingInput = 4,
    kExitOutput = 5,
    kExitColorConfig = 6,
};

// Runs a render; prints progress, warnings and the summary; returns the exit code.
int runRender(const RenderOptions& options);

}  // namespace fluence::app
