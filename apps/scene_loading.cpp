#include "apps/scene_loading.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "delegate/render_index.h"
#include "scene/asset_values.h"
#include "scene/layer_file.h"
#include "scene/usda_parser.h"
#include "scene/usdz_package.h"

namespace fluence::app {

void printError(const std::string& message) { std::fprintf(stderr, "fluence: error: %s\n", message.c_str()); }

namespace {

// The references to one asset file: the first (in the stage's order) names them all.
struct AssetUse {
    const usd::AssetReference* first = nullptr;
    std::size_t count = 0;
    bool arc = false;          // a sublayer, reference, payload or clip names it
    bool rendered = false;     // the render reads it (see checkAssets)
    bool needsPlugin = false;  // an arc names it, and its format needs a plugin Fluence does not have
};

// A volume field prim's filePath (OpenVDBAsset, Field3DAsset), which the render reads.
bool isFieldFile(const usd::Stage& stage, const usd::AssetReference& a) {
    if (a.property != "filePath" || a.primPath.empty()) return false;
    const usd::PrimSpec* prim = stage.prim(a.primPath);
    return prim && delegate::isFieldAssetType(prim->typeName);
}

// Whether asset-valued attributes read their assets at the frames rendered (see checkAssets): each
// attribute is resolved at the frames once, however many of the stage's asset references name it.
class AssetsReadAtFrames {
public:
    AssetsReadAtFrames(const usd::Stage& stage, const std::vector<double>& frames) : stage_(stage), frames_(frames) {}

    // Whether the attribute of reference `a` names its asset at one of the frames; true when there
    // are no frames, or `a` is not an attribute of a composed prim.
    bool reads(const usd::AssetReference& a) {
        if (frames_.empty()) return true;
        auto [it, inserted] = read_.try_emplace({a.primPath, a.property});
        if (inserted) it->second = readAssets(a);
        return !it->second || it->second->contains(a.resolved);
    }

private:
    // The resolved asset paths the attribute names at the frames; nullopt: not an attribute.
    std::optional<std::set<std::string>> readAssets(const usd::AssetReference& a) const {
        const usd::PrimSpec* prim = stage_.prim(a.primPath);
        const usd::AttributeSpec* attribute = prim ? prim->attribute(a.property) : nullptr;
        if (!attribute) return std::nullopt;
        std::set<std::string> read;
        for (double frame : frames_) {
            const std::optional<usd::Value> value = usd::Stage::resolve(*attribute, usd::renderReadTime(frame));
            // Composition anchors asset values in place (scene/prim_composer): they hold resolved paths.
            if (value)
                usd::anyAssetValue(*value, [&](const usd::Value& asset) {
                    read.insert(asset.strings.begin(), asset.strings.end());
                    return false;
                });
        }
        return read;
    }

    const usd::Stage& stage_;
    const std::vector<double>& frames_;
    std::map<std::pair<std::string, std::string>, std::optional<std::set<std::string>>> read_;
};

// What is wrong with an asset file the stage cannot use: an entry of a USDZ package that is there
// but cannot be read (compressed, encrypted) says so, naming the package and the entry; any other
// is `missing` followed by the file.
std::string assetProblem(const std::string& file, const std::string& missing) {
    if (usd::splitPackagePath(file) && usd::packagedEntryExists(file)) return usd::packagedEntryProblem(file);
    return missing + file;
}

}  // namespace

// Missing assets (textures, VDBs) are named, once per file with the number of references to it;
// arcs and clips that could not be followed were warned by composition (once per layer, with the
// number of prims naming it), and are errors too when missing assets are. An arc to a layer in a
// format that needs a plugin Fluence does not have (usd::missingFormatPlugin) is a scene error then.
int checkAssets(const usd::Stage& stage, WarningLog& warnings, MissingAssets missing,
                const std::vector<double>& frames) {
    std::vector<std::string> files;  // in the order first met
    std::map<std::string, AssetUse> uses;
    const std::vector<usd::AssetReference> references = stage.assetReferences();
    AssetsReadAtFrames readAtFrames(stage, frames);
    for (const usd::AssetReference& a : references) {
        const bool arc =
            a.property == "subLayers" || a.property == "references" || a.property == "payload" || a.property == "clips";
        const bool needsPlugin = arc && !usd::missingFormatPlugin(a.resolved).empty();
        if (a.exists && !needsPlugin) continue;
        auto [it, inserted] = uses.try_emplace(a.resolved);
        if (inserted) files.push_back(a.resolved);
        AssetUse& use = it->second;
        if (!use.first) use.first = &a;
        ++use.count;
        use.arc = use.arc || arc;
        use.needsPlugin = use.needsPlugin || needsPlugin;
        // What the render reads: layers, shader and light inputs (textures), volume field files,
        // at the frames rendered. Other asset-valued attributes (model:cardTexture*, a
        // SpatialAudio's filePath, documentation) only warn.
        use.rendered = use.rendered || arc ||
                       ((a.property.starts_with("inputs:") || isFieldFile(stage, a)) && readAtFrames.reads(a));
    }
    std::size_t missingCount = 0, unsupportedCount = 0;
    for (const std::string& file : files) {
        const AssetUse& use = uses.at(file);
        const usd::AssetReference& a = *use.first;
        const std::string where = a.primPath.empty() ? a.location.str() : a.primPath + "." + a.property;
        const std::string others =
            use.count > 1 ? " (and " + std::to_string(use.count - 1) + " more references to it)" : "";
        if (use.needsPlugin) {
            if (missing == MissingAssets::Fail) {
                printError(where + ": " + usd::unsupportedFormatMessage(file) + others);
                ++unsupportedCount;
            }
        } else if (missing == MissingAssets::Fail && use.rendered) {
            printError(where + ": " + assetProblem(file, "missing asset ") + " (authored as @" + a.authored + "@)" +
                       others);
            ++missingCount;
        } else if (!use.arc) {
            warnings(where, assetProblem(file, "asset not found: ") + " (authored as @" + a.authored + "@)" + others);
        }
    }
    if (missingCount > 0) {
        printError(std::to_string(missingCount) + (missingCount == 1 ? " asset is" : " assets are") +
                   " missing; --allow-missing renders without " + (missingCount == 1 ? "it" : "them"));
        return kExitMissingInput;
    }
    if (unsupportedCount > 0) {
        printError(std::to_string(unsupportedCount) + (unsupportedCount == 1 ? " layer needs" : " layers need") +
                   " a file format plugin Fluence does not have; --allow-missing renders without " +
                   (unsupportedCount == 1 ? "it" : "them"));
        return kExitScene;
    }
    return kExitOk;
}

int composeStage(const std::string& path, const usd::StageOptions& options, WarningLog& warnings,
                 std::unique_ptr<usd::Stage>& stage) {
    if (!(usd::splitPackagePath(path) ? usd::packagedEntryExists(path) : std::filesystem::exists(path))) {
        printError("scene file not found: " + path);
        return kExitMissingInput;
    }
    try {
        stage = usd::Stage::open(path, options);
    } catch (const usd::UnsupportedFormatError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const usd::FileError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const usd::ParseError& e) {
        printError(e.what());
        return kExitScene;
    }
    for (const usd::CompositionWarning& w : stage->warnings())
        warnings(
            w.location.file.empty() ? w.primPath : w.location.str() + (w.primPath.empty() ? "" : ": " + w.primPath),
            w.message);
    return kExitOk;
}

int openStage(const std::string& path, const usd::StageOptions& options, WarningLog& warnings,
              std::unique_ptr<usd::Stage>& stage) {
    if (int code = composeStage(path, options, warnings, stage); code != kExitOk) return code;
    return checkAssets(*stage, warnings, MissingAssets::Warn);
}

}  // namespace fluence::app
