// Value clips (internal to the scene library; USD's "Value Clips" and UsdClipsAPI): time samples
// that a prim's `clips` metadata draws from a sequence of clip layers, for the attributes of the
// prim and of its descendants.
//
// A clip set (one entry of the `clips` dictionary; `clipSets` orders and filters them) names the
// clip layers (`assetPaths`, or `templateAssetPath` with `templateStartTime`, `templateEndTime`,
// `templateStride` and `templateActiveOffset`, which derive asset paths, `times` and `active` from
// the files that exist), which clip is active from which stage time on (`active`: (stage time,
// clip index)), how stage time maps to clip time (`times`: (stage time, clip time) points joined
// by straight lines, two points at one stage time making a jump), where the prim's opinions sit in
// the clips (`primPath`), which attributes the clips hold (`manifestAssetPath`: a layer declaring
// the varying attributes; without one, every attribute with samples in some clip), and whether a
// clip without samples for an attribute is bridged by its neighbours
// (`interpolateMissingClipValues`) or gives the manifest's default, else a value block.
//
// Composition (clipSetsOf; USD's Usd_ComputeClipSetDefinitionsForPrimIndex): per node of the prim
// index, weakest layer first, each layer's clip-set dictionaries over the weaker ones, their
// `active` and `times` stage times moved by that layer's offset; the strongest layer authoring the
// asset paths is the set's anchor. Nodes compose strongest first, the first anchor winning. Clip
// layers are read alone: their sublayers, arcs, metadata and default values are ignored. A clip
// file that cannot be read is a warning naming it, and gives no samples.
//
// Strength (scene/prim_composer.h): a clip set's samples are weaker than the anchoring layer and
// every stronger layer of its layer stack, and stronger than the rest (weaker sublayers,
// references, payloads...), for the prim that authors the set and its descendants (the set of the
// nearest prim first). Clips never give default values.
//
// Time samples (ClipSet::samples; USD's Usd_ClipSet::ListTimeSamplesForPath and value lookup):
// every clip sample mapped to the stage times where that clip is active, every `times` stage time,
// and every clip's activation time, each valued by the active clip at its clip time (interpolated
// between the clip's samples as Stage::resolve does). Linear interpolation of these stage samples
// is what USD's value resolution does between them, so flattening them is exact.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/composition_types.h"
#include "scene/layer_stack.h"
#include "scene/prim_index.h"

namespace fluence::usd::detail {

// A layer read as a clip or manifest (both null when the file could not be read).
struct ClipLayer {
    const Layer* layer = nullptr;
    const SpecIndex* specs = nullptr;

    const AttributeSpec* attribute(const std::string& primPath, const std::string& name) const;
};

struct ClipSet {
    struct Clip {
        ClipLayer layer;
        double authoredStart = 0.0;  // the stage time of its `active` entry
        double start = 0.0;          // active from start (inclusive) to end (exclusive)
        double end = 0.0;
    };
    struct TimeMapping {
        double stage = 0.0;
        double clip = 0.0;
        bool jump = false;  // the left side of a jump discontinuity
    };

    std::string name;
    const LayerStack* stack = nullptr;  // the anchor: where the set's asset paths were authored
    std::string sourcePrim;             // the anchoring prim's path there, without variant selections
    int anchorLayer = 0;                // the authoring layer, in `stack`
    std::string clipPrim;               // `primPath`: where sourcePrim's opinions are in the clips
    bool interpolateMissing = false;
    bool generatedManifest = true;  // no `manifestAssetPath`: declared by the clips' samples
    ClipLayer manifest;
    std::vector<Clip> clips;         // by start time; never empty
    std::vector<TimeMapping> times;  // sorted, with USD's copies of both ends; empty: identity

    // The stage-time samples the set gives the attribute `attribute` of the prim `primPath` (at or
    // below sourcePrim, in the anchoring stack's namespace), or std::nullopt when the manifest does
    // not declare that attribute varying. Asset values are anchored at their clip layer and
    // reported to `assets` as (authored, resolved).
    std::optional<TimeSamples> samples(const std::string& primPath, const std::string& attribute,
                                       std::vector<std::pair<std::string, std::string>>* assets) const;

private:
    double toClipTime(double stageTime) const;
    double toStageTime(double clipTime, std::size_t segment) const;
    TimeMapping segmentEnd(std::size_t i) const;
    void addSampleTimes(const Clip& clip, const AttributeSpec* attribute, std::vector<double>& out) const;
};

// The clip sets that the prim of `index` authors, in strength order (`clipSets` order), their layers
// read through `registry`; invalid sets are reported and left out.
std::vector<std::shared_ptr<const ClipSet>> clipSetsOf(const PrimIndex& index, LayerRegistry& registry,
                                                       CompositionLog& log);

}  // namespace fluence::usd::detail
