// After a frame is written: its summary on stdout (what was rendered, the scene's size, the time
// of each step, rays and samples, the method's own note) and its entry in the run's --summary.
#pragma once

#include <cstddef>
#include <string>

#include "apps/cli_options.h"
#include "apps/frame_build.h"
#include "apps/frame_outputs.h"
#include "apps/frame_render.h"
#include "apps/run_summary.h"
#include "apps/warning_log.h"

namespace fluence::app {

// "1 light", "3 lights" (`plural`: when not singular + "s").
std::string counted(std::size_t n, const std::string& singular, const std::string& plural = "");

// The seconds each step took (the parse's is the shared stage load's, 0 after the first frame).
struct FrameTimes {
    double parse = 0.0, build = 0.0, write = 0.0, total = 0.0;
};

void printFrameSummary(const RenderOptions& opt, const std::pair<int, int>& res, const BuiltFrame& built,
                       const RenderedFrame& frame, const FrameOutputs& outputs, const FrameTimes& times,
                       const WarningLog& warnings);

FrameSummary frameSummary(double time, const std::pair<int, int>& res, const BuiltFrame& built,
                          const RenderedFrame& frame, const FrameOutputs& outputs, const FrameTimes& times);

}  // namespace fluence::app
