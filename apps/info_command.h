// `fluence info`: what a scene holds, as Fluence composes it.
#pragma once

#include "apps/cli_options.h"

namespace fluence::app {

// Prints the layers, the composed prim tree with types, the cameras, lights, materials, volumes
// and render settings, the classes of light paths the scene can produce and which of them each
// integrator misses, every asset path with whether it resolves, the malformed prims a render
// leaves out (delegate/render_index.h) and the composition warnings. Returns an exit code (0 when
// the scene composed, whatever the warnings; with InfoOptions::strict, kExitScene when a prim is
// malformed).
int runInfo(const InfoOptions& options);

}  // namespace fluence::app
