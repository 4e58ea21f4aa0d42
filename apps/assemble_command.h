// `fluence assemble -o OUT.exr TILE.exr...`: merges tiles rendered with --tile-count/--tile-index
// into the whole image (output/tile_assembly.h). Exit codes: 4 when a tile cannot be read, 3 when
// the tiles do not make one image (a tile missing, overlapping or from another image), 5 when the
// output cannot be written; nothing is left at OUT.exr on failure.
#pragma once

#include "apps/cli_options.h"

namespace fluence::app {

int runAssemble(const AssembleOptions& options);

}  // namespace fluence::app
