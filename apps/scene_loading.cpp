#include "apps/scene_loading.h"

#include <cstdio>
#include <filesystem>

#include "delegate/render_index.h"
#include "scene/usda_parser.h"
#include "scene/usdz_package.h"

namespace fluence::app {

void printError(const std::string& message) { std::fprintf(stderr, "fluence: error: %s\n", message.c_str()); }

int openStage(const std::string& path, const usd::StageOptions& options, WarningLog& warnings,
              std::unique_ptr<usd::Stage>& stage, MissingAssets missing) {
    if (!(usd::splitPackagePath(path) ? usd::packagedEntryExists(path) : std::filesystem::exists(path))) {
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
    // warned above, and are errors too when missing assets are.
    std::size_t missingCount = 0;
    for (const usd::AssetReference& a : stage->assetReferences()) {
        if (a.exists) continue;
        const bool arc = a.property == "subLayers" || a.property == "references" || a.property == "payload" || a.property == "clips";
        // What the render reads: layers, shader and light inputs (textures), volume field files.
        // Other asset-valued attributes (model:cardTexture*, a SpatialAudio's filePath,
        // documentation) only warn.
        const usd::PrimSpec* prim = a.primPath.empty() ? nullptr : stage->prim(a.primPath);
        const bool fieldFile = a.property == "filePath" && prim && delegate::isFieldAssetType(prim->typeName);
        const bool rendered = arc || a.property.starts_with("inputs:") || fieldFile;
        const std::string where = a.primPath.empty() ? a.location.str() : a.primPath + "." + a.property;
        if (missing == MissingAssets::Fail && rendered) {
            printError(where + ": missing asset " + a.resolved + " (authored as @" + a.authored + "@)");
            ++missingCount;
        } else if (!arc) {
            warnings(where, "asset not found: " + a.resolved + " (authored as @" + a.authored + "@)");
        }
    }
    if (missingCount > 0) {
        printError(std::to_string(missingCount) + (missingCount == 1 ? " asset is" : " assets are") +
                   " missing; --allow-missing renders without " + (missingCount == 1 ? "it" : "them"));
        return kExitMissingInput;
    }
    return kExitOk;
}

}  // namespace fluence::app
