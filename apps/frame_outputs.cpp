#include "apps/frame_outputs.h"

#include <filesystem>

#include "apps/frame_tokens.h"
#include "apps/scene_loading.h"
#include "integrators/adaptive_sampling.h"

namespace fluence::app {

namespace {

// The part of the image a render takes: the whole, or tile --tile-index of --tile-count. With
// adaptive sampling the tiles' edges are moved to the nearest multiple of its block size, where its
// decisions are independent (integrators/adaptive_sampling.h), so the tiles assemble into the
// one-piece render.
PixelWindow tileWindow(const RenderOptions& opt, std::pair<int, int> res) {
    if (!opt.tileCount) return {0, 0, res.first, res.second};
    const auto [columns, rows] = *opt.tileCount;
    const int step = opt.targetError > 0.0 ? integrators::AdaptiveSampling::kBlockSize : 1;
    auto edge = [step](int size, int i, int count) {
        return std::min(size, (size * i / count + step / 2) / step * step);
    };
    const int column = opt.tileIndex % columns, row = opt.tileIndex / columns;
    return {edge(res.first, column, columns), edge(res.second, row, rows), edge(res.first, column + 1, columns),
            edge(res.second, row + 1, rows)};
}

// `path` with the tile suffix ($T: the tile's index) before its extension.
std::string withTileSuffix(const std::string& path, std::string suffix, int index) {
    for (std::size_t at; (at = suffix.find("$T")) != std::string::npos;) suffix.replace(at, 2, std::to_string(index));
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

// Each product's file. Returns the exit code.
int productFiles(const RenderOptions& opt, double time, const PlannedRender& planned, std::vector<std::string>& files) {
    for (const PlannedProduct& p : planned.products) {
        if (opt.frameCount > 1 && !hasFrameToken(p.outputPattern)) {
            printError("rendering " + std::to_string(opt.frameCount) +
                       " frames needs a frame token ($F, $F4, %04d) in the output path '" + p.outputPattern + "'");
            return kExitUsage;
        }
        const std::string path = expandFrameTokens(p.outputPattern, time);
        files.push_back(opt.tileCount ? withTileSuffix(path, opt.tileSuffix, opt.tileIndex) : path);
    }
    return kExitOk;
}

// --make-output-path: the folders of every file written. Returns the exit code.
int makeOutputFolders(const FrameOutputs& outputs) {
    std::vector<std::string> made = outputs.files;
    made.push_back(outputs.preview);
    for (const std::string& path : made)
        if (std::filesystem::path folder = std::filesystem::path(path).parent_path();
            !path.empty() && !folder.empty()) {
            std::error_code error;
            std::filesystem::create_directories(folder, error);
            if (error) {
                printError("cannot make the output folder " + folder.string() + ": " + error.message());
                return kExitOutput;
            }
        }
    return kExitOk;
}

}  // namespace

int planFrameOutputs(const RenderOptions& opt, double time, const PlannedRender& planned, WarningLog& warnings,
                     FrameOutputs& outputs) {
    if (int code = productFiles(opt, time, planned, outputs.files); code != kExitOk) return code;
    const std::pair<int, int> res = planned.resolution;
    const PixelWindow wholeTile = tileWindow(opt, res);
    if (wholeTile.empty()) {
        printError("tile " + std::to_string(opt.tileIndex) + " of --tile-count " +
                   std::to_string(opt.tileCount->first) + " " + std::to_string(opt.tileCount->second) +
                   " has no pixels at " + std::to_string(res.first) + "x" + std::to_string(res.second));
        return kExitUsage;
    }
    outputs.window = wholeTile.intersect(planned.window());
    if (outputs.window.empty()) {
        warnings(planned.products.front().path,
                 "tile " + std::to_string(opt.tileIndex) + " holds no pixel of its data window; nothing written");
        return kExitOk;
    }
    outputs.preview = expandFrameTokens(opt.preview, time);
    return opt.makeOutputPath ? makeOutputFolders(outputs) : kExitOk;
}

}  // namespace fluence::app
