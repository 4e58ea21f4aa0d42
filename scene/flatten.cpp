#include "scene/flatten.h"

#include <algorithm>
#include <set>
#include <string>

#include "scene/prim_composer.h"
#include "scene/prim_index.h"

namespace fluence::usd::detail {

namespace {

// Work budget: a few lines of text can describe arcs whose composed namespace grows exponentially
// (each prim referencing the one before from ten children). Composition stops, with a warning,
// once the composed prims outnumber the specs of all layers read by more than kPrimsPerSpec
// (plus kFreePrims); prim-index nodes are budgeted kNodesPerPrim times as many.
constexpr std::size_t kFreePrims = 100'000;
constexpr std::size_t kPrimsPerSpec = 1'000;
constexpr std::size_t kNodesPerPrim = 16;

bool flag(const PrimSpec& prim, const char* key, bool fallback) {
    const MetadataEntry* entry = findMetadata(prim.metadata, key);
    if (!entry) return fallback;
    if (auto number = entry->value.asDouble()) return *number != 0.0;
    if (auto word = entry->value.asString()) return *word == "true" || *word == "True";
    return fallback;
}

class Flattener {
public:
    Flattener(LayerRegistry& registry, CompositionLog& log, const StageOptions& options)
        : registry_(registry), log_(log), options_(options), indexer_(registry, log, options), composer_(assets_) {}

    FlattenResult run(const LayerStack& root) {
        const Layer& rootLayer = root.rootLayer();
        auto layer = std::make_unique<Layer>();
        layer->identifier = rootLayer.identifier;
        layer->header = rootLayer.header;
        for (const MetadataEntry& entry : rootLayer.metadata) {
            if (entry.key == "subLayers" || entry.key == "rootPrims" || entry.key == "relocates") continue;
            layer->metadata.push_back(entry);
            layer->metadata.back().value = anchorAssets(entry.value, rootLayer);
        }
        for (const std::string& name : composeRootPrimNames(root)) {
            if (stopped_) break;
            compose(indexer_.root(root, childPrimPath("/", name)), layer->rootPrims, false, {});
        }
        checkDefaultPrim(root, *layer);
        for (const VariantSelection& option : options_.variantSelections)
            if (!composedPaths_.contains(option.primPath))
                log_.warn("variant selection " + option.variantSet + "=" + option.selection + " for <" +
                              option.primPath + "> ignored: no such prim",
                          {}, option.primPath);
        return {std::move(layer), std::move(assets_)};
    }

    FlattenedPrim subtree(const LayerStack& root, const std::string& path) {
        std::vector<std::string> names = primNames(path);
        if (names.empty()) return {};
        // The ancestors' indices, each one's instanceable flag read off its composed spec.
        PrimIndex index = indexer_.root(root, childPrimPath("/", names.front()));
        bool belowInstance = false;
        ClipSets clips;
        for (std::size_t i = 1; i < names.size(); ++i) {
            std::vector<Opinion> opinions = opinionsOf(index);
            if (opinions.empty()) return {};
            std::unique_ptr<PrimSpec> ancestor = composer_.compose(index, opinions);
            if (!flag(*ancestor, "active", true)) return {};
            belowInstance = belowInstance || (flag(*ancestor, "instanceable", false) && index.hasArcs());
            clips = withOwnClips(index, clips);
            index = indexer_.child(index, names[i], belowInstance);
        }
        assets_.clear();
        std::vector<std::unique_ptr<PrimSpec>> prims;
        compose(index, prims, belowInstance, clips);
        return {prims.empty() ? nullptr : std::move(prims.front()), std::move(assets_)};
    }

private:
    // The clip sets for the prim of `index`: its own, then its ancestors' (`inherited`).
    ClipSets withOwnClips(const PrimIndex& index, const ClipSets& inherited) {
        ClipSets clips = clipSetsOf(index, registry_, log_);
        clips.insert(clips.end(), inherited.begin(), inherited.end());
        return clips;
    }

    void compose(const PrimIndex& index, std::vector<std::unique_ptr<PrimSpec>>& siblings, bool belowInstance,
                 const ClipSets& inheritedClips) {
        std::size_t budget = kFreePrims + kPrimsPerSpec * registry_.specCount();
        if (++prims_ > budget || indexer_.nodesMade() > kNodesPerPrim * budget) {
            if (!stopped_)
                log_.warn("composition stopped at " + std::to_string(prims_ - 1) + " prims: the composition arcs " +
                              "multiply the layers' " + std::to_string(registry_.specCount()) +
                              " prim specs more than " + std::to_string(kPrimsPerSpec) + "-fold",
                          {}, index.path());
            stopped_ = true;
            return;
        }
        std::vector<Opinion> opinions = opinionsOf(index);
        if (opinions.empty()) return;
        ClipSets clips = withOwnClips(index, inheritedClips);
        std::unique_ptr<PrimSpec> prim = composer_.compose(index, opinions, clips);
        if (!options_.variantSelections.empty()) composedPaths_.insert(prim->path);
        bool instance = flag(*prim, "instanceable", false) && index.hasArcs();
        if (instance)
            prim->metadata.push_back({"fluence:instancePrototype", ListOpKind::Explicit,
                                      Value::string("string", ValueKind::String, {index.instanceKey()}, false),
                                      prim->location});
        if (index.hasUnloadedPayload())
            prim->metadata.push_back({"fluence:unloadedPayload", ListOpKind::Explicit,
                                      Value::numeric("bool", {1}, 1, false), prim->location});
        if (flag(*prim, "active", true)) {
            for (const std::string& name : composeChildNames(index)) {
                if (stopped_) break;
                compose(indexer_.child(index, name, belowInstance || instance), prim->children,
                        belowInstance || instance, clips);
            }
        }
        siblings.push_back(std::move(prim));
    }

    void checkDefaultPrim(const LayerStack& root, const Layer& composed) {
        const MetadataEntry* entry = findMetadata(root.rootLayer().metadata, "defaultPrim");
        std::string path = root.defaultPrimPath();
        if (entry && !path.empty() && !composed.primAtPath(path))
            log_.warn("defaultPrim \"" + entry->value.asString().value_or("") + "\" names no prim of the stage",
                      entry->location, path);
    }

    LayerRegistry& registry_;
    CompositionLog& log_;
    const StageOptions& options_;
    std::vector<AssetReference> assets_;
    PrimIndexer indexer_;
    PrimComposer composer_;
    std::set<std::string> composedPaths_;  // kept only to check StageOptions' variant selections
    std::size_t prims_ = 0;
    bool stopped_ = false;
};

}  // namespace

FlattenedPrim flattenSubtree(const LayerStack& root, const std::string& path, LayerRegistry& registry,
                             CompositionLog& log, const StageOptions& options) {
    return Flattener(registry, log, options).subtree(root, path);
}

FlattenResult flatten(const LayerStack& root, LayerRegistry& registry, CompositionLog& log,
                      const StageOptions& options) {
    return Flattener(registry, log, options).run(root);
}

}  // namespace fluence::usd::detail
