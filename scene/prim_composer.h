// Value resolution for one composed prim (internal to the scene library; USD spec "Value
// Resolution"): the opinions of a prim index, strongest first, combined into one PrimSpec.
//
//   - specifier: the strongest one that is not `over` (a prim only ever `over`ridden stays over);
//     typeName: the strongest authored one; location: the strongest `def` (else the strongest spec).
//   - metadata: per key, the strongest opinion; list-op fields (apiSchemas and any field edited
//     with prepend/append/delete/add/reorder) composed as list ops; dictionaries (customData,
//     assetInfo, ...) merged key by key. Composition arcs and variant selections are consumed by
//     composition and not copied.
//   - attributes: the strongest default; the time samples of the strongest spec that authors a
//     value, when that value is time samples (a stronger default hides weaker samples), with
//     times mapped through the opinion's layer offsets; connections composed as list ops. Value
//     clips (scene/value_clips.h) take part as a source of time samples placed just after their
//     anchoring layer: the strongest clip set that declares the attribute, when it is stronger
//     than every spec authoring a value, gives the time samples.
//   - relationships: targets composed as list ops (`= None` is an explicit empty list).
//   - paths (targets, connections) are made absolute and mapped into the stage's namespace;
//     asset values are anchored at the directory of the layer that authored them.
//   - properties and children: the union over all opinions, weakest first, so an asset's own
//     order comes first and stronger layers add to it; `reorder nameChildren` applies per spec.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/composition_types.h"
#include "scene/prim_index.h"
#include "scene/value_clips.h"

namespace fluence::usd::detail {

// One spec's opinions about the prim.
struct Opinion {
    SpecRef spec;
    const Layer* layer = nullptr;
    int node = 0;        // in the prim index
    int rank = 0;        // the node's place in strength order
    int layerIndex = 0;  // the layer's place in the node's layer stack
    LayerOffset time;    // the spec's time codes to the stage's
};

// Every spec of the index, strongest first.
std::vector<Opinion> opinionsOf(const PrimIndex& index);

// Child prim names, weakest opinion first, each spec's `reorder nameChildren` applied, and each
// node's relocations (Relocates::editChildNames) before its specs.
std::vector<std::string> composeChildNames(const PrimIndex& index);

// The root prim names of a layer stack, likewise (`reorder rootPrims`; prims relocated to the
// root first).
std::vector<std::string> composeRootPrimNames(const LayerStack& stack);

// A copy of `value` with every asset path anchored at `layer`'s directory; each asset path is
// reported to `found` (when not null) as (authored, resolved).
Value anchorAssets(const Value& value, const Layer& layer,
                   std::vector<std::pair<std::string, std::string>>* found = nullptr);

// Dictionary composition: `stronger`'s entries over `weaker`'s, nested dictionaries merged the
// same way (`stronger` itself when either is not a dictionary).
Value mergeDictionaries(const Value& weaker, const Value& stronger);

using ClipSets = std::vector<std::shared_ptr<const ClipSet>>;

class PrimComposer {
public:
    // Asset-valued attributes of composed prims are appended to `assets` (exists left false).
    explicit PrimComposer(std::vector<AssetReference>& assets) : assets_(assets) {}

    // The composed prim, without children. `clipSets`: the clip sets of the prim and of its
    // ancestors, nearest prim first.
    std::unique_ptr<PrimSpec> compose(const PrimIndex& index, const std::vector<Opinion>& opinions,
                                      const ClipSets& clipSets = {});

private:
    struct PropertyOpinion;
    struct ClipSource;

    // Where each clip set applies in the index, strongest first.
    static std::vector<ClipSource> clipSources(const PrimIndex& index, const ClipSets& clipSets);
    AttributeSpec composeAttribute(const PrimIndex& index, const std::vector<PropertyOpinion>& opinions,
                                   const std::vector<ClipSource>& clips);
    RelationshipSpec composeRelationship(const PrimIndex& index, const std::vector<PropertyOpinion>& opinions);

    std::vector<AssetReference>& assets_;
};

}  // namespace fluence::usd::detail
