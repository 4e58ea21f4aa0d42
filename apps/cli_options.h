// Command-line options of `fluence render`, named after Houdini's husk where husk has the same
// notion, so farm plugins can drive Fluence the way they drive husk.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/attribute_overrides.h"
#include "apps/cryptomatte_layers.h"
#include "apps/light_path_aovs.h"
#include "apps/progress_reporter.h"
#include "core/random.h"
#include "render/dome_light_sampling.h"
#include "scene/stage.h"

namespace fluence::app {

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RenderOptions {
    std::string scene;
    std::string output;                             // -o/--output; default: <scene stem>.exr
    std::string preview;                            // --preview FILE.png: an sRGB preview through the OCIO display/view
    std::optional<int> spp;                         // --spp N (default 64)
    std::optional<std::pair<int, int>> resolution;  // -r/--res W H
    std::string camera;                             // -c/--camera /Prim/Path
    int threads = 0;                                // -j/--threads N (0: all cores)
    std::uint64_t seed = 0;                         // --seed S
    std::optional<SamplerKind> sampler;             // --sampler NAME (else fluence:sampler, else sobol)
    std::string integrator;  // --integrator NAME ("": the render settings' fluence:integrator, else path)
    std::map<std::string, double> integratorParameters;  // --sppm-photons N, ... (apps/integrator_parameters.h)
    double timeLimit = 0.0;                              // --time-limit SECONDS (0: none)
    double targetError = 0.0;        // --target-error E: adaptive sampling's relative error per pixel (0: off)
    double meanSpp = 0.0;            // --mean-spp N: adaptive sampling to a budget of N spp on average (0: off)
    int minSpp = 16;                 // --min-spp N: samples every pixel takes before it may stop
    int maxDepth = 64;               // --max-depth N
    double dicingRate = 1.0;         // --dicing-rate PIXELS: micro-edge length of subdivision surfaces
    std::optional<int> subdivLevel;  // --subdiv-level N: uniform refinement instead of dicing
    std::string subsurface;          // --subsurface randomwalk|diffusion: every material's method ("" keeps theirs)
    std::optional<render::DomeLightSampling>
        domeSampling;  // --dome-sampling auto|always (else fluence:domeLightSampling)
    std::optional<double>
        frame;  // -f/--frame F (default: the stage's startTimeCode, else none: each attribute's earliest sample)
    int frameCount = 1;           // -n/--frame-count N: frames to render from --frame on
    double frameIncrement = 1.0;  // -i/--frame-inc K: time codes between them
    bool makeOutputPath = false;  // --make-output-path: create the output's folders
    std::string summary;          // --summary FILE.json: what the render did (apps/run_summary.h)
    std::optional<double>
        checkpointSeconds;  // --checkpoint SECS: a resumable checkpoint that often (apps/pass_outputs.h)
    bool resume = false;    // --resume: go on from the output's checkpoint, if there is one
    std::optional<double> snapshotSeconds;         // --snapshot SECS: the image so far beside the output that often
    std::optional<std::pair<int, int>> tileCount;  // --tile-count X Y: the image split into X x Y tiles
    int tileIndex = 0;  // --tile-index N: the tile to render, 0 to X*Y - 1, row by row from the top left
    std::string tileSuffix = "_tile$T";  // --tile-suffix FMT: added before the output's extension ($T: the index)
    std::string settings;                // -s/--settings /Render/Path (default: the stage's renderSettingsPrimPath)
    std::vector<usd::VariantSelection> variants;      // --variant /Prim/Path:set=selection (repeatable)
    usd::LoadRules loadRules;                         // --load P, --unload P (repeatable), --no-payloads
    std::vector<LightPathOption> lightPaths;          // --lpe NAME=EXPRESSION (repeatable)
    std::vector<CryptomatteSource> cryptomatte;       // --cryptomatte object,material
    int cryptomatteDepth = kDefaultCryptomatteDepth;  // --cryptomatte-depth N
    std::vector<AttributeOverride> overrides;         // --set [TYPE ]/Prim.attr=VALUE (repeatable)
    ProgressStyle progress = ProgressStyle::Auto;     // -V [LEVEL][a]: 0 none, a ALF_PROGRESS lines
    bool defaultLight = true;   // --no-default-light: no default lights in a scene where nothing emits
    bool motionBlur = true;     // --no-motion-blur: the camera's shutter as an instant
    bool allowMissing = false;  // --allow-missing: render without missing layers, textures and VDBs (warnings)
    bool strict = false;        // --strict: a malformed prim is an error (exit 3), not a warning and skipped
    std::optional<std::vector<std::string>> purposes;  // --purpose a,b: else the render settings' includedPurposes
    bool denoise = false;  // --denoise: RGBA denoised, the noisy beauty kept as noisy.R/G/B (apps/frame_denoise.h)
    bool denoiseLayers = false;   // --denoise-layers: with --denoise, the light path layers denoised too
    bool denoiseBuffers = false;  // --denoise-buffers: the half images and variance written, nothing denoised
};

// Options of `fluence denoise`.
struct DenoiseOptions {
    std::string input;    // IN.exr
    std::string output;   // -o/--output OUT.exr
    bool layers = false;  // --denoise-layers: the light path layers too
    int threads = 0;      // -j/--threads N
};

// Options of `fluence assemble`.
struct AssembleOptions {
    std::string output;              // -o/--output OUT.exr
    std::vector<std::string> tiles;  // the tile EXRs
};

// Options of `fluence info`.
struct InfoOptions {
    std::string scene;
    std::vector<usd::VariantSelection> variants;
    std::string settings;
    usd::LoadRules loadRules;
    bool strict = false;  // --strict: exit 3 when a prim is malformed (what `render --strict` refuses)
};

inline constexpr int kDefaultSpp = 64;
inline constexpr int kMaxSubdivLevel = 8;
inline constexpr int kDefaultWidth = 640, kDefaultHeight = 480;
inline constexpr const char* kDefaultIntegrator = "path";

// Parses the arguments after `fluence render`. Throws UsageError with a one-line reason.
RenderOptions parseRenderOptions(const std::vector<std::string>& args);
InfoOptions parseInfoOptions(const std::vector<std::string>& args);
AssembleOptions parseAssembleOptions(const std::vector<std::string>& args);
DenoiseOptions parseDenoiseOptions(const std::vector<std::string>& args);
// Parses "/Prim/Path:set=selection".
usd::VariantSelection parseVariantSelection(const std::string& text);

// The registered integrators' names, "path, naive, ...", for messages.
std::string integratorNames();

std::string usageText();

}  // namespace fluence::app
