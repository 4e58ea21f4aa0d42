// Rendering a frame, step 3 (apps/render_command.cpp runs the steps): the camera, the integrator
// and the film, checkpoints and snapshots at pass boundaries, and the render itself.
#pragma once

#include <memory>
#include <vector>

#include "apps/cli_options.h"
#include "apps/cryptomatte_layers.h"
#include "apps/frame_build.h"
#include "apps/frame_outputs.h"
#include "apps/pass_outputs.h"
#include "apps/render_products.h"
#include "apps/warning_log.h"
#include "color/color_management.h"
#include "core/film.h"
#include "integrators/renderer.h"
#include "output/exr_writer.h"
#include "render/camera.h"
#include "scene/stage.h"

namespace fluence::app {

// What the render made, for the write step. Not copied nor moved: the pass outputs' snapshot
// writer reads `header` where it is.
struct RenderedFrame {
    std::unique_ptr<render::Camera> camera;
    std::unique_ptr<integrators::Integrator> integrator;
    integrators::RenderSettings settings;
    std::unique_ptr<Film> film;
    std::vector<CryptomatteLayerRequest> cryptomatteRequests;
    std::unique_ptr<CryptomatteFilm> cryptomatte;  // null without Cryptomatte layers
    output::ExrHeader header;                      // the outputs' EXR header, but for what the render's end adds
    std::unique_ptr<PassOutputs> passOutputs;
    integrators::RenderStats stats;
    bool alreadyWritten = false;  // --resume found every output written by this same render: nothing rendered

    RenderedFrame() = default;
    RenderedFrame(const RenderedFrame&) = delete;
    RenderedFrame& operator=(const RenderedFrame&) = delete;
};

// Renders `built` into `frame` for `planned`, over `outputs.window`. Returns the exit code:
// kExitOk (with frame.alreadyWritten when --resume had nothing left to do), else the error printed.
int renderFrameImage(const RenderOptions& opt, const usd::Stage& stage, const color::ColorManagement& colors,
                     double time, const PlannedRender& planned, BuiltFrame& built, const FrameOutputs& outputs,
                     WarningLog& warnings, RenderedFrame& frame);

}  // namespace fluence::app
