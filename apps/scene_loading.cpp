#include "apps/scene_loading.h"

#include <cstdio>
#include <filesystem>

#include "scene/usda_parser.h"

namespace fluence::app {

void printError(const std::string& message) { std::fprintf(stderr, "fluence: error: %s\n", message.c_str()); }

int openStage(const std::string& path, const usd::StageOptions& options, WarningLog& warnings,
              std::unique_ptr<usd::Stage>& stage) {
    if (!std::filesystem::exists(path)) {
        printError("scene file not found: " + path);
        return kExitMissingInput;
    }
    try {
        stage = usd::Stage::open(path, options);
    } catch (const usd::FileError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const usd::ParseError& e) {
        printError(e.what());
        return kExitScene;
    }
    for (const usd::CompositionWarning& w : stage->warnings())
        warnings(w.location.file.empty() ? w.primPath : w.location.str() + (w.primPath.empty() ? "" : ": " + w.primPath),
                 w.message);
    // Missing assets (textures, VDBs) are named; arcs and clips that could not be followed were
    // warned above.
    for (const usd::AssetReference& a : stage->assetReferences())
        if (!a.exists && a.property != "subLayers" && a.property != "references" && a.property != "payload" &&
            a.property != "clips")
            warnings(a.primPath + "." + a.property, "asset not found: " + a.resolved + " (authored as @" + a.authored + "@)");
    return kExitOk;
}

}  // namespace fluence::app
