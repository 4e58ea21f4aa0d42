// The plain types of the stage's composition API (options in: variant selections and payload
// load rules; warnings and asset references out) and the collector the composition code reports
// into.
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "scene/layer.h"
#include "scene/load_rules.h"

namespace fluence::usd {

// A variant selection made from outside the scene (`--variant /Prim/Path:set=selection`). It
// overrides the selections authored for that prim.
struct VariantSelection {
    std::string primPath;
    std::string variantSet;
    std::string selection;
};

struct StageOptions {
    std::vector<VariantSelection> variantSelections;
    LoadRules loadRules;  // which payloads are included (all by default)
};

// Something composition could not honour; composition went on without it. `location` is where
// the offending arc or value was authored (empty for problems with StageOptions).
struct CompositionWarning {
    std::string message;
    SourceLocation location;
    std::string primPath;
};

// One asset path used by the composed stage: an asset-valued attribute (property = its name) or
// an arc target or value clip that could not be used (property = "subLayers", "references",
// "payload" or "clips").
struct AssetReference {
    std::string primPath;
    std::string property;
    std::string authored;  // as written in the layer
    std::string resolved;  // anchored at the authoring layer's directory, lexically normalized
    bool exists = false;
    SourceLocation location;
};

// Collects warnings (each reported once: a repeat with the same message and location is dropped)
// and the arc targets that could not be resolved.
class CompositionLog {
public:
    void warn(std::string message, SourceLocation location, std::string primPath) {
        if (!seen_.emplace(message, location.str()).second) return;
        warnings_.push_back({std::move(message), std::move(location), std::move(primPath)});
    }
    // A problem with the asset `asset` (a resolved layer path) met at one more site: the first
    // site's warning stands for all of them, and says how many prims (and layers, for sublayers)
    // name the asset: "... (referenced by 548 prims)".
    void warnAboutAsset(const std::string& asset, std::string message, SourceLocation location, std::string primPath) {
        auto [it, first] = assetWarnings_.try_emplace(asset);
        AssetWarning& w = it->second;
        (primPath.empty() ? w.layers : w.prims).insert(primPath.empty() ? location.file : primPath);
        if (first) {
            w.index = warnings_.size();
            w.message = message;
            warnings_.push_back({std::move(message), std::move(location), std::move(primPath)});
            return;
        }
        if (w.prims.size() + w.layers.size() > 1)
            warnings_[w.index].message = w.message + " (referenced by " + w.sites() + ")";
    }
    void unresolvedArc(AssetReference reference) { unresolved_.push_back(std::move(reference)); }

    const std::vector<CompositionWarning>& warnings() const { return warnings_; }
    const std::vector<AssetReference>& unresolvedArcs() const { return unresolved_; }

private:
    struct AssetWarning {
        std::size_t index = 0;  // into warnings_
        std::string message;    // as the first site gave it
        std::set<std::string> prims, layers;
        std::string sites() const {
            auto counted = [](std::size_t n, const char* what) {
                return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
            };
            if (layers.empty()) return counted(prims.size(), "prim");
            if (prims.empty()) return counted(layers.size(), "layer");
            return counted(prims.size(), "prim") + " and " + counted(layers.size(), "layer");
        }
    };

    std::vector<CompositionWarning> warnings_;
    std::map<std::string, AssetWarning> assetWarnings_;  // by asset
    std::vector<AssetReference> unresolved_;
    std::set<std::pair<std::string, std::string>> seen_;
};

}  // namespace fluence::usd
