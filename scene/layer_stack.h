// Layer stacks and the layers they are made of (internal to the scene library).
//
// A layer stack is a root layer and, recursively, its `subLayers`, strongest first (USD spec,
// "Layer stack" and "LayerOffset"): the root layer, then each sublayer followed by its own
// sublayers. Each layer carries the layer offset that maps its time codes to the stack's root
// layer: a sublayer's (offset, scale) composed through every level above it. Composition arcs
// target whole layer stacks: a reference to @chair.usda@ sees chair.usda and its sublayers.
//
// Time codes per second (USD's SdfLayer::GetTimeCodesPerSecond and Pcp's layer-offset scaling):
// a layer's rate is its `timeCodesPerSecond`, else its `framesPerSecond`, else 24. A sublayer
// whose rate differs from the layer that names it is scaled by (that layer's rate / the
// sublayer's rate) before its authored offset applies, so one second stays one second; arcs to
// another layer stack do the same with the authoring layer's rate and the target stack's root
// layer's rate (LayerOffset::between).
//
// Relocates (scene/relocates.h) belong to the whole stack: each stack carries the validated
// relocations its layers author.
//
// The LayerRegistry reads each layer file once (cached by absolute path) and builds each layer
// stack once (cached by root layer). Files that cannot serve as layers when an arc points at
// them (missing, another file format) are reported and skipped; syntax errors and damaged crate files throw.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/composition_types.h"
#include "scene/layer.h"
#include "scene/relocates.h"

namespace fluence::usd::detail {

// Maps a time code t of an inner layer to t * scale + offset in the layer above it.
struct LayerOffset {
    double offset = 0.0;
    double scale = 1.0;

    double apply(double time) const { return time * scale + offset; }
    // This offset applied after `inner`: t -> apply(inner.apply(t)).
    LayerOffset after(const LayerOffset& inner) const { return {offset + inner.offset * scale, scale * inner.scale}; }
    bool isIdentity() const { return offset == 0.0 && scale == 1.0; }
    // The offset authored on a sublayer, reference or payload (identity when none was written).
    static LayerOffset of(const Value& arc);
    // The scale that maps time codes of a layer at `innerRate` time codes per second to one at
    // `outerRate`.
    static LayerOffset between(double outerRate, double innerRate) { return {0.0, outerRate / innerRate}; }
};

// The layer's time codes per second: `timeCodesPerSecond`, else `framesPerSecond`, else 24
// (values that are not positive and finite are passed over).
double timeCodesPerSecond(const Layer& layer);

// What a layer holds at one path: a prim spec, or a variant of a variant set on a prim.
struct SpecRef {
    const PrimSpec* prim = nullptr;
    const VariantSpec* variant = nullptr;

    explicit operator bool() const { return prim || variant; }
    const Metadata& metadata() const { return prim ? prim->metadata : variant->metadata; }
    const std::vector<AttributeSpec>& attributes() const { return prim ? prim->attributes : variant->attributes; }
    const std::vector<RelationshipSpec>& relationships() const {
        return prim ? prim->relationships : variant->relationships;
    }
    const std::vector<std::unique_ptr<PrimSpec>>& children() const { return prim ? prim->children : variant->children; }
    const std::vector<VariantSetSpec>& variantSets() const { return prim ? prim->variantSets : variant->variantSets; }
};

// Every spec of a layer by path, variants included ("/A", "/A{v=x}", "/A{v=x}B").
class SpecIndex {
public:
    explicit SpecIndex(const Layer& layer);
    SpecRef find(const std::string& path) const;
    std::size_t size() const { return specs_.size(); }

private:
    void add(const std::string& path, SpecRef spec);
    std::unordered_map<std::string, SpecRef> specs_;
};

struct LayerStack {
    struct Entry {
        const Layer* layer = nullptr;
        const SpecIndex* specs = nullptr;
        LayerOffset offset;  // this layer's time to the root layer's time
    };
    std::string identifier;     // the root layer's identifier
    std::vector<Entry> layers;  // strongest first; layers[0] is the root layer
    Relocates relocates;        // the relocations the stack's layers author

    const Layer& rootLayer() const { return *layers.front().layer; }
    // The stack's rate: its root layer's (USD's PcpLayerStack::GetTimeCodesPerSecond).
    double timeCodesPerSecond() const { return usd::detail::timeCodesPerSecond(rootLayer()); }
    // The stack's default prim as an absolute path ("" when the root layer names none).
    std::string defaultPrimPath() const;
    // True when some layer of the stack has a spec at `path`.
    bool hasSpecAt(const std::string& path) const;
};

// Where an arc that needs a layer file was authored, for warnings.
struct ArcSite {
    const char* arc;       // "sublayer", "reference", "payload", "clip", "clip manifest"
    const char* property;  // the metadata field: "subLayers", "references", "payload", "clips"
    std::string authored;  // the asset path as written
    SourceLocation location;
    std::string primPath;
};

class LayerRegistry {
public:
    explicit LayerRegistry(CompositionLog& log) : log_(log) {}

    // The stage's root layer stack. open() reads the file (FileError when it cannot be read,
    // ParseError on bad syntax; layers are read by usd::readLayerFile: text, crate or MaterialX);
    // adopt() takes an in-memory layer.
    const LayerStack& openRoot(const std::string& path);
    const LayerStack& adoptRoot(std::unique_ptr<Layer> layer);

    // The layer stack rooted at the layer file `resolvedPath`, or nullptr (after a warning) when
    // the file cannot be used as a layer. ParseError on bad syntax.
    const LayerStack* stackFor(const std::string& resolvedPath, const ArcSite& site);

    // Every layer file read, the root layer first.
    std::vector<std::string> files() const;

    // The number of prim and variant specs in every layer read so far.
    std::size_t specCount() const { return specCount_; }

    // The layer file `resolvedPath` alone (value clips read single layers), or nullptr (after a
    // warning) when it cannot be used as a layer; and the index of a layer's specs.
    const Layer* layerFor(const std::string& resolvedPath, const ArcSite& site);
    const SpecIndex& specIndexOf(const Layer& layer);

private:
    // Takes ownership of a parsed layer and reports its parse warnings.
    const Layer& keep(std::unique_ptr<Layer> layer);
    const LayerStack& buildStack(const Layer& root);
    void addToStack(LayerStack& stack, const Layer& layer, const LayerOffset& offset, std::vector<std::string>& chain);

    CompositionLog& log_;
    std::vector<std::unique_ptr<Layer>> layers_;
    std::vector<std::string> files_;               // in reading order
    std::map<std::string, const Layer*> byPath_;   // nullptr: unusable file
    std::map<std::string, std::string> problems_;  // why an unusable file is
    std::map<const Layer*, std::unique_ptr<SpecIndex>> specIndexes_;
    std::size_t specCount_ = 0;
    std::map<const Layer*, std::unique_ptr<LayerStack>> stacks_;
};

}  // namespace fluence::usd::detail
