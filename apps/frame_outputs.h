// Rendering a frame, step 2 (apps/render_command.cpp runs the steps): the files it writes and the
// pixels it renders.
#pragma once

#include <string>
#include <vector>

#include "apps/cli_options.h"
#include "apps/render_products.h"
#include "apps/warning_log.h"

namespace fluence::app {

struct FrameOutputs {
    std::vector<std::string> files;  // each planned product's, frame tokens expanded, tile suffix added
    std::string preview;             // --preview's, "" for none
    PixelWindow window;              // the pixels rendered: the tile's part of the products' data windows
};

// The outputs of `planned` at time code `time`, their folders made with --make-output-path.
// Returns the exit code: kExitOk with an empty window when the tile holds no pixel of the data
// window (warned: nothing to render), else the error printed.
int planFrameOutputs(const RenderOptions& opt, double time, const PlannedRender& planned, WarningLog& warnings,
                     FrameOutputs& outputs);

}  // namespace fluence::app
