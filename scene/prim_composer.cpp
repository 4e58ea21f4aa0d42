#include "scene/prim_composer.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "scene/asset_path.h"
#include "scene/asset_values.h"
#include "scene/list_op.h"
#include "scene/namespace_remap.h"

namespace fluence::usd::detail {

namespace {

using Found = std::vector<std::pair<std::string, std::string>>;

// Prim metadata that composition consumes (arcs, variant selections, reorder statements, value
// clips).
const std::unordered_set<std::string> kCompositionFields = {"references",  "payload",     "payloads", "inherits",
                                                            "specializes", "variantSets", "variants", "nameChildren",
                                                            "properties",  "relocates",   "clips",    "clipSets"};

void anchorInPlace(Value& value, const Layer& layer, Found* found) {
    if (!anyAssetValue(value, [](const Value&) { return true; })) return;
    switch (value.kind) {
        case ValueKind::Asset:
            for (std::string& path : value.strings) {
                std::string resolved = anchorAssetPath(layer.identifier, path);
                if (found && !path.empty()) found->emplace_back(path, resolved);
                path = std::move(resolved);
            }
            break;
        case ValueKind::List:
            for (Value& item : value.items) anchorInPlace(item, layer, found);
            break;
        case ValueKind::Dictionary:
            if (value.dictionary) {
                auto copy = std::make_shared<Dictionary>(*value.dictionary);
                for (auto& entry : *copy) anchorInPlace(entry.second, layer, found);
                value.dictionary = std::move(copy);
            }
            break;
        default: break;
    }
}

struct MetadataOpinion {
    const Metadata* metadata;
    const Layer* layer;
};

// Per-key composition of metadata (see the file comment of prim_composer.h); `sources` strongest
// first.
Metadata composeMetadata(const std::vector<MetadataOpinion>& sources,
                         const std::function<bool(const std::string&)>& skip) {
    std::vector<std::string> keys;
    std::unordered_set<std::string> seen;
    for (auto it = sources.rbegin(); it != sources.rend(); ++it)
        for (const MetadataEntry& entry : *it->metadata)
            if (!skip(entry.key) && seen.insert(entry.key).second) keys.push_back(entry.key);

    Metadata out;
    for (const std::string& key : keys) {
        // This key's entries, per spec, strongest spec first.
        std::vector<std::pair<std::vector<const MetadataEntry*>, const Layer*>> perSpec;
        bool listOp = key == "apiSchemas", strings = true;
        for (const MetadataOpinion& source : sources) {
            std::vector<const MetadataEntry*> entries;
            for (const MetadataEntry& entry : *source.metadata) {
                if (entry.key != key) continue;
                entries.push_back(&entry);
                listOp = listOp || entry.op != ListOpKind::Explicit;
                strings = strings && (entry.value.isStringLike() || entry.value.isBlocked());
            }
            if (!entries.empty()) perSpec.emplace_back(std::move(entries), source.layer);
        }
        const MetadataEntry& strongest = *perSpec.front().first.back();
        if (listOp && strings) {
            std::vector<SpecListEdits<std::string>> edits;
            ValueKind kind = ValueKind::Token;
            for (const auto& [entries, layer] : perSpec) {
                SpecListEdits<std::string> specEdits;
                for (const MetadataEntry* entry : entries) {
                    specEdits.push_back({entry->op, entry->value.strings});
                    if (entry->value.isStringLike()) kind = entry->value.kind;
                }
                edits.push_back(std::move(specEdits));
            }
            out.push_back({key, ListOpKind::Explicit,
                           Value::string("", kind, composeListEdits(edits, std::equal_to<>()), true),
                           strongest.location});
        } else if (strongest.value.kind == ValueKind::Dictionary) {
            Value merged;
            for (auto it = perSpec.rbegin(); it != perSpec.rend(); ++it) {
                for (const MetadataEntry* entry : it->first) {
                    Value value = entry->value;
                    anchorInPlace(value, *it->second, nullptr);
                    merged = merged.kind == ValueKind::Dictionary && value.kind == ValueKind::Dictionary
                                 ? mergeDictionaries(merged, value)
                                 : value;
                }
            }
            out.push_back({key, strongest.op, std::move(merged), strongest.location});
        } else {
            MetadataEntry entry = strongest;
            anchorInPlace(entry.value, *perSpec.front().second, nullptr);
            out.push_back(std::move(entry));
        }
    }
    return out;
}

std::string lastName(const std::string& path) { return path.substr(path.rfind('/') + 1); }

}  // namespace

Value anchorAssets(const Value& value, const Layer& layer, Found* found) {
    Value out = value;
    anchorInPlace(out, layer, found);
    return out;
}

Value mergeDictionaries(const Value& weaker, const Value& stronger) {
    if (!weaker.dictionary || !stronger.dictionary) return stronger;
    auto merged = std::make_shared<Dictionary>(*weaker.dictionary);
    for (const auto& entry : *stronger.dictionary) {
        const std::string& key = entry.first;
        const Value& value = entry.second;
        auto it = std::find_if(merged->begin(), merged->end(), [&key](const auto& e) { return e.first == key; });
        if (it == merged->end())
            merged->emplace_back(key, value);
        else if (it->second.kind == ValueKind::Dictionary && value.kind == ValueKind::Dictionary)
            it->second = mergeDictionaries(it->second, value);
        else
            it->second = value;
    }
    Value out = stronger;
    out.dictionary = std::move(merged);
    return out;
}

std::vector<Opinion> opinionsOf(const PrimIndex& index) {
    std::vector<Opinion> opinions;
    std::vector<int> order = index.strengthOrder();
    for (std::size_t rank = 0; rank < order.size(); ++rank) {
        const IndexNode& node = index.nodes()[order[rank]];
        for (const auto& [layer, spec] : node.specs) {
            const LayerStack::Entry& entry = node.stack->layers[static_cast<std::size_t>(layer)];
            opinions.push_back(
                {spec, entry.layer, order[rank], static_cast<int>(rank), layer, node.offset.after(entry.offset)});
        }
    }
    return opinions;
}

namespace {

void appendNames(std::vector<std::string>& names, std::unordered_set<std::string>& seen,
                 const std::vector<std::unique_ptr<PrimSpec>>& prims, const Metadata& metadata,
                 const char* reorderKey) {
    for (const auto& prim : prims)
        if (seen.insert(prim->name).second) names.push_back(prim->name);
    for (const MetadataEntry& entry : metadata)
        if (entry.key == reorderKey && entry.op == ListOpKind::Reorder)
            names = applyOrdering(names, entry.value.strings, std::equal_to<>());
}

}  // namespace

std::vector<std::string> composeChildNames(const PrimIndex& index) {
    std::vector<std::string> names;
    std::unordered_set<std::string> seen;
    std::set<std::string> prohibited;
    std::vector<int> order = index.strengthOrder();
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const IndexNode& node = index.nodes()[*it];
        if (node.inert) continue;
        if (node.stack->relocates.editChildNames(node.path, names, prohibited)) seen = {names.begin(), names.end()};
        for (auto spec = node.specs.rbegin(); spec != node.specs.rend(); ++spec)
            appendNames(names, seen, spec->second.children(), spec->second.metadata(), "nameChildren");
    }
    std::erase_if(names, [&](const std::string& name) { return prohibited.contains(name); });
    return names;
}

std::vector<std::string> composeRootPrimNames(const LayerStack& stack) {
    std::vector<std::string> names;
    std::set<std::string> prohibited;  // root prims are never relocation sources
    stack.relocates.editChildNames("/", names, prohibited);
    std::unordered_set<std::string> seen(names.begin(), names.end());
    for (auto it = stack.layers.rbegin(); it != stack.layers.rend(); ++it)
        appendNames(names, seen, it->layer->rootPrims, it->layer->metadata, "rootPrims");
    return names;
}

// ---- PrimComposer ------------------------------------------------------------------------------

struct PrimComposer::PropertyOpinion {
    const AttributeSpec* attribute = nullptr;
    const RelationshipSpec* relationship = nullptr;
    const Opinion* opinion = nullptr;
};

// A clip set where it applies: at a node of its anchoring layer stack, just after its anchoring
// layer.
struct PrimComposer::ClipSource {
    const ClipSet* set = nullptr;
    std::string primPath;  // the node's prim path, without variant selections
    int rank = 0;
    int layerIndex = 0;

    bool strongerThan(const Opinion& o) const { return rank < o.rank || (rank == o.rank && layerIndex < o.layerIndex); }
};

namespace {

// The paths of one property spec, absolute and in the stage's namespace.
std::vector<std::string> pathsInStage(const PrimIndex& index, const Opinion& opinion,
                                      const std::vector<std::string>& paths) {
    std::string owner = stripVariantSelections(index.nodes()[opinion.node].path);
    std::vector<std::string> out;
    out.reserve(paths.size());
    for (const std::string& path : paths) out.push_back(index.mapToRoot(opinion.node, absolutePath(owner, path)));
    return out;
}

}  // namespace

std::unique_ptr<PrimSpec> PrimComposer::compose(const PrimIndex& index, const std::vector<Opinion>& opinions,
                                                const ClipSets& clipSets) {
    auto prim = std::make_unique<PrimSpec>();
    prim->path = index.path();
    prim->name = lastName(prim->path);
    prim->specifier = Specifier::Over;
    bool typed = false, located = false, defined = false;
    for (const Opinion& opinion : opinions) {
        const PrimSpec* spec = opinion.spec.prim;
        if (!spec) continue;
        if (!typed && !spec->typeName.empty()) {
            prim->typeName = spec->typeName;
            typed = true;
        }
        if (prim->specifier == Specifier::Over) prim->specifier = spec->specifier;
        if (!located || (!defined && spec->specifier == Specifier::Def)) {
            prim->location = spec->location;
            located = true;
            defined = spec->specifier == Specifier::Def;
        }
    }

    std::vector<MetadataOpinion> metadata;
    for (const Opinion& opinion : opinions) metadata.push_back({&opinion.spec.metadata(), opinion.layer});
    prim->metadata = composeMetadata(metadata, [](const std::string& key) { return kCompositionFields.contains(key); });

    // Properties: names weakest first, opinions strongest first.
    std::vector<std::string> attributeNames, relationshipNames;
    std::unordered_map<std::string, std::vector<PropertyOpinion>> attributes, relationships;
    for (auto it = opinions.rbegin(); it != opinions.rend(); ++it) {
        for (const AttributeSpec& a : it->spec.attributes())
            if (attributes.try_emplace(a.name).second) attributeNames.push_back(a.name);
        for (const RelationshipSpec& r : it->spec.relationships())
            if (relationships.try_emplace(r.name).second) relationshipNames.push_back(r.name);
    }
    for (const Opinion& opinion : opinions) {
        for (const AttributeSpec& a : opinion.spec.attributes()) attributes[a.name].push_back({&a, nullptr, &opinion});
        for (const RelationshipSpec& r : opinion.spec.relationships())
            relationships[r.name].push_back({nullptr, &r, &opinion});
    }
    std::vector<ClipSource> clips = clipSources(index, clipSets);
    prim->attributes.reserve(attributeNames.size());
    for (const std::string& name : attributeNames)
        prim->attributes.push_back(composeAttribute(index, attributes[name], clips));
    prim->relationships.reserve(relationshipNames.size());
    for (const std::string& name : relationshipNames)
        prim->relationships.push_back(composeRelationship(index, relationships[name]));
    return prim;
}

std::vector<PrimComposer::ClipSource> PrimComposer::clipSources(const PrimIndex& index, const ClipSets& clipSets) {
    std::vector<ClipSource> clips;
    std::vector<int> order = clipSets.empty() ? std::vector<int>{} : index.strengthOrder();
    for (const auto& set : clipSets) {
        for (std::size_t rank = 0; rank < order.size(); ++rank) {
            const IndexNode& node = index.nodes()[order[rank]];
            std::string path = stripVariantSelections(node.path);
            if (!node.inert && node.stack == set->stack && hasPathPrefix(path, set->sourcePrim))
                clips.push_back({set.get(), std::move(path), static_cast<int>(rank), set->anchorLayer});
        }
    }
    // Strongest first; at one place, the nearer prim's sets first (clipSets keeps that order).
    std::stable_sort(clips.begin(), clips.end(), [](const ClipSource& a, const ClipSource& b) {
        return std::tie(a.rank, a.layerIndex) < std::tie(b.rank, b.layerIndex);
    });
    return clips;
}

AttributeSpec PrimComposer::composeAttribute(const PrimIndex& index, const std::vector<PropertyOpinion>& opinions,
                                             const std::vector<ClipSource>& clips) {
    const AttributeSpec& strongest = *opinions.front().attribute;
    AttributeSpec out;
    out.name = strongest.name;
    out.typeName = strongest.typeName;
    out.custom = strongest.custom;
    out.uniform = strongest.uniform;
    out.location = strongest.location;

    Found found;
    const PropertyOpinion* defaultSource = nullptr;
    const PropertyOpinion* valueSource = nullptr;
    for (const PropertyOpinion& o : opinions) {
        if (!defaultSource && o.attribute->hasDefault) defaultSource = &o;
        if (!valueSource && (o.attribute->hasDefault || !o.attribute->timeSamples.empty())) valueSource = &o;
    }
    if (defaultSource) {
        out.hasDefault = true;
        out.defaultValue = anchorAssets(defaultSource->attribute->defaultValue, *defaultSource->opinion->layer, &found);
    }
    std::optional<TimeSamples> fromClips;
    for (const ClipSource& clip : clips) {
        if (valueSource && !clip.strongerThan(*valueSource->opinion)) break;
        if ((fromClips = clip.set->samples(clip.primPath, out.name, &found))) break;
    }
    if (fromClips) {
        out.timeSamples = std::move(*fromClips);
    } else if (valueSource && !valueSource->attribute->timeSamples.empty()) {
        const LayerOffset& time = valueSource->opinion->time;
        out.timeSamples.reserve(valueSource->attribute->timeSamples.size());
        for (const auto& [t, value] : valueSource->attribute->timeSamples)
            out.timeSamples.emplace_back(time.apply(t), anchorAssets(value, *valueSource->opinion->layer, &found));
        if (time.scale < 0)
            std::stable_sort(out.timeSamples.begin(), out.timeSamples.end(),
                             [](const auto& a, const auto& b) { return a.first < b.first; });
    }

    std::vector<SpecListEdits<std::string>> edits;
    std::vector<MetadataOpinion> metadata;
    for (const PropertyOpinion& o : opinions) {
        SpecListEdits<std::string> specEdits;
        if (!o.attribute->connections.empty())
            specEdits.push_back({o.attribute->connectionOp, pathsInStage(index, *o.opinion, o.attribute->connections)});
        for (const MetadataEntry& entry : o.attribute->metadata)
            if (entry.key == "connectionPaths")
                specEdits.push_back({entry.op, pathsInStage(index, *o.opinion, entry.value.strings)});
        edits.push_back(std::move(specEdits));
        metadata.push_back({&o.attribute->metadata, o.opinion->layer});
    }
    out.connections = composeListEdits(edits, std::equal_to<>());
    out.metadata = composeMetadata(metadata, [](const std::string& key) { return key == "connectionPaths"; });

    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    for (auto& [authored, resolved] : found)
        assets_.push_back({index.path(), out.name, std::move(authored), std::move(resolved), false, out.location});
    return out;
}

RelationshipSpec PrimComposer::composeRelationship(const PrimIndex& index,
                                                   const std::vector<PropertyOpinion>& opinions) {
    const RelationshipSpec& strongest = *opinions.front().relationship;
    RelationshipSpec out;
    out.name = strongest.name;
    out.custom = strongest.custom;
    out.location = strongest.location;

    std::vector<SpecListEdits<std::string>> edits;
    std::vector<MetadataOpinion> metadata;
    const RelationshipSpec* strongestEdit = nullptr;
    for (const PropertyOpinion& o : opinions) {
        const RelationshipSpec& r = *o.relationship;
        SpecListEdits<std::string> specEdits;
        if (r.blocked)
            specEdits.push_back({ListOpKind::Explicit, {}});
        else if (!r.targets.empty())
            specEdits.push_back({r.op, pathsInStage(index, *o.opinion, r.targets)});
        for (const MetadataEntry& entry : r.metadata)
            if (entry.key == "targetPaths")
                specEdits.push_back({entry.op, pathsInStage(index, *o.opinion, entry.value.strings)});
        if (!strongestEdit && !specEdits.empty()) strongestEdit = &r;
        edits.push_back(std::move(specEdits));
        metadata.push_back({&r.metadata, o.opinion->layer});
    }
    out.targets = composeListEdits(edits, std::equal_to<>());
    out.blocked = out.targets.empty() && strongestEdit && strongestEdit->blocked;
    out.metadata = composeMetadata(metadata, [](const std::string& key) { return key == "targetPaths"; });
    return out;
}

}  // namespace fluence::usd::detail
