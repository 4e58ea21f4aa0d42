#include "apps/render_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <thread>

#include "apps/frame_build.h"
#include "apps/frame_outputs.h"
#include "apps/frame_render.h"
#include "apps/frame_summary.h"
#include "apps/frame_write.h"
#include "apps/render_products.h"
#include "apps/run_summary.h"
#include "apps/snapshot_signal.h"
#include "apps/stop_signals.h"
#include "apps/stopwatch.h"
#include "color/color_management.h"
#include "delegate/scene_delegate.h"
#include "output/atomic_file.h"
#include "scene/stage.h"

namespace fluence::app {

namespace {

// Renders the stage at time code `time` for the products of `planned` (apps/render_products.h)
// and writes them, in four steps: build, plan the outputs, render, write; returns the exit code.
// `parseSeconds` is the (shared) stage load's, for the summary; `primvars` those the frame's
// primvar RenderVars read.
int renderFrame(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors, double time,
                double parseSeconds, WarningLog& warnings, RunSummary& summary, const PlannedRender& planned,
                const std::set<std::string>& primvars) {
    const Stopwatch total;
    BuiltFrame built;
    if (int code = buildFrame(opt, stage, colors, time, planned, primvars, warnings, built); code != kExitOk)
        return code;
    FrameOutputs outputs;
    if (int code = planFrameOutputs(opt, time, planned, warnings, outputs); code != kExitOk || outputs.window.empty())
        return code;
    RenderedFrame frame;
    if (int code = renderFrameImage(opt, stage, colors, time, planned, built, outputs, warnings, frame);
        code != kExitOk || frame.alreadyWritten)
        return code;
    const Stopwatch writing;
    if (int code = writeFrame(opt, colors, planned, *built.scene, outputs, warnings, frame); code != kExitOk)
        return code;
    const FrameTimes times{parseSeconds, built.seconds, writing.seconds(), total.seconds()};
    printFrameSummary(opt, planned.resolution, built, frame, outputs, times, warnings);
    summary.frames.push_back(frameSummary(time, planned.resolution, built, frame, outputs, times));
    return kExitOk;
}

// Renders and writes every render product of the frame at `time` (apps/render_products.h), one
// render per camera and image; returns the exit code.
int renderProducts(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors, double time,
                   double parseSeconds, WarningLog& warnings, RunSummary& summary) {
    RenderPlan plan;
    try {
        std::function<void(const std::string&, const std::string&)> warn =
            [&](const std::string& where, const std::string& message) { warnings(where, message); };
        plan = planRenders(delegate::renderSettingsFromStage(stage, opt.settings, time, opt.strict ? nullptr : warn),
                           opt, std::filesystem::path(opt.scene).stem().string(), warn);
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const UsageError& e) {
        printError(e.what());
        return kExitUsage;
    }
    for (std::size_t r = 0; r < plan.renders.size(); ++r)
        if (int code = renderFrame(opt, stage, colors, time, r == 0 ? parseSeconds : 0.0, warnings, summary,
                                   plan.renders[r], plan.primvars());
            code != kExitOk)
            return code;
    return kExitOk;
}

// Loads the stage once and renders every frame; returns the exit code.
int renderFrames(const RenderOptions& opt, WarningLog& warnings, RunSummary& summary) {
    // Colour management first: every authored colour goes through it.
    std::optional<color::ColorManagement> colors;
    try {
        colors = color::ColorManagement::load();
    } catch (const std::exception& e) {
        printError(e.what());
        return kExitColorConfig;
    }

    // Parse and compose, once for every frame.
    const Stopwatch parsing;
    std::unique_ptr<usd::Stage> stage;
    if (int code = composeStage(opt.scene, {opt.variants, opt.loadRules}, warnings, stage); code != kExitOk)
        return code;
    try {
        applyAttributeOverrides(*stage, opt.overrides);
    } catch (const UsageError& e) {
        printError(e.what());
        return kExitUsage;
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    }

    // The frames: --frame (else the stage's startTimeCode, else none: the delegate reads each
    // attribute's earliest time sample, delegate/prim_reader.h) and the
    // --frame-count - 1 after it, --frame-inc apart.
    const double first = opt.frame ? *opt.frame : stage->startTimeCode().value_or(usd::kDefaultTime);
    if (opt.frameCount > 1 && std::isnan(first)) {
        printError("--frame-count " + std::to_string(opt.frameCount) +
                   " needs a first frame: give --frame or a startTimeCode");
        return kExitUsage;
    }
    std::vector<double> frames;
    for (int k = 0; k < opt.frameCount; ++k) frames.push_back(first + k * opt.frameIncrement);
    // The assets those frames read (after the overrides, which may replace some).
    if (int code = checkAssets(*stage, warnings, opt.allowMissing ? MissingAssets::Warn : MissingAssets::Fail, frames);
        code != kExitOk)
        return code;
    const double parseSeconds = summary.parseSeconds = parsing.seconds();

    for (int k = 0; k < opt.frameCount; ++k) {
        const double time = frames[k];
        if (StopSignals::flag()) {
            printError("interrupted by a signal before frame " + std::to_string(time) + "; nothing more written");
            return kExitInterrupted;
        }
        if (opt.frameCount > 1) std::printf("fluence: frame %g (%d of %d)\n", time, k + 1, opt.frameCount);
        if (int code = renderProducts(opt, *stage, *colors, time, k == 0 ? parseSeconds : 0.0, warnings, summary);
            code != kExitOk)
            return code;
    }
    return kExitOk;
}

}  // namespace

int runRender(const RenderOptions& opt) {
    const StopSignals stopSignals;
    const SnapshotSignal snapshotSignal;
    WarningLog warnings;
    RunSummary summary;
    summary.scene = opt.scene;
    summary.seed = opt.seed;
    summary.threads = opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency());
    summary.exitCode = renderFrames(opt, warnings, summary);
    if (opt.summary.empty()) return summary.exitCode;
    summary.warnings = warnings.entries();
    try {
        writeSummary(opt.summary, summary);
    } catch (const output::OutputError& e) {
        printError(e.what());
        return summary.exitCode == kExitOk ? kExitOutput : summary.exitCode;
    }
    return summary.exitCode;
}

}  // namespace fluence::app
