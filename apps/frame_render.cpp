#include "apps/frame_render.h"

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "apps/frame_denoise.h"
#include "apps/frame_summary.h"
#include "apps/progress_reporter.h"
#include "apps/render_checkpoint.h"
#include "apps/render_fingerprint.h"
#include "apps/scene_loading.h"
#include "integrators/adaptive_sampling.h"
#include "apps/stop_signals.h"
#include "core/sampler_names.h"
#include "output/exr_attributes.h"
#include "version.h"

namespace fluence::app {

namespace {

// Whether every output of a frame is already written by this same render (its header carries the
// render's fingerprint digest) and none is still going (no checkpoint beside the first).
bool alreadyRendered(const std::vector<std::string>& outputs, const std::string& checkpoint,
                     const std::string& digest) {
    std::error_code error;
    if (std::filesystem::exists(checkpoint, error)) return false;
    return std::all_of(outputs.begin(), outputs.end(), [&](const std::string& output) {
        return std::filesystem::exists(output, error) &&
               output::readStringAttribute(output, "fluence/fingerprint") == digest;
    });
}

// The planned light path AOVs the integrator writes: all, or none (warned) when it writes none.
// Returns the exit code: --lpe asking one of an integrator that writes none is a usage error, an
// expression it cannot write (IntegratorInfo::lightPathProblem) an error naming it.
int lightPathAovs(const RenderOptions& opt, const PlannedRender& planned, const integrators::IntegratorInfo& integrator,
                  WarningLog& warnings, std::vector<integrators::LightPathAov>& aovs) {
    aovs = planned.lightPaths;
    if (aovs.empty()) return kExitOk;
    if (integrator.lightPathExpressions) {
        for (const integrators::LightPathAov& aov : aovs) {
            const std::string problem = integrator.lightPathProblem ? integrator.lightPathProblem(aov.expression) : "";
            if (problem.empty()) continue;
            const bool option = std::any_of(opt.lightPaths.begin(), opt.lightPaths.end(),
                                            [&](const LightPathOption& o) { return o.name == aov.name; });
            printError(std::string(option ? "--lpe " : "lpe RenderVar ") + aov.name + ": integrator '" +
                       integrator.name + "' cannot write it: " + problem);
            return option ? kExitUsage : kExitScene;
        }
        return kExitOk;
    }
    const std::string why =
        "integrator '" + integrator.name + "' does not write light path expression AOVs (path, bdpt and sppm do)";
    if (!opt.lightPaths.empty()) {
        printError("--lpe: " + why);
        return kExitUsage;
    }
    warnings(planned.products.front().path, why + "; " + counted(aovs.size(), "lpe RenderVar") + " left out");
    aovs.clear();
    return kExitOk;
}

integrators::RenderSettings renderSettings(const RenderOptions& opt, const PixelWindow& window, int imageWidth) {
    integrators::RenderSettings rs;
    rs.samplesPerPixel = opt.spp.value_or(opt.meanSpp > 0.0 ? int(std::ceil(8.0 * opt.meanSpp)) : kDefaultSpp);
    rs.seed = opt.seed;
    rs.threads = opt.threads;
    rs.timeLimitSeconds = opt.timeLimit;
    rs.targetError = opt.targetError;
    rs.meanSamplesPerPixel = opt.meanSpp;
    rs.minSamples = opt.minSpp;
    rs.stop = &StopSignals::flag();
    rs.windowX = window.x0;
    rs.windowY = window.y0;
    rs.imageWidth = imageWidth;
    return rs;
}

// The outputs' EXR header (their snapshots' too), but for what the render's end adds.
output::ExrHeader frameHeader(const RenderOptions& opt, const color::ColorManagement& colors,
                              const render::Camera& camera, const PixelWindow& window, std::pair<int, int> res,
                              const std::string& cameraPath, const std::string& integrator, double time) {
    output::ExrHeader header;
    header.colorSpace = color::ColorManagement::kRenderingSpace;
    header.chromaticities = color::ColorManagement::renderingChromaticities();
    header.pixelAspectRatio = camera.pixelAspectRatio();
    header.dataChannels = Film::dataChannelNames();
    if (opt.tileCount) {
        header.x = window.x0;
        header.y = window.y0;
        header.fullWidth = res.first;
        header.fullHeight = res.second;
        header.strings.push_back({"fluence/tile", std::to_string(opt.tileIndex) + " of " +
                                                      std::to_string(opt.tileCount->first) + "x" +
                                                      std::to_string(opt.tileCount->second)});
    }
    header.strings.insert(header.strings.end(), {{"fluence/version", kFluenceVersion},
                                                 {"fluence/scene", std::filesystem::absolute(opt.scene).string()},
                                                 {"fluence/camera", cameraPath},
                                                 {"fluence/integrator", integrator},
                                                 {"fluence/ocioConfig", colors.configDescription()}});
    if (!std::isnan(time)) header.floats.push_back({"fluence/frame", float(time)});
    return header;
}

// The camera, the light path AOVs the integrator writes, the Cryptomatte requests and the
// integrator (warned when it renders a window without light tracing). Returns the exit code.
int prepare(const RenderOptions& opt, const PlannedRender& planned, BuiltFrame& built, const PixelWindow& window,
            WarningLog& warnings, std::vector<integrators::LightPathAov>& aovs, RenderedFrame& frame) {
    const std::pair<int, int> res = planned.resolution;
    try {
        frame.camera =
            std::make_unique<render::Camera>(*built.populated->scene.camera, res.first, res.second, planned.framing);
        built.scene->setTextureFilterCamera(*frame.camera);
    } catch (const std::invalid_argument& e) {
        printError(e.what());
        return kExitScene;
    }
    if (int code = lightPathAovs(opt, planned, *built.integrator, warnings, aovs); code != kExitOk) return code;
    try {
        frame.cryptomatteRequests = cryptomatteLayers(
            findProduct(built.populated->renderSettings, planned.products.front().path), opt.cryptomatte);
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    }
    integrators::IntegratorSettings isettings;
    isettings.maxDepth = opt.maxDepth;
    isettings.parameters = built.parameters;
    isettings.lightPathAovs = std::make_shared<const std::vector<integrators::LightPathAov>>(aovs);
    frame.integrator = built.integrator->create(isettings);
    if (frame.integrator->usesSplats() &&
        (window.width() != res.first || window.height() != res.second))  // integrators/renderer.h
        warnings(opt.scene,
                 "integrator '" + built.integrator->name +
                     "' renders a window of the image (a tile or a data window) without light tracing (t = 1): "
                     "point-light caustics seen directly are missed");
    return kExitOk;
}

// With --checkpoint or --resume: the render's fingerprint, in the header; frame.alreadyWritten
// when --resume finds the outputs written by this same render.
CheckpointFingerprint fingerprintRender(const RenderOptions& opt, const usd::Stage& stage,
                                        const ResolvedRender& resolved, const FrameOutputs& outputs,
                                        RenderedFrame& frame) {
    if (!opt.checkpointSeconds && !opt.resume) return {};
    const CheckpointFingerprint fingerprint = renderFingerprint(opt, stage, resolved);
    const std::string digest = fingerprintDigest(fingerprint);
    const std::string& outputPath = outputs.files.front();
    if (opt.resume && alreadyRendered(outputs.files, checkpointPath(outputPath), digest)) {
        std::printf("fluence: --resume: %s is already rendered (same fingerprint, no checkpoint); skipped\n",
                    outputPath.c_str());
        frame.alreadyWritten = true;
    }
    frame.header.strings.push_back({"fluence/fingerprint", digest});
    return fingerprint;
}

// Checkpoints and snapshots at pass boundaries (apps/pass_outputs.h), and the film resumed from
// a checkpoint with --resume. Returns the exit code.
int startPasses(const RenderOptions& opt, const std::string& outputPath, const CheckpointFingerprint& fingerprint,
                WarningLog& warnings, RenderedFrame& frame) {
    frame.passOutputs = std::make_unique<PassOutputs>(
        opt, outputPath, fingerprint, frame.cryptomatte.get(), warnings,
        [&opt, &frame](const std::string& path, const Film& partial, int samplesDone) {
            output::ExrHeader snapshotHeader = frame.header;
            snapshotHeader.floats.insert(snapshotHeader.floats.end(), {{"fluence/samplesPerPixel", float(samplesDone)},
                                                                       {"fluence/seed", float(opt.seed)},
                                                                       {"fluence/snapshot", 1.0f}});
            output::writeExr(path, partial.resolve(), snapshotHeader);
        });
    try {
        frame.settings.firstSample = frame.passOutputs->resume(*frame.film);
    } catch (const CheckpointMismatch& e) {
        printError(std::string(e.what()) + "; delete it, or render without --resume");
        return kExitUsage;
    } catch (const CheckpointError& e) {
        printError(e.what());
        return kExitMissingInput;
    }
    frame.settings.onPass = [&frame](int samplesDone) { frame.passOutputs->onPass(*frame.film, samplesDone); };
    return kExitOk;
}

}  // namespace

int renderFrameImage(const RenderOptions& opt, const usd::Stage& stage, const color::ColorManagement& colors,
                     double time, const PlannedRender& planned, BuiltFrame& built, const FrameOutputs& outputs,
                     WarningLog& warnings, RenderedFrame& frame) {
    const std::pair<int, int> res = planned.resolution;
    const PixelWindow& window = outputs.window;
    std::vector<integrators::LightPathAov> aovs;
    if (int code = prepare(opt, planned, built, window, warnings, aovs, frame); code != kExitOk) return code;
    std::vector<std::string> layers;
    for (const integrators::LightPathAov& aov : aovs) layers.push_back(aov.name);
    frame.settings = renderSettings(opt, window, res.first);
    frame.settings.sampler = built.sampler;
    frame.film = std::make_unique<Film>(window.width(), window.height(), frame.camera->farClip(), layers);
    // Adaptive sampling reads the half buffers too: enabled before a checkpoint is read into the film.
    if (keepsDenoiseBuffers(opt) || integrators::AdaptiveSampling::enabled(frame.settings))
        frame.film->enableDenoiseBuffers();
    frame.cryptomatte = cryptomatteFilm(frame.cryptomatteRequests, window.width(), window.height());
    frame.settings.cryptomatte = frame.cryptomatte.get();
    const std::string& cameraPath = built.populated->cameraPath;
    frame.header = frameHeader(opt, colors, *frame.camera, window, res, cameraPath, built.integrator->name, time);
    frame.header.strings.push_back({"fluence/sampler", std::string(samplerName(built.sampler))});
    frame.header.strings.push_back({"fluence/domeLightSampling", std::string(render::domeLightSamplingName(
                                                                     built.populated->scene.domeLightSampling))});
    const ResolvedRender resolved{cameraPath,
                                  res.first,
                                  res.second,
                                  window.x0,
                                  window.y0,
                                  window.width(),
                                  window.height(),
                                  time,
                                  built.integrator->name,
                                  built.parameters,
                                  frame.settings.samplesPerPixel,
                                  aovs,
                                  std::string(samplerName(built.sampler))};
    const CheckpointFingerprint fingerprint = fingerprintRender(opt, stage, resolved, outputs, frame);
    if (frame.alreadyWritten) return kExitOk;
    if (int code = startPasses(opt, outputs.files.front(), fingerprint, warnings, frame); code != kExitOk) return code;
    integrators::RenderProgress progress;
    try {
        ProgressReporter reporter(progress, opt.progress);
        frame.stats =
            integrators::render(*built.scene, *frame.camera, *frame.integrator, frame.settings, *frame.film, &progress);
    } catch (const std::invalid_argument& e) {  // an integrator refusing the scene (radiosity and light links)
        printError(e.what());
        return kExitScene;
    }
    if (frame.stats.interrupted) {
        printError("interrupted by a signal after " + std::to_string(frame.stats.samples) +
                   " samples; nothing written to " + outputs.files.front());
        return kExitInterrupted;
    }
    return kExitOk;
}

}  // namespace fluence::app
