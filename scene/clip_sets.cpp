// A prim's clip sets from its `clips` and `clipSets` metadata (scene/value_clips.h), after USD's
// Usd_ComputeClipSetDefinitionsForPrimIndex and Usd_ClipSet.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "scene/asset_path.h"
#include "scene/clip_template.h"
#include "scene/list_op.h"
#include "scene/namespace_remap.h"
#include "scene/prim_composer.h"
#include "scene/value_clips.h"

namespace fluence::usd::detail {

namespace {

// UsdTimeCode::SafeStep(): how far before a jump its left side is moved.
constexpr double kSafeStep = std::numeric_limits<double>::epsilon() * 1e6 * 10.0 * 2.0;

using Pairs = std::vector<std::pair<double, double>>;

// A clip set's metadata as composed so far.
struct Composed {
    Value info;  // the set's dictionary
    bool anchored = false;
    int anchorNode = -1;
    int anchorRank = 0;
    int anchorLayer = 0;
    LayerOffset anchorOffset;
    SourceLocation location;
    std::size_t order = 0;  // position in the anchoring node's composed clipSets list
};

// `value` ("active", "times": (stage time, x) pairs) as pairs, or nullopt.
std::optional<Pairs> pairsOf(const Value* value) {
    if (!value || !value->isNumeric() || value->components != 2) return std::nullopt;
    Pairs out;
    for (std::size_t i = 0; i + 1 < value->numbers.size(); i += 2)
        out.emplace_back(value->numbers[i], value->numbers[i + 1]);
    return out;
}

// The set's dictionary with the stage times of its `active` and `times` moved by `offset`.
Value offsetTimes(const Value& info, const LayerOffset& offset) {
    if (offset.isIdentity() || !info.dictionary) return info;
    auto entries = std::make_shared<Dictionary>(*info.dictionary);
    for (auto& [key, value] : *entries) {
        if ((key != "active" && key != "times") || !pairsOf(&value)) continue;
        std::vector<double> numbers = value.numbers;
        for (std::size_t i = 0; i < numbers.size(); i += 2) numbers[i] = offset.apply(numbers[i]);
        value.numbers = std::move(numbers);
    }
    Value out = info;
    out.dictionary = std::move(entries);
    return out;
}

// The clip sets of one node, weakest layer first (USD's _ResolveClipSetsInNode), keyed by name;
// sets that `clipSets` leaves out are dropped.
std::map<std::string, Composed> composeNode(const PrimIndex& index, int n, CompositionLog& log) {
    const IndexNode& node = index.nodes()[n];
    std::map<std::string, Composed> sets;
    std::vector<SpecListEdits<std::string>> listed;  // strongest first: each layer's clipSets, then its clips
    for (auto spec = node.specs.rbegin(); spec != node.specs.rend(); ++spec) {
        const auto& [layer, ref] = *spec;
        LayerOffset offset = node.offset.after(node.stack->layers[static_cast<std::size_t>(layer)].offset);
        SpecListEdits<std::string> clipSets, named;
        for (const MetadataEntry& entry : ref.metadata()) {
            if (entry.key == "clipSets") clipSets.push_back({entry.op, entry.value.strings});
            if (entry.key != "clips" || !entry.value.dictionary) continue;
            std::vector<std::string> names;
            for (const auto& [name, info] : *entry.value.dictionary) {
                if (name.empty() || info.kind != ValueKind::Dictionary) {
                    log.warn("clip set '" + name + "' ignored: a clip set is a named dictionary", entry.location,
                             index.path());
                    continue;
                }
                Composed& set = sets[name];
                if (info.find("assetPaths") || info.find("templateAssetPath")) {
                    set.anchored = true;
                    set.anchorLayer = layer;
                    set.anchorOffset = offset;
                    set.location = entry.location;
                }
                set.info = mergeDictionaries(set.info, offsetTimes(info, offset));
                names.push_back(name);
            }
            std::sort(names.begin(), names.end());
            named.push_back({ListOpKind::Add, std::move(names)});
        }
        listed.insert(listed.begin(), std::move(named));
        listed.insert(listed.begin(), std::move(clipSets));
    }
    std::vector<std::string> order = composeListEdits(listed, std::equal_to<>());
    for (auto it = sets.begin(); it != sets.end();) {
        auto at = std::find(order.begin(), order.end(), it->first);
        if (at == order.end()) {
            it = sets.erase(it);
            continue;
        }
        it->second.order = static_cast<std::size_t>(at - order.begin());
        ++it;
    }
    return sets;
}

// Why a set's explicit metadata is unusable ("" when it is fine; USD's _ValidateClipFields).
std::string problemOf(const std::string& clipPrim, const std::vector<ClipAsset>& assets, const Pairs& active,
                      const std::optional<Pairs>& times) {
    if (clipPrim.size() < 2 || clipPrim.front() != '/' || clipPrim.find_first_of(".{}") != std::string::npos)
        return "primPath '" + clipPrim + "' is not an absolute prim path";
    if (std::any_of(assets.begin(), assets.end(), [](const ClipAsset& a) { return a.authored.empty(); }))
        return "an empty asset path in assetPaths";
    auto finite = [](const Pairs& pairs) {
        return std::all_of(pairs.begin(), pairs.end(),
                           [](const auto& p) { return std::isfinite(p.first) && std::isfinite(p.second); });
    };
    if (!finite(active) || !finite(times.value_or(Pairs{}))) return "active and times need finite numbers";
    std::map<double, double> starts;
    for (const auto& [stage, clip] : active) {
        if (!(clip >= 0 && clip < static_cast<double>(assets.size())))
            return "an active entry names no clip of assetPaths (" + std::to_string(assets.size()) + " clips)";
        if (!starts.emplace(stage, clip).second) return "two clips are active from one stage time";
    }
    std::map<double, int> seen;
    for (const auto& entry : times.value_or(Pairs{}))
        if (++seen[entry.first] > 2) return "more than two times entries share one stage time";
    return "";
}

class ClipSetBuilder {
public:
    ClipSetBuilder(const PrimIndex& index, LayerRegistry& registry, CompositionLog& log)
        : index_(index), registry_(registry), log_(log) {}

    std::shared_ptr<const ClipSet> build(const std::string& name, const Composed& composed) {
        const IndexNode& node = index_.nodes()[composed.anchorNode];
        const Layer& anchor = *node.stack->layers[static_cast<std::size_t>(composed.anchorLayer)].layer;
        location_ = composed.location;
        const Value& info = composed.info;
        auto text = [&](const char* key) {
            const Value* v = info.find(key);
            return v && v->isStringLike() ? v->asString() : std::nullopt;
        };
        auto number = [&](const char* key) {
            const Value* v = info.find(key);
            return v && v->isNumeric() ? v->asDouble() : std::nullopt;
        };

        std::vector<ClipAsset> assets;
        std::optional<Pairs> active, times;
        if (const Value* paths = info.find("assetPaths"); paths && paths->kind == ValueKind::Asset) {
            for (const std::string& path : paths->strings)
                assets.push_back({path, anchorAssetPath(anchor.identifier, path)});
            active = pairsOf(info.find("active"));
            times = pairsOf(info.find("times"));
        } else if (auto pattern = text("templateAssetPath")) {
            auto stride = number("templateStride");
            auto start = number("templateStartTime");
            auto end = number("templateEndTime");
            if (!stride || !start || !end) return nullptr;
            std::string problem;
            std::optional<ClipTemplate> derived = deriveClipTemplate(*pattern, anchor.identifier, *start, *end, *stride,
                                                                     number("templateActiveOffset"), problem);
            if (!derived) return reject(name, problem);
            assets = std::move(derived->assets);
            active = std::move(derived->active);
            times = std::move(derived->times);
            for (auto* pairs : {&*active, &*times})
                for (auto& pair : *pairs) pair.first = composed.anchorOffset.apply(pair.first);
        }
        std::optional<std::string> clipPrim = text("primPath");
        if (!clipPrim || !active) return nullptr;  // incomplete: not a clip set (as in USD)
        if (std::string problem = problemOf(*clipPrim, assets, *active, times); !problem.empty())
            return reject(name, problem);
        if (active->empty()) return nullptr;  // an empty set blocks a weaker one

        auto set = std::make_shared<ClipSet>();
        set->name = name;
        set->stack = node.stack;
        set->sourcePrim = stripVariantSelections(node.path);
        set->anchorLayer = composed.anchorLayer;
        set->clipPrim = *clipPrim;
        set->interpolateMissing = number("interpolateMissingClipValues").value_or(0.0) != 0.0;
        if (const Value* manifest = info.find("manifestAssetPath"); manifest && manifest->kind == ValueKind::Asset) {
            std::string authored = manifest->asString().value_or("");
            set->generatedManifest = false;
            set->manifest = read("clip manifest", {authored, anchorAssetPath(anchor.identifier, authored)});
        }
        std::sort(active->begin(), active->end());
        for (std::size_t i = 0; i < active->size(); ++i) {
            const auto& [start, clip] = (*active)[i];
            bool first = i == 0, last = i + 1 == active->size();
            set->clips.push_back({read("clip", assets[static_cast<std::size_t>(clip)]), start,
                                  first ? std::numeric_limits<double>::lowest() : start,
                                  last ? std::numeric_limits<double>::max() : (*active)[i + 1].first});
        }
        set->times = mappings(times.value_or(Pairs{}));
        return set;
    }

private:
    std::shared_ptr<const ClipSet> reject(const std::string& name, const std::string& problem) {
        log_.warn("clip set '" + name + "' ignored: " + problem, location_, index_.path());
        return nullptr;
    }

    ClipLayer read(const char* what, const ClipAsset& asset) {
        const Layer* layer =
            registry_.layerFor(asset.resolved, {what, "clips", asset.authored, location_, index_.path()});
        return layer ? ClipLayer{layer, &registry_.specIndexOf(*layer)} : ClipLayer{};
    }

    // The `times` curve as USD keeps it: sorted by stage time (stably), the left point of each
    // jump moved a safe step earlier, and both ends repeated.
    static std::vector<ClipSet::TimeMapping> mappings(Pairs times) {
        std::stable_sort(times.begin(), times.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<ClipSet::TimeMapping> out;
        for (const auto& [stage, clip] : times) out.push_back({stage, clip, false});
        for (std::size_t i = 0; i + 1 < out.size(); ++i) {
            if (out[i].stage != out[i + 1].stage) continue;
            out[i].stage -= kSafeStep;
            out[i].jump = true;
        }
        if (!out.empty()) {
            ClipSet::TimeMapping first = out.front(), last = out.back();
            out.insert(out.begin(), first);
            out.push_back(last);
        }
        return out;
    }

    const PrimIndex& index_;
    LayerRegistry& registry_;
    CompositionLog& log_;
    SourceLocation location_;
};

}  // namespace

std::vector<std::shared_ptr<const ClipSet>> clipSetsOf(const PrimIndex& index, LayerRegistry& registry,
                                                       CompositionLog& log) {
    auto authorsClips = [](const IndexNode& node) {
        return std::any_of(node.specs.begin(), node.specs.end(),
                           [](const auto& spec) { return findMetadata(spec.second.metadata(), "clips"); });
    };
    if (std::none_of(index.nodes().begin(), index.nodes().end(), authorsClips)) return {};
    // Nodes strongest first; the first anchor found wins, stronger dictionaries over weaker ones.
    std::map<std::string, Composed> composed;
    std::vector<int> order = index.strengthOrder();
    for (std::size_t rank = 0; rank < order.size(); ++rank) {
        int n = order[rank];
        if (index.nodes()[n].inert || index.nodes()[n].specs.empty()) continue;
        for (auto& [name, set] : composeNode(index, n, log)) {
            Composed& into = composed[name];
            if (!into.anchored && set.anchored) {
                into.anchored = true;
                into.anchorNode = n;
                into.anchorRank = static_cast<int>(rank);
                into.anchorLayer = set.anchorLayer;
                into.anchorOffset = set.anchorOffset;
                into.location = set.location;
                into.order = set.order;
            }
            into.info = into.info.dictionary ? mergeDictionaries(set.info, into.info) : set.info;
        }
    }
    std::vector<std::pair<std::string, const Composed*>> anchored;
    for (const auto& [name, set] : composed)
        if (set.anchored) anchored.emplace_back(name, &set);
    std::stable_sort(anchored.begin(), anchored.end(), [](const auto& a, const auto& b) {
        return std::tie(a.second->anchorRank, a.second->order) < std::tie(b.second->anchorRank, b.second->order);
    });
    std::vector<std::shared_ptr<const ClipSet>> sets;
    ClipSetBuilder builder(index, registry, log);
    for (const auto& [name, set] : anchored)
        if (auto built = builder.build(name, *set)) sets.push_back(std::move(built));
    return sets;
}

}  // namespace fluence::usd::detail
