#include "apps/render_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "apps/cryptomatte_layers.h"
#include "apps/frame_tokens.h"
#include "apps/pass_outputs.h"
#include "apps/progress_reporter.h"
#include "apps/render_products.h"
#include "apps/render_fingerprint.h"
#include "apps/run_summary.h"
#include "apps/snapshot_signal.h"
#include "apps/stop_signals.h"
#include "color/color_management.h"
#include "delegate/scene_delegate.h"
#include "integrators/automatic_choice.h"
#include "integrators/renderer.h"
#include "integrators/scene_path_classes.h"
#include "output/atomic_file.h"
#include "output/exr_attributes.h"
#include "output/exr_writer.h"
#include "output/preview_writer.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "version.h"

namespace fluence::app {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// "1 light", "3 lights".
std::string counted(std::size_t n, const std::string& singular, const std::string& plural = "") {
    return std::to_string(n) + " " + (n == 1 ? singular : (plural.empty() ? singular + "s" : plural));
}

// The integrator the render uses: --integrator, else the render settings' fluence:integrator,
// else the default. Throws SceneError when the settings name none that Fluence has.
// `sceneClasses`: the PathClass bits the scene can produce, for `auto`.
const integrators::IntegratorInfo& chosenIntegrator(const RenderOptions& opt, const delegate::DelegateResult& populated,
                                                    unsigned sceneClasses) {
    const auto& settings = populated.renderSettings;
    std::string name = !opt.integrator.empty() ? opt.integrator  // checked when parsed
                       : settings && !settings->integrator.empty() ? settings->integrator
                                                                   : kDefaultIntegrator;
    if (name == integrators::kAutomaticIntegrator) {
        const integrators::AutomaticChoice choice = integrators::chooseIntegrator(sceneClasses);
        std::printf("fluence: integrator auto: %s, %s\n", choice.integrator->name.c_str(), choice.reason.c_str());
        return *choice.integrator;
    }
    if (const integrators::IntegratorInfo* info = integrators::findIntegrator(name)) return *info;
    throw delegate::SceneError("render settings " + settings->path + ": fluence:integrator '" + settings->integrator +
                               "' is not an integrator (available: " + integratorNames() + ")");
}

// The part of the image a render takes: the whole, or tile --tile-index of --tile-count.
PixelWindow tileWindow(const RenderOptions& opt, std::pair<int, int> res) {
    if (!opt.tileCount) return {0, 0, res.first, res.second};
    const auto [columns, rows] = *opt.tileCount;
    const int column = opt.tileIndex % columns, row = opt.tileIndex / columns;
    const int x0 = res.first * column / columns, x1 = res.first * (column + 1) / columns;
    const int y0 = res.second * row / rows, y1 = res.second * (row + 1) / rows;
    return {x0, y0, x1, y1};
}

// `path` with the tile suffix ($T: the tile's index) before its extension.
std::string withTileSuffix(const std::string& path, std::string suffix, int index) {
    for (std::size_t at; (at = suffix.find("$T")) != std::string::npos;) suffix.replace(at, 2, std::to_string(index));
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

// Whether every output of a frame is already written by this same render (its header carries the
// render's fingerprint digest) and none is still going (no checkpoint beside the first).
bool alreadyRendered(const std::vector<std::string>& outputs, const std::string& checkpoint, const std::string& digest) {
    std::error_code error;
    if (std::filesystem::exists(checkpoint, error)) return false;
    return std::all_of(outputs.begin(), outputs.end(), [&](const std::string& output) {
        return std::filesystem::exists(output, error) && output::readStringAttribute(output, "fluence/fingerprint") == digest;
    });
}

// Renders the stage at time code `time` for the products of `planned` (apps/render_products.h)
// and writes them; returns the exit code. `parseSeconds` is the (shared) stage load's, for the
// summary; `primvars` those the frame's primvar RenderVars read.
int renderFrame(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors, double time,
                double parseSeconds, WarningLog& warnings, RunSummary& summary, const PlannedRender& planned,
                const std::set<std::string>& primvars) {
    const auto start = Clock::now();

    // Build: delegate, then the render scene.
    auto t = Clock::now();
    delegate::DelegateOptions dopt;
    dopt.cameraPath = planned.cameraPath;
    dopt.settingsPath = opt.settings;
    dopt.resolution = planned.resolution;
    dopt.aovPrimvars = primvars;
    dopt.defaultResolution = {kDefaultWidth, kDefaultHeight};
    dopt.dicing.rate = static_cast<float>(opt.dicingRate);
    dopt.dicing.uniformLevel = opt.subdivLevel.value_or(-1);
    dopt.time = time;
    dopt.purposes = opt.purposes;
    dopt.allowMissing = opt.allowMissing;
    dopt.strict = opt.strict;
    dopt.defaultLight = opt.defaultLight;
    dopt.convertColor = [&](const RGB& c, const std::string& space) { return colors.toRenderingSpace(space, c); };
    dopt.warn = [&](const std::string& path, const std::string& message) { warnings(path, message); };
    std::optional<delegate::DelegateResult> populated;
    std::unique_ptr<render::RenderScene> scene;
    const integrators::IntegratorInfo* integratorInfo = nullptr;
    unsigned sceneClasses = 0;  // the light paths the scene can produce (integrators/path_classes.h)
    try {
        populated = delegate::populateScene(stage, dopt);
        sceneClasses = integrators::scenePathClasses(populated->scene);
        integratorInfo = &chosenIntegrator(opt, *populated, sceneClasses);
        if (!opt.subsurface.empty())
            for (render::MaterialDesc& m : populated->scene.materials)
                m.subsurfaceMethod = opt.subsurface == "diffusion" ? render::SubsurfaceMethod::Diffusion : render::SubsurfaceMethod::RandomWalk;
        scene = std::make_unique<render::RenderScene>(populated->scene, std::make_shared<texture::TextureSystem>(colors));
        for (const render::Warning& w : scene->warnings()) warnings(w.where, w.message);
    } catch (const delegate::MissingAssetError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const color::ColorError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const std::invalid_argument& e) {
        printError(e.what());
        return kExitScene;
    }
    const double buildSeconds = secondsSince(t);
    if (scene->lightCount() == 0) warnings(populated->cameraPath, "the scene has no lights; the image will be black");
    if (const unsigned missed = sceneClasses & ~integratorInfo->covers)
        warnings(opt.scene, "integrator '" + integratorInfo->name + "' misses: " + integrators::describePathClasses(missed) +
                                " (light that this scene has)");

    // Render: the planned products' camera and image, over their data windows' part of the tile.
    const auto& settings = populated->renderSettings;
    const delegate::RenderProductDesc* product = findProduct(settings, planned.products.front().path);
    const std::pair<int, int> res = planned.resolution;
    std::vector<std::string> outputs;  // each product's file
    for (const PlannedProduct& p : planned.products) {
        if (opt.frameCount > 1 && !hasFrameToken(p.outputPattern)) {
            printError("rendering " + std::to_string(opt.frameCount) + " frames needs a frame token ($F, $F4, %04d) in the output path '" +
                       p.outputPattern + "'");
            return kExitUsage;
        }
        const std::string path = expandFrameTokens(p.outputPattern, time);
        outputs.push_back(opt.tileCount ? withTileSuffix(path, opt.tileSuffix, opt.tileIndex) : path);
    }
    const std::string& outputPath = outputs.front();
    const PixelWindow wholeTile = tileWindow(opt, res);
    if (wholeTile.empty()) {
        printError("tile " + std::to_string(opt.tileIndex) + " of --tile-count " + std::to_string(opt.tileCount->first) + " " +
                   std::to_string(opt.tileCount->second) + " has no pixels at " + std::to_string(res.first) + "x" +
                   std::to_string(res.second));
        return kExitUsage;
    }
    const PixelWindow window = wholeTile.intersect(planned.window());
    if (window.empty()) {
        warnings(planned.products.front().path, "tile " + std::to_string(opt.tileIndex) + " holds no pixel of its data window; nothing written");
        return kExitOk;
    }
    const std::string previewPath = expandFrameTokens(opt.preview, time);
    std::vector<std::string> made = outputs;
    made.push_back(previewPath);
    if (opt.makeOutputPath)
        for (const std::string& path : made)
            if (std::filesystem::path folder = std::filesystem::path(path).parent_path(); !path.empty() && !folder.empty()) {
                std::error_code error;
                std::filesystem::create_directories(folder, error);
                if (error) {
                    printError("cannot make the output folder " + folder.string() + ": " + error.message());
                    return kExitOutput;
                }
            }
    std::unique_ptr<render::Camera> camera;
    try {
        camera = std::make_unique<render::Camera>(*populated->scene.camera, res.first, res.second, planned.framing);
        scene->setTextureFilterCamera(*camera);
    } catch (const std::invalid_argument& e) {
        printError(e.what());
        return kExitScene;
    }
    std::vector<integrators::LightPathAov> aovs = planned.lightPaths;
    if (!aovs.empty() && !integratorInfo->lightPathExpressions) {
        const std::string why = "integrator '" + integratorInfo->name + "' does not write light path expression AOVs (path does)";
        if (!opt.lightPaths.empty()) {
            printError("--lpe: " + why);
            return kExitUsage;
        }
        warnings(product->path, why + "; " + counted(aovs.size(), "lpe RenderVar") + " left out");
        aovs.clear();
    }
    std::vector<CryptomatteLayerRequest> cryptomatteRequests;
    try {
        cryptomatteRequests = cryptomatteLayers(product, opt.cryptomatte);
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    }
    std::vector<std::string> layers;
    for (const integrators::LightPathAov& aov : aovs) layers.push_back(aov.name);
    integrators::IntegratorSettings isettings;
    isettings.maxDepth = opt.maxDepth;
    isettings.lightPathAovs = std::make_shared<const std::vector<integrators::LightPathAov>>(std::move(aovs));
    std::unique_ptr<integrators::Integrator> integrator = integratorInfo->create(isettings);
    if (integrator->usesSplats() && (window.width() != res.first || window.height() != res.second))  // integrators/renderer.h
        warnings(opt.scene, "integrator '" + integratorInfo->name +
                                "' renders a window of the image (a tile or a data window) without light tracing (t = 1): "
                                "point-light caustics seen directly are missed");
    integrators::RenderSettings rs;
    rs.samplesPerPixel = opt.spp.value_or(kDefaultSpp);
    rs.seed = opt.seed;
    rs.threads = opt.threads;
    rs.timeLimitSeconds = opt.timeLimit;
    rs.targetError = opt.targetError;
    rs.minSamples = opt.minSpp;
    rs.stop = &StopSignals::flag();
    rs.windowX = window.x0;
    rs.windowY = window.y0;
    rs.imageWidth = res.first;
    Film film(window.width(), window.height(), camera->farClip(), layers);
    std::unique_ptr<CryptomatteFilm> cryptomatte = cryptomatteFilm(cryptomatteRequests, window.width(), window.height());
    rs.cryptomatte = cryptomatte.get();
    // The output's EXR header (its snapshots' too), but for what the render's end adds.
    output::ExrHeader header;
    header.colorSpace = color::ColorManagement::kRenderingSpace;
    header.chromaticities = color::ColorManagement::renderingChromaticities();
    header.pixelAspectRatio = camera->pixelAspectRatio();
    header.dataChannels = Film::dataChannelNames();
    if (opt.tileCount) {
        header.x = window.x0;
        header.y = window.y0;
        header.fullWidth = res.first;
        header.fullHeight = res.second;
        header.strings.push_back({"fluence/tile", std::to_string(opt.tileIndex) + " of " + std::to_string(opt.tileCount->first) +
                                                      "x" + std::to_string(opt.tileCount->second)});
    }
    header.strings.insert(header.strings.end(), {{"fluence/version", kFluenceVersion},
                      {"fluence/scene", std::filesystem::absolute(opt.scene).string()},
                      {"fluence/camera", populated->cameraPath},
                      {"fluence/integrator", integratorInfo->name},
                      {"fluence/ocioConfig", colors.configDescription()}});
    if (!std::isnan(time)) header.floats.push_back({"fluence/frame", float(time)});
    // Checkpoints and snapshots at pass boundaries (apps/pass_outputs.h).
    const bool checkpoints = opt.checkpointSeconds || opt.resume;
    const ResolvedRender resolved{populated->cameraPath, res.first, res.second, window.x0, window.y0, window.width(), window.height(),
                                  time, integratorInfo->name, rs.samplesPerPixel, *isettings.lightPathAovs};
    const CheckpointFingerprint fingerprint = checkpoints ? renderFingerprint(opt, stage, resolved) : CheckpointFingerprint{};
    if (checkpoints) {
        const std::string digest = fingerprintDigest(fingerprint);
        if (opt.resume && alreadyRendered(outputs, checkpointPath(outputPath), digest)) {
            std::printf("fluence: --resume: %s is already rendered (same fingerprint, no checkpoint); skipped\n", outputPath.c_str());
            return kExitOk;
        }
        header.strings.push_back({"fluence/fingerprint", digest});
    }
    PassOutputs passOutputs(opt, outputPath, fingerprint,
                            cryptomatte.get(), warnings, [&](const std::string& path, const Film& partial, int samplesDone) {
                                output::ExrHeader snapshotHeader = header;
                                snapshotHeader.floats.insert(snapshotHeader.floats.end(), {{"fluence/samplesPerPixel", float(samplesDone)},
                                                             {"fluence/seed", float(opt.seed)}, {"fluence/snapshot", 1.0f}});
                                output::writeExr(path, partial.resolve(), snapshotHeader);
                            });
    try {
        rs.firstSample = passOutputs.resume(film);
    } catch (const CheckpointMismatch& e) {
        printError(std::string(e.what()) + "; delete it, or render without --resume");
        return kExitUsage;
    } catch (const CheckpointError& e) {
        printError(e.what());
        return kExitMissingInput;
    }
    rs.onPass = [&](int samplesDone) { passOutputs.onPass(film, samplesDone); };
    integrators::RenderProgress progress;
    integrators::RenderStats stats;
    {
        ProgressReporter reporter(progress, opt.progress);
        stats = integrators::render(*scene, *camera, *integrator, rs, film, &progress);
    }
    if (stats.interrupted) {
        printError("interrupted by a signal after " + std::to_string(stats.samples) + " samples; nothing written to " + outputPath);
        return kExitInterrupted;
    }

    // Write.
    t = Clock::now();
    const Image image = film.resolve();
    const Image firstHit = integrators::renderFirstHitAovs(*scene, *camera, rs, film, planned.firstHitAovs);
    header.floats.insert(header.floats.end(), {{"fluence/samplesPerPixel", float(stats.samplesPerPixel)},
                     {"fluence/seed", float(opt.seed)},
                     {"fluence/renderSeconds", float(stats.seconds)}});
    try {
        for (std::size_t p = 0; p < planned.products.size(); ++p) {
            const PixelWindow written = planned.products[p].window.intersect(window);
            if (written.empty()) {
                warnings(planned.products[p].path, "tile " + std::to_string(opt.tileIndex) + " holds no pixel of its data window; not written");
                continue;
            }
            output::ExrHeader productHeader = header;
            Image productImg = productImage(planned.products[p], written, image, firstHit, window, productHeader);
            describeProductHeader(productHeader, *camera, written, res);
            if (p == 0 && cryptomatte) {
                if (written == window)
                    appendCryptomatteLayers(productImg, productHeader, *cryptomatte, cryptomatteRequests, *scene, opt.cryptomatteDepth);
                else
                    warnings(planned.products[p].path, "Cryptomatte layers need the product's data window to be its render's; left out");
            }
            output::writeExr(outputs[p], productImg, productHeader);
        }
        if (!previewPath.empty()) output::writePreviewPng(previewPath, image, colors);
    } catch (const output::OutputError& e) {
        printError(e.what());
        return kExitOutput;
    }
    passOutputs.finish();
    const double writeSeconds = secondsSince(t);

    // Summary.
    const double total = secondsSince(start);
    const double samples = double(stats.samples);
    const auto& st = scene->stats();
    std::printf("fluence: rendered %s\n", opt.scene.c_str());
    std::printf("  camera       %s\n", populated->cameraPath.empty() ? "(default: framing the scene)" : populated->cameraPath.c_str());
    std::printf("  image        %d x %d, %d spp, integrator %s, seed %llu, %d threads\n", res.first, res.second,
                stats.samplesPerPixel, integratorInfo->name.c_str(), static_cast<unsigned long long>(opt.seed),
                opt.threads > 0 ? opt.threads : int(std::thread::hardware_concurrency()));
    std::printf("  scene        %s, %s, %s (%s), %s\n", counted(st.meshes, "mesh", "meshes").c_str(),
                counted(st.triangles, "triangle").c_str(), counted(st.lights, "light").c_str(),
                counted(st.emissiveTriangles, "emissive triangle").c_str(), counted(warnings.count(), "warning").c_str());
    if (rs.targetError > 0.0)
        std::printf("  adaptive     target error %g: %.1f spp on average (%d to %d per pixel)\n", rs.targetError,
                    samples / (double(res.first) * res.second), std::min(rs.minSamples, stats.samplesPerPixel),
                    stats.samplesPerPixel);
    if (st.instances > 0)
        std::printf("  instancing   %s placing %s (stored once)\n", counted(st.instances, "instance").c_str(),
                    counted(st.instancedTriangles, "triangle").c_str());
    std::printf("  time         parse %.3f s, build %.3f s, render %.3f s, write %.3f s, total %.3f s\n", parseSeconds,
                buildSeconds, stats.seconds, writeSeconds, total);
    std::printf("  throughput   %.3f Msamples/s, %.3f Mrays/s (%llu rays: %llu camera, %llu bounce, %llu shadow)\n",
                samples / stats.seconds * 1e-6, double(stats.counters.rays()) / stats.seconds * 1e-6,
                static_cast<unsigned long long>(stats.counters.rays()), static_cast<unsigned long long>(stats.counters.camera),
                static_cast<unsigned long long>(stats.counters.bounce), static_cast<unsigned long long>(stats.counters.shadow));
    if (stats.counters.nonFiniteSamples > 0)
        std::fprintf(stderr, "fluence: warning: %llu samples were NaN or infinite and were discarded (please report)\n",
                     static_cast<unsigned long long>(stats.counters.nonFiniteSamples));
    if (const std::string& note = stats.methodSummary; !note.empty()) std::printf("  method       %s\n", note.c_str());
    for (const std::string& path : outputs) std::printf("  output       %s\n", path.c_str());
    if (!previewPath.empty()) std::printf("  preview      %s\n", previewPath.c_str());

    FrameSummary& frame = summary.frames.emplace_back();
    frame.time = time;
    frame.output = outputPath;
    frame.integrator = integratorInfo->name;
    frame.camera = populated->cameraPath;
    frame.width = res.first;
    frame.height = res.second;
    frame.samplesPerPixel = stats.samplesPerPixel;
    frame.samples = stats.samples;
    frame.cameraRays = stats.counters.camera;
    frame.bounceRays = stats.counters.bounce;
    frame.shadowRays = stats.counters.shadow;
    frame.nonFiniteSamples = stats.counters.nonFiniteSamples;
    frame.buildSeconds = buildSeconds;
    frame.renderSeconds = stats.seconds;
    frame.writeSeconds = writeSeconds;
    frame.totalSeconds = total;
    return kExitOk;
}

// Renders and writes every render product of the frame at `time` (apps/render_products.h), one
// render per camera and image; returns the exit code.
int renderProducts(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors, double time,
                   double parseSeconds, WarningLog& warnings, RunSummary& summary) {
    RenderPlan plan;
    try {
        plan = planRenders(delegate::renderSettingsFromStage(stage, opt.settings, time), opt,
                           std::filesystem::path(opt.scene).stem().string(), [&](const std::string& where, const std::string& message) { warnings(where, message); });
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const UsageError& e) {
        printError(e.what());
        return kExitUsage;
    }
    for (std::size_t r = 0; r < plan.renders.size(); ++r)
        if (int code = renderFrame(opt, stage, colors, time, r == 0 ? parseSeconds : 0.0, warnings, summary, plan.renders[r], plan.primvars());
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
    const auto t = Clock::now();
    std::unique_ptr<usd::Stage> stage;
    const MissingAssets missing = opt.allowMissing ? MissingAssets::Warn : MissingAssets::Fail;
    if (int code = openStage(opt.scene, {opt.variants, opt.loadRules}, warnings, stage, missing); code != kExitOk) return code;
    try {
        applyAttributeOverrides(*stage, opt.overrides);
    } catch (const UsageError& e) {
        printError(e.what());
        return kExitUsage;
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    }
    const double parseSeconds = summary.parseSeconds = secondsSince(t);

    // The frames: --frame (else the stage's startTimeCode, else none: the delegate reads each
    // attribute's earliest time sample, delegate/prim_reader.h) and the
    // --frame-count - 1 after it, --frame-inc apart.
    const double first = opt.frame ? *opt.frame : stage->startTimeCode().value_or(usd::kDefaultTime);
    if (opt.frameCount > 1 && std::isnan(first)) {
        printError("--frame-count " + std::to_string(opt.frameCount) + " needs a first frame: give --frame or a startTimeCode");
        return kExitUsage;
    }
    for (int k = 0; k < opt.frameCount; ++k) {
        const double time = first + k * opt.frameIncrement;
        if (StopSignals::flag()) {
            printError("interrupted by a signal before frame " + std::to_string(time) + "; nothing more written");
            return kExitInterrupted;
        }
        if (opt.frameCount > 1) std::printf("fluence: frame %g (%d of %d)\n", time, k + 1, opt.frameCount);
        if (int code = renderProducts(opt, *stage, *colors, time, k == 0 ? parseSeconds : 0.0, warnings, summary); code != kExitOk)
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
