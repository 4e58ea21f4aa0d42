#include "apps/cli_options.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "apps/integrator_parameters.h"
#include "core/sampler_names.h"
#include "delegate/imageable.h"
#include "integrators/automatic_choice.h"
#include "integrators/integrator.h"
#include "render/subsurface_method.h"

namespace fluence::app {

namespace {

template <typename T>
T parseNumber(const std::string& flag, const std::string& text) {
    T value{};
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end) throw UsageError(flag + " expects a number, got '" + text + "'");
    return value;
}

class ArgCursor {
public:
    explicit ArgCursor(const std::vector<std::string>& args) : args_(args) {}
    bool done() const { return i_ >= args_.size(); }
    const std::string& next() { return args_[i_++]; }
    const std::string& value(const std::string& flag) {
        if (done()) throw UsageError(flag + " needs a value");
        return next();
    }

private:
    const std::vector<std::string>& args_;
    std::size_t i_ = 0;
};

// --load P, --unload P and --no-payloads, as USD load rules. Whatever the order given, the rule of
// the nearest prim wins: --no-payloads is the stage-wide rule, and deeper prims' rules apply last.
class LoadRuleArgs {
public:
    // Takes `arg` (and its value) when it is one of these options.
    bool take(const std::string& arg, ArgCursor& cur) {
        if (arg == "--no-payloads") {
            none_ = true;
        } else if (arg == "--load" || arg == "--unload") {
            const std::string& path = cur.value(arg);
            if (!path.starts_with("/")) throw UsageError(arg + " needs an absolute prim path such as /World/Asset");
            rules_.emplace_back(path, arg == "--load");
        } else {
            return false;
        }
        return true;
    }

    usd::LoadRules rules() const {
        usd::LoadRules out = none_ ? usd::LoadRules::loadNone() : usd::LoadRules::loadAll();
        auto depth = [](const std::string& path) {
            return path == "/" ? 0 : std::count(path.begin(), path.end(), '/');
        };
        std::vector<std::pair<std::string, bool>> byDepth = rules_;
        std::stable_sort(byDepth.begin(), byDepth.end(),
                         [&](const auto& a, const auto& b) { return depth(a.first) < depth(b.first); });
        for (const auto& [path, load] : byDepth) {
            if (load)
                out.load(path);
            else
                out.unload(path);
        }
        return out;
    }

private:
    bool none_ = false;
    std::vector<std::pair<std::string, bool>> rules_;  // (prim path, load), as given
};

// "a,b,c" -> {"a", "b", "c"} (empty items dropped).
std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    for (std::size_t start = 0; start <= text.size();) {
        std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) items.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return items;
}

// husk's -V: a verbosity digit (0: no progress) and/or 'a' for ALF_PROGRESS lines even on a
// terminal, e.g. `-V a`, `-V2a`, `-V 0`.
ProgressStyle parseVerbosity(const std::string& text) {
    std::size_t digits = 0;
    while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
    const std::string suffix = text.substr(digits);
    if ((digits == 0 && suffix.empty()) || (suffix != "" && suffix != "a"))
        throw UsageError("-V expects a verbosity level and/or 'a' (e.g. -V a, -V2a), got '" + text + "'");
    if (suffix == "a") return ProgressStyle::Alfred;
    return std::stoi(text.substr(0, digits)) == 0 ? ProgressStyle::None : ProgressStyle::Auto;
}

// --complexity, as husk has it: how finely subdivision surfaces are refined. lowest renders the
// control cage, low and medium refine uniformly one and two levels, high dices at 2 pixels per
// micro-edge and veryhigh (the default) at --dicing-rate. --subdiv-level and --dicing-rate, when
// given, win.
void applyComplexity(const std::string& complexity, bool dicingRateGiven, RenderOptions& o) {
    if (complexity.empty() || complexity == "veryhigh") return;
    if (complexity == "high") {
        if (!dicingRateGiven) o.dicingRate = 2.0;
        return;
    }
    const int level = complexity == "lowest" ? 0 : complexity == "low" ? 1 : complexity == "medium" ? 2 : -1;
    if (level < 0)
        throw UsageError("--complexity must be lowest, low, medium, high or veryhigh, got '" + complexity + "'");
    if (!o.subdivLevel) o.subdivLevel = level;
}

// An argument that is not an option: the scene file, given once.
void takeScene(const std::string& arg, std::string& scene) {
    if (arg.starts_with("-") && arg.size() > 1) throw UsageError("unknown option '" + arg + "'");
    if (!scene.empty()) throw UsageError("unexpected argument '" + arg + "' (the scene is already " + scene + ")");
    scene = arg;
}

}  // namespace

usd::VariantSelection parseVariantSelection(const std::string& text) {
    auto colon = text.find(':'), equals = text.find('=', colon == std::string::npos ? 0 : colon);
    if (!text.starts_with("/") || colon == std::string::npos || equals == std::string::npos || colon + 1 == equals)
        throw UsageError("--variant expects /Prim/Path:set=selection, got '" + text + "'");
    return {text.substr(0, colon), text.substr(colon + 1, equals - colon - 1), text.substr(equals + 1)};
}

InfoOptions parseInfoOptions(const std::vector<std::string>& args) {
    InfoOptions o;
    ArgCursor cur(args);
    LoadRuleArgs load;
    while (!cur.done()) {
        const std::string arg = cur.next();
        if (load.take(arg, cur)) continue;
        if (arg == "--variant") {
            o.variants.push_back(parseVariantSelection(cur.value(arg)));
        } else if (arg == "-s" || arg == "--settings") {
            o.settings = cur.value(arg);
        } else if (arg == "--strict") {
            o.strict = true;
        } else {
            takeScene(arg, o.scene);
        }
    }
    if (o.scene.empty()) throw UsageError("no scene file given");
    o.loadRules = load.rules();
    return o;
}

AssembleOptions parseAssembleOptions(const std::vector<std::string>& args) {
    AssembleOptions o;
    ArgCursor cur(args);
    while (!cur.done()) {
        const std::string arg = cur.next();
        if (arg == "-o" || arg == "--output")
            o.output = cur.value(arg);
        else if (arg.starts_with("-"))
            throw UsageError("unknown option '" + arg + "' for assemble");
        else
            o.tiles.push_back(arg);
    }
    if (o.output.empty()) throw UsageError("assemble needs -o OUT.exr");
    if (o.tiles.empty()) throw UsageError("assemble needs the tile images to merge");
    return o;
}

DenoiseOptions parseDenoiseOptions(const std::vector<std::string>& args) {
    DenoiseOptions o;
    ArgCursor cur(args);
    while (!cur.done()) {
        const std::string arg = cur.next();
        if (arg == "-o" || arg == "--output") {
            o.output = cur.value(arg);
        } else if (arg == "--denoise-layers") {
            o.layers = true;
        } else if (arg == "-j" || arg == "--threads") {
            o.threads = parseNumber<int>(arg, cur.value(arg));
            if (o.threads < 0) throw UsageError(arg + " must be 0 (all cores) or more");
        } else if (arg.starts_with("-")) {
            throw UsageError("unknown option '" + arg + "' for denoise");
        } else if (o.input.empty()) {
            o.input = arg;
        } else {
            throw UsageError("denoise takes one image (got '" + o.input + "' and '" + arg + "')");
        }
    }
    if (o.input.empty()) throw UsageError("denoise needs the image to denoise");
    if (o.output.empty()) throw UsageError("denoise needs -o OUT.exr");
    return o;
}

RenderOptions parseRenderOptions(const std::vector<std::string>& args) {
    RenderOptions o;
    ArgCursor cur(args);
    LoadRuleArgs load;
    std::string complexity;
    bool dicingRateGiven = false;
    while (!cur.done()) {
        const std::string arg = cur.next();
        if (load.take(arg, cur)) continue;
        if (arg == "-o" || arg == "--output") {
            o.output = cur.value(arg);
        } else if (arg == "--preview") {
            o.preview = cur.value(arg);
        } else if (arg == "--spp") {
            o.spp = parseNumber<int>(arg, cur.value(arg));
            if (*o.spp < 1) throw UsageError("--spp must be at least 1");
        } else if (arg == "-r" || arg == "--res") {
            int w = parseNumber<int>(arg, cur.value(arg));
            int h = parseNumber<int>(arg, cur.value(arg));
            if (w < 1 || h < 1 || w > 65536 || h > 65536)
                throw UsageError(arg + " needs a width and height from 1 to 65536");
            o.resolution = {w, h};
        } else if (arg == "-c" || arg == "--camera") {
            o.camera = cur.value(arg);
            if (!o.camera.starts_with("/"))
                throw UsageError(arg + " needs an absolute prim path such as /World/Camera");
        } else if (arg == "-j" || arg == "--threads") {
            o.threads = parseNumber<int>(arg, cur.value(arg));
            if (o.threads < 0) throw UsageError(arg + " must be 0 (all cores) or more");
        } else if (arg == "--seed") {
            o.seed = parseNumber<std::uint64_t>(arg, cur.value(arg));
        } else if (arg == "--sampler") {
            const std::string name = cur.value(arg);
            o.sampler = samplerNamed(name);
            if (!o.sampler)
                throw UsageError("unknown sampler '" + name + "' (available: " + std::string(kSamplerNames) + ")");
        } else if (arg == "--integrator") {
            o.integrator = cur.value(arg);
            if (o.integrator != integrators::kAutomaticIntegrator && !integrators::findIntegrator(o.integrator))
                throw UsageError("unknown integrator '" + o.integrator + "' (available: " + integratorNames() + ")");
        } else if (arg == "--time-limit") {
            o.timeLimit = parseNumber<double>(arg, cur.value(arg));
            if (!(o.timeLimit >= 0.0) || !std::isfinite(o.timeLimit))
                throw UsageError("--time-limit must be >= 0 seconds");
        } else if (arg == "--target-error") {
            o.targetError = parseNumber<double>(arg, cur.value(arg));
            if (!(o.targetError >= 0.0) || !std::isfinite(o.targetError))
                throw UsageError("--target-error must be >= 0");
        } else if (arg == "--mean-spp") {
            o.meanSpp = parseNumber<double>(arg, cur.value(arg));
            if (!(o.meanSpp >= 1.0) || !std::isfinite(o.meanSpp)) throw UsageError("--mean-spp must be at least 1");
        } else if (arg == "--min-spp") {
            o.minSpp = parseNumber<int>(arg, cur.value(arg));
            if (o.minSpp < 2) throw UsageError("--min-spp must be at least 2");
        } else if (arg == "--max-depth") {
            o.maxDepth = parseNumber<int>(arg, cur.value(arg));
            if (o.maxDepth < 0) throw UsageError("--max-depth must be >= 0");
        } else if (arg == "--dicing-rate") {
            dicingRateGiven = true;
            o.dicingRate = parseNumber<double>(arg, cur.value(arg));
            if (!(o.dicingRate > 0.0) || !std::isfinite(o.dicingRate))
                throw UsageError("--dicing-rate must be > 0 pixels");
        } else if (arg == "--subdiv-level") {
            o.subdivLevel = parseNumber<int>(arg, cur.value(arg));
            if (*o.subdivLevel < 0 || *o.subdivLevel > kMaxSubdivLevel)
                throw UsageError("--subdiv-level must be between 0 and " + std::to_string(kMaxSubdivLevel));
        } else if (arg == "--denoise") {
            o.denoise = true;
        } else if (arg == "--denoise-layers") {
            o.denoise = o.denoiseLayers = true;
        } else if (arg == "--denoise-buffers") {
            o.denoiseBuffers = true;
        } else if (arg == "--lpe") {
            o.lightPaths.push_back(parseLightPathOption(cur.value(arg)));
        } else if (arg == "--cryptomatte") {
            o.cryptomatte = parseCryptomatteOption(splitList(cur.value(arg)));
        } else if (arg == "--cryptomatte-depth") {
            o.cryptomatteDepth = parseNumber<int>(arg, cur.value(arg));
            if (o.cryptomatteDepth < 1 || o.cryptomatteDepth > kMaxCryptomatteDepth)
                throw UsageError("--cryptomatte-depth must be between 1 and " + std::to_string(kMaxCryptomatteDepth));
        } else if (arg == "--subsurface") {
            o.subsurface = cur.value(arg);
            if (!render::subsurfaceMethodNamed(o.subsurface))
                throw UsageError("--subsurface must be " + std::string(render::kSubsurfaceMethodNames));
        } else if (arg == "--dome-sampling") {
            const std::string name = cur.value(arg);
            o.domeSampling = render::domeLightSamplingNamed(name);
            if (!o.domeSampling)
                throw UsageError("--dome-sampling must be " + std::string(render::kDomeLightSamplingNames) + ", not '" +
                                 name + "'");
        } else if (arg == "-f" || arg == "--frame") {
            o.frame = parseNumber<double>(arg, cur.value(arg));
            if (!std::isfinite(*o.frame)) throw UsageError(arg + " must be a finite time code");
        } else if (arg == "-n" || arg == "--frame-count") {
            o.frameCount = parseNumber<int>(arg, cur.value(arg));
            if (o.frameCount < 1) throw UsageError(arg + " must be at least 1");
        } else if (arg == "-i" || arg == "--frame-inc") {
            o.frameIncrement = parseNumber<double>(arg, cur.value(arg));
            if (!(o.frameIncrement > 0.0) || !std::isfinite(o.frameIncrement)) throw UsageError(arg + " must be > 0");
        } else if (arg == "--make-output-path") {
            o.makeOutputPath = true;
        } else if (arg == "--summary") {
            o.summary = cur.value(arg);
        } else if (arg == "--checkpoint" || arg == "--snapshot") {
            const double seconds = parseNumber<double>(arg, cur.value(arg));
            if (!(seconds >= 0.0) || !std::isfinite(seconds)) throw UsageError(arg + " must be >= 0 seconds");
            (arg == "--checkpoint" ? o.checkpointSeconds : o.snapshotSeconds) = seconds;
        } else if (arg == "--resume") {
            o.resume = true;
        } else if (arg == "--tile-count") {
            const int x = parseNumber<int>(arg, cur.value(arg)), y = parseNumber<int>(arg, cur.value(arg));
            if (x < 1 || y < 1 || x > 1024 || y > 1024) throw UsageError("--tile-count needs X and Y from 1 to 1024");
            o.tileCount = {x, y};
        } else if (arg == "--tile-index") {
            o.tileIndex = parseNumber<int>(arg, cur.value(arg));
        } else if (arg == "--tile-suffix") {
            o.tileSuffix = cur.value(arg);
        } else if (arg == "-s" || arg == "--settings") {
            o.settings = cur.value(arg);
        } else if (arg == "--variant") {
            o.variants.push_back(parseVariantSelection(cur.value(arg)));
        } else if (arg == "--set") {
            o.overrides.push_back(parseAttributeOverride(cur.value(arg)));
        } else if (arg == "-V" || (arg.starts_with("-V") && arg.size() > 2)) {
            o.progress = parseVerbosity(arg == "-V" ? cur.value(arg) : arg.substr(2));
        } else if (arg == "--allow-missing") {
            o.allowMissing = true;
        } else if (arg == "--strict") {
            o.strict = true;
        } else if (arg == "--no-default-light") {
            o.defaultLight = false;
        } else if (arg == "--no-motion-blur") {
            o.motionBlur = false;
        } else if (arg == "--purpose") {
            o.purposes = splitList(cur.value(arg));
            try {
                delegate::IncludedPurposes::fromNames(*o.purposes);
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--purpose: ") + e.what());
            }
        } else if (arg == "--complexity") {
            complexity = cur.value(arg);
        } else if (const integrators::IntegratorParameter* p =
                       arg.starts_with("--") ? findIntegratorParameter(arg.substr(2)) : nullptr) {
            const double value = parseNumber<double>(arg, cur.value(arg));
            if (const std::string why = parameterProblem(*p, value); !why.empty()) throw UsageError(arg + " " + why);
            o.integratorParameters[p->option] = value;
        } else {
            takeScene(arg, o.scene);
        }
    }
    applyComplexity(complexity, dicingRateGiven, o);
    if (o.tileCount && (o.tileIndex < 0 || o.tileIndex >= o.tileCount->first * o.tileCount->second))
        throw UsageError("--tile-index must be from 0 to " +
                         std::to_string(o.tileCount->first * o.tileCount->second - 1));
    if (!o.tileCount && o.tileIndex != 0) throw UsageError("--tile-index needs --tile-count");
    if (o.meanSpp > 0.0 && o.targetError > 0.0) throw UsageError("--mean-spp and --target-error: choose one");
    if (o.meanSpp > 0.0 && o.tileCount)
        throw UsageError(
            "--mean-spp spreads one budget over the whole image: it cannot render a tile (use --target-error)");
    if (o.meanSpp > 0.0 && o.spp && *o.spp < o.meanSpp) throw UsageError("--mean-spp must be at most --spp");
    if (o.scene.empty()) throw UsageError("no scene file given");
    o.loadRules = load.rules();
    return o;
}

std::string integratorNames() {
    std::string names;
    for (const auto& i : integrators::integratorRegistry()) names += (names.empty() ? "" : ", ") + i.name;
    return names + ", " + integrators::kAutomaticIntegrator;
}

std::string usageText() {
    std::string integratorList;
    for (const auto& i : integrators::integratorRegistry())
        integratorList += "                        " + i.name + "  " + i.pathClasses + "  " + i.description + "\n";
    return "usage: fluence render SCENE.usda [options]\n"
           "       fluence info SCENE.usda [--variant /Prim:set=sel]... [-s /Render/Settings]\n"
           "                               [--load /Prim]... [--unload /Prim]... [--no-payloads] [--strict]\n"
           "       fluence cat LAYER [-o OUT.usda] [--flatten [--variant /Prim:set=sel]... [--load /Prim]...\n"
           "                         [--unload /Prim]... [--no-payloads]]\n"
           "                               the layer as USDA text (stdout without -o); --flatten: the composed\n"
           "                               stage as one layer, like usdcat --flatten\n"
           "       fluence assemble -o OUT.exr TILE.exr...   merge tiles into the image rendered in one piece\n"
           "       fluence denoise IN.exr -o OUT.exr [--denoise-layers] [-j N]\n"
           "                               denoise an image rendered with --denoise or --denoise-buffers (or\n"
           "                               assembled from such tiles): RGB denoised, the noisy beauty kept\n"
           "                               as noisy.R/G/B\n"
           "       fluence farm submit SCENE [--frames A-B[xK]] [--tiles X Y] [--backend slurm|local]\n"
           "                               [--output-dir DIR] [--jobs N] [-j N] [-- RENDER OPTIONS...]\n"
           "                               one task per frame and tile, run by Slurm (default when sbatch is in\n"
           "                               PATH) or here, N at a time; tiles merged into DIR/NAME[.0001].exr\n"
           "       fluence farm status DIR | resume DIR | merge DIR\n"
           "                               per task done/queued/running/failed/missing; redo the failed and\n"
           "                               missing tasks; assemble the images whose tiles are all done\n"
           "       fluence review PATH... [--port N] [--bind ADDR] [--open] [--static OUT_DIR]\n"
           "                               a colour-managed review page of EXR files, folders and frame sequences\n"
           "                               (name.$F4.exr, name.####.exr) in a browser: every layer under the OCIO\n"
           "                               display/view/look of the render's config, exposure, gamma, A/B wipe;\n"
           "                               served on 127.0.0.1 at a free port (the URL is printed) until Ctrl-C,\n"
           "                               or written to OUT_DIR as files that open from disk\n"
           "       fluence --help | --version\n"
           "\n"
           "`render` renders a USD scene to a multi-channel OpenEXR image (beauty RGBA in linear Rec.709,\n"
           "plus albedo, N, Z and sampleCount AOVs). `info` prints the composed prim tree, the cameras,\n"
           "lights, materials, volumes and render settings, the classes of light paths the scene can\n"
           "produce and those each integrator misses, every asset path with whether it resolves, and the\n"
           "malformed prims a render leaves out (with --strict, `info` exits 3 when there is one).\n"
           "\n"
           "options:\n"
           "  -o, --output FILE.exr   output image (default: the render product's productName, else SCENE's\n"
           "                          name with .exr, in the current folder); frame tokens $F, $F4, $FF,\n"
           "                          %04d expand to the frame (several frames need one)\n"
           "      --preview FILE.png  also write an sRGB preview through the OCIO display/view transform\n"
           "      --spp N             samples per pixel (default 64)\n"
           "  -r, --res W H           resolution (default: the render settings', else 640 480)\n"
           "  -c, --camera PATH       camera prim (default: the render settings' camera, else the first Camera)\n"
           "  -s, --settings PATH     RenderSettings prim (default: the stage's renderSettingsPrimPath)\n"
           "      --variant P:SET=SEL select variant SEL of variant set SET on prim P (repeatable)\n"
           "      --load PATH         load the payloads of prim PATH and its descendants (repeatable)\n"
           "      --unload PATH       leave out the payloads of prim PATH and its descendants (repeatable);\n"
           "                          the nearest prim's --load/--unload wins\n"
           "      --no-payloads       load no payloads but those --load names (and the prims above them)\n"
           "      --set [T ]P.A=V     override attribute A of prim P with the USDA value V, as a session layer\n"
           "                          would (repeatable); T, the type, when P has no A: --set 'float "
           "/L.inputs:exposure=1'\n"
           "      --purpose LIST      purposes to render, e.g. default,render (default: the render settings'\n"
           "                          includedPurposes, else default,render; husk's `geometry` is `default`)\n"
           "      --complexity LEVEL  subdivision surfaces: lowest (the cage), low, medium (1 and 2 uniform\n"
           "                          levels), high (2-pixel dicing), veryhigh (default: --dicing-rate)\n"
           "  -V LEVEL                progress: 0 none; a (as in -V a, -V2a) ALF_PROGRESS n% lines on stdout even on "
           "a\n"
           "                          terminal (default: a bar on a terminal, those lines otherwise)\n"
           "      --allow-missing     render even when layers, textures, IES profiles or VDB files are missing (each "
           "a\n"
           "                          warning); without it a missing asset is an error (exit 4), and a layer\n"
           "                          that needs a file format plugin (Alembic, Draco) is one (exit 3)\n"
           "      --strict            a malformed prim (face counts that do not match the indices, a GeomSubset\n"
           "                          index out of range, ...) is an error (exit 3); without it the prim is\n"
           "                          skipped with a warning naming it and the reason, and the rest rendered\n"
           "                          (in an instance's prototype, only that prim); a visibility or purpose\n"
           "                          that is not a token is read as not authored, as USD reads it, with a\n"
           "                          warning (an error with --strict)\n"
           "      --no-default-light  render a scene in which nothing emits (no light, emissive surface or\n"
           "                          volume) black; by default it is lit, with a warning, by a distant light\n"
           "                          along the camera's view and a dim dome, as usdview does; the dome is\n"
           "                          not the background, which stays black with alpha 0 (also\n"
           "                          fluence:defaultLight = false on the render settings)\n"
           "      --no-motion-blur    render every camera's shutter as an instant (as disableMotionBlur on\n"
           "                          the render settings does); by default what moves while the shutter is\n"
           "                          open (shutter:open to shutter:close, time codes around the frame) blurs\n"
           "  -f, --frame F           time code to render (default: the stage's startTimeCode, else none: each\n"
           "                          time-sampled attribute takes its earliest sample, as in Hydra)\n"
           "  -n, --frame-count N     render N frames from --frame on, the stage read once (default 1)\n"
           "  -i, --frame-inc K       time codes between those frames (default 1)\n"
           "      --make-output-path  create the output's folders\n"
           "      --summary FILE.json write what the render did (settings, per-stage times, peak memory,\n"
           "                          samples, rays, warnings, exit code), whether it succeeded or not\n"
           "      --checkpoint SECS   every SECS seconds (0: every pass), at a pass boundary, save the render's\n"
           "                          state to OUTPUT.checkpoint (removed once the image is written)\n"
           "      --resume            go on from OUTPUT.checkpoint if there is one (else render from the start);\n"
           "                          the image is bit-identical to an uninterrupted render's; a checkpoint of\n"
           "                          another render (scene, seed, resolution, ...) is refused (exit 2); a frame\n"
           "                          this same render already wrote (no checkpoint left) is skipped\n"
           "      --snapshot SECS     every SECS seconds (0: every pass), and on SIGUSR1, write the image so\n"
           "                          far to STEM.snapshot.exr beside the output (removed once the image is written)\n"
           "      --tile-count X Y    render one of X x Y tiles of the image (--tile-index N, 0 to X*Y-1, row\n"
           "      --tile-index N      by row from the top left) to the output with --tile-suffix (default\n"
           "      --tile-suffix FMT   _tile$T, $T the index) before its extension; `fluence assemble` merges them\n"
           "  -j, --threads N         worker threads (default 0: every core)\n"
           "      --seed S            random seed (default 0); same seed and spp give a bit-identical image\n"
           "      --sampler NAME      the camera samples' random numbers (default: the render settings'\n"
           "                          fluence:sampler, else sobol): sobol (Owen-scrambled Sobol, each pixel's\n"
           "                          samples stratified: less noise at the same spp) or independent (hashed)\n"
           "      --integrator NAME   solution method (default: the render settings' fluence:integrator, else\n"
           "                          " +
           std::string(kDefaultIntegrator) + "):\n" + integratorList +
           "                        auto  the cheapest of direct, whitted, path, sppm that covers the scene's path\n"
           "                              classes (fluence info lists them); the render log says which and why\n"
           "  method parameters (the option wins over the render settings' attribute):\n" +
           integratorParameterUsage() +
           "      --max-depth N       maximum scattering events per path (default 64)\n"
           "      --dicing-rate PX    subdivision surfaces and displaced meshes: target micro-edge length in\n"
           "                          pixels (default 1)\n"
           "      --subdiv-level N    subdivision surfaces: uniform refinement, 4^N triangle pairs per quad,\n"
           "                          instead of camera-driven dicing (for comparisons); displaced polygon\n"
           "                          meshes: 2^N segments per edge\n"
           "      --subsurface METHOD subsurface scattering of every material: randomwalk, randomwalk_guided\n"
           "                          (steps guided to the surface: less noise for the time) or diffusion\n"
           "                          (default: each material's subsurface_type, else randomwalk_guided)\n"
           "      --dome-sampling P   auto: next-event estimation leaves a dome light without texture (constant\n"
           "                          radiance) to BSDF and phase sampling, as Cycles does; always: it samples\n"
           "                          it as any light (default: the render settings' fluence:domeLightSampling,\n"
           "                          else auto)\n"
           "      --time-limit SECS   stop starting new sample passes after SECS seconds (0: no limit)\n"
           "      --target-error E    adaptive sampling to a noise level: each pixel stops once the relative\n"
           "                          standard error of its mean (estimated from the halves of its samples over\n"
           "                          its 5x5 neighbourhood) is at most E (e.g. 0.02), after --min-spp and at\n"
           "                          most --spp samples; tiles then have edges on multiples of 8 pixels\n"
           "      --mean-spp N        adaptive sampling to a budget: the cost of N uniform samples per pixel\n"
           "                          (about the CPU time of --spp N: each sample's rays, medium lookups\n"
           "                          and walk steps are counted), each pixel's share chosen to lower the\n"
           "                          image's relative error most for its cost; at most --spp per pixel\n"
           "                          (default 8 N); not with tiles\n"
           "      --min-spp N         samples every pixel takes before adaptive sampling may stop it (default 16)\n"
           "      --lpe NAME=EXPR     a light path expression AOV: the light of the paths EXPR matches, as the\n"
           "                          EXR layer NAME (repeatable; also RenderVars with sourceType \"lpe\");\n"
           "                          e.g. --lpe diffuse='C<RD>.*L' --lpe specular='C<R[GS]>.*L'; path, bdpt,\n"
           "                          sppm (expressions of at most 64 automaton states)\n"
           "      --denoise           denoise the beauty (feature-guided regression on the albedo, N and Z\n"
           "                          AOVs and the two half images): RGB denoised, the noisy beauty kept as\n"
           "                          noisy.R/G/B, the half images half0/half1 and variance.R/G/B written too;\n"
           "                          a tile keeps only the buffers (denoise the assembled image)\n"
           "      --denoise-layers    --denoise, and each --lpe layer denoised on its own (NAME_noisy kept)\n"
           "      --denoise-buffers   write half0, half1 and variance only, for 'fluence denoise' later\n"
           "      --cryptomatte L,... Cryptomatte ID layers: object (CryptoObject), material (CryptoMaterial);\n"
           "                          also RenderVars with sourceType \"raw\" and sourceName "
           "CryptoObject/CryptoMaterial\n"
           "      --cryptomatte-depth N  ranks (id, coverage) kept per pixel and layer (default 6)\n"
           "\n"
           "environment:\n"
           "  OCIO                    an OpenColorIO config to use instead of Fluence's built-in one\n"
           "\n"
           "exit codes:\n"
           "  0 image written   1 internal error   2 usage error   3 scene error (syntax or semantic; a layer\n"
           "  in a format that needs a USD plugin Fluence does not have: Alembic .abc, Draco .drc)\n"
           "  4 missing input (scene file, asset)   5 output could not be written   6 colour configuration error\n"
           "  7 interrupted (SIGTERM or SIGINT: the render stops between tiles and writes nothing)\n"
           "  farm: 8 work still queued or running   9 tasks failed or missing (farm resume)   10 scheduler error\n";
}

}  // namespace fluence::app
