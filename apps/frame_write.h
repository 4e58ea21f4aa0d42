// Rendering a frame, step 4 (apps/render_command.cpp runs the steps): every planned product's
// OpenEXR image and the preview, written atomically.
#pragma once

#include "apps/cli_options.h"
#include "apps/frame_outputs.h"
#include "apps/frame_render.h"
#include "apps/render_products.h"
#include "apps/warning_log.h"
#include "color/color_management.h"
#include "render/render_scene.h"

namespace fluence::app {

// Writes the products of `planned` and the preview from `frame`, then lets its pass outputs go
// (checkpoint and snapshot removed). Returns the exit code: kExitOk, else the error printed.
int writeFrame(const RenderOptions& opt, const color::ColorManagement& colors, const PlannedRender& planned,
               const render::RenderScene& scene, const FrameOutputs& outputs, WarningLog& warnings,
               RenderedFrame& frame);

}  // namespace fluence::app
