// USD composition by flattening: the stage's layers and composition arcs become one Layer whose
// prim specs hold the composed result, as UsdStage::Flatten would write it (internal to the scene
// library; the Stage is its user).
//
// Algorithm (the USD specification's "Composition" chapter; section names in quotes):
//
//  1. Layer stack ("Layer stack", "LayerOffset"; scene/layer_stack.h). The root layer and its
//     `subLayers`, recursively, strongest first, each with the layer offset that maps its time
//     codes to the root layer's, including the scaling between layers authored at different
//     `timeCodesPerSecond` (else `framesPerSecond`, else 24). Every layer file is read once; a
//     sublayer cycle is reported. The stack's `relocates` are gathered and validated
//     (scene/relocates.h).
//
//  2. Prim index ("LIVRPS Strength Ordering"; scene/prim_index.h). For each prim, from the root
//     prims down, the tree of sites that hold opinions about it, walked in strength order:
//        L  Local opinions: the prim's path in the root layer stack, strongest layer first
//           (value clips sit among them: see 3).
//        I  Inherits: the class prims it inherits and their namespace, including classes that
//           referenced assets use, as seen from the stage's layers ("implied inherits").
//        V  VariantSets: the selected variant of each variant set (the strongest selection
//           authored anywhere in the index, or one given in StageOptions), nested sets included.
//           Relocates: a prim relocated to this path composes from its source's ancestral arcs,
//           without the opinions authored at the source (scene/relocates.h).
//        R  References: internal </Path>, external @file@</Path> and @file@ (its defaultPrim),
//           the lists composed as list ops, their layer offsets (and rate scaling) applied.
//        P  Payloads: as references, for the prims StageOptions::loadRules load (USD's
//           UsdStageLoadRules; scene/load_rules.h).
//        S  Specializes: the weakest of all, even weaker than opinions that references bring.
//     Each arc's target is indexed the same way, so arcs inside referenced layers compose too.
//     A child prim's index starts from its parent's ("ancestral arcs"). Arc cycles are reported
//     and cut.
//
//  3. Value resolution ("Value Resolution"; scene/prim_composer.h). The prim's specs, strongest
//     first, give its specifier, type, metadata, properties and children (relocated children
//     renamed, removed or added); paths that point into a referenced or relocated namespace are
//     mapped to where it landed ("Namespace", "Path translation"; scene/namespace_remap.h);
//     asset paths are anchored at their layer ("Asset resolution"; scene/asset_path.h); time
//     samples are moved by the layer offsets. Value clips ("Value Clips"; scene/value_clips.h)
//     are composed here, at flatten time, into the attributes' time samples, as UsdStage::Flatten
//     writes them: a prim's `clips` apply to it and its descendants, just weaker than the layer
//     that anchors them. Only the clip layers are kept in memory (read once, their numbers
//     shared with the composed samples), not a per-time cache.
//
//  4. Instancing ("Instancing"). An `instanceable` prim with composition arcs is flattened like
//     any other, except that, as in USD, the root layer stack's own opinions on its descendants
//     do not apply; it gets the metadata `fluence:instancePrototype`, a key equal for instances
//     that USD would give one prototype (same arcs, sites, variant selections, layer offsets).
//
// A prim whose payload the load rules left out gets the metadata `fluence:unloadedPayload`
// (`fluence info` marks it). Composition metadata (arcs, variant selections, relocates, clips)
// is consumed and not copied. Inactive prims (`active = false`) are kept, without their
// descendants, as USD populates them.
// Problems composition can step over (missing files and prims, cycles, unsupported formats, unknown
// variant selections, invalid relocates and clip sets, missing clips) become warnings; syntax
// errors in any layer throw usd::ParseError.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/composition_types.h"
#include "scene/layer_stack.h"

namespace fluence::usd::detail {

struct FlattenResult {
    std::unique_ptr<Layer> layer;
    std::vector<AssetReference> assets;  // every asset-valued attribute of the composed prims
};

FlattenResult flatten(const LayerStack& root, LayerRegistry& registry, CompositionLog& log,
                      const StageOptions& options);

struct FlattenedPrim {
    std::unique_ptr<PrimSpec> prim;      // null when no prim is composed at the path any more
    std::vector<AssetReference> assets;  // the asset-valued attributes of the prim and its descendants
};

// The prim at the absolute path `path` and its descendants, composed again (after `options`
// changed), its ancestors' arcs included.
FlattenedPrim flattenSubtree(const LayerStack& root, const std::string& path, LayerRegistry& registry,
                             CompositionLog& log, const StageOptions& options);

}  // namespace fluence::usd::detail
