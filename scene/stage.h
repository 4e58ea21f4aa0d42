// The stage: the composed scene graph the delegate reads.
//
// Stage::open reads the root layer, its sublayers and every layer that references, loaded payloads
// and value clips reach, and composes them (scene/flatten.h: sublayers, inherits, variants,
// relocates, references, payloads, specializes; layer offsets and time-code rates; value clips)
// into one flattened Layer whose prim specs hold the composed result; prim(), traverse() and the
// layer-metadata queries read that layer. What the stage adds on top is USD's value resolution at
// a time code — layer-metadata fallbacks (upAxis "Y", metersPerUnit 0.01), attribute values at a
// time code (the default value, or time samples held or linearly interpolated; scene/time_samples.h)
// — and the traversal rules (only defined, active prims; `over`-only and `class` subtrees are not
// rendered). Time codes are the root layer's: startTimeCode and endTimeCode are read from it as
// authored, and every composed time sample is mapped into it.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/composition_types.h"
#include "scene/layer.h"

namespace fluence::usd {

namespace detail {
class LayerRegistry;
struct LayerStack;
}  // namespace detail

// USD's UsdTimeCode::Default(): the attribute's default value, ignoring time samples.
inline constexpr double kDefaultTime = std::numeric_limits<double>::quiet_NaN();
// USD's UsdTimeCode::EarliestTime(): before every time sample, so a time-sampled attribute gives
// its first sample and an attribute without samples its default value. Hydra renders a stage at
// this time when no frame is asked for (UsdImagingGLRenderParams::frame, the stage scene index).
inline constexpr double kEarliestTime = std::numeric_limits<double>::lowest();
// The time a render reads a frame at: the frame, or kEarliestTime where none is given (NaN), as
// Hydra does. The delegate's readers and the missing-asset check both use it.
inline double renderReadTime(double frame) { return std::isnan(frame) ? kEarliestTime : frame; }

class Stage {
public:
    // An in-memory root layer (tests, the fuzzer). Its internal arcs compose; external ones
    // resolve against the directory of its identifier (the current directory for a bare name).
    explicit Stage(std::unique_ptr<Layer> rootLayer, const StageOptions& options = {});

    // Reads a .usda file (or a .usd / .sdf file holding USD text) and composes it. Throws
    // usd::FileError when the root layer cannot be read, usd::ParseError on a syntax error in any
    // layer (a binary crate root layer included). Everything else composition can step over is
    // in warnings().
    static std::unique_ptr<Stage> open(const std::string& path, const StageOptions& options = {});

    ~Stage();

    const Layer& rootLayer() const;                            // the root layer as parsed
    const Layer& composedLayer() const { return *composed_; }  // the flattened result

    // Layer metadata, from the root layer (relocates and sublayers are consumed by composition).
    std::string defaultPrim() const;
    char upAxis() const;           // 'Y' or 'Z'; USD's fallback is 'Y'
    double metersPerUnit() const;  // USD's fallback is 0.01 (centimetres)
    std::optional<double> startTimeCode() const;
    std::optional<double> endTimeCode() const;

    // The composed prim at an absolute path (nullptr if none).
    const PrimSpec* prim(const std::string& path) const;

    // Visits defined (`def`), active composed prims depth-first in composed order. The visitor
    // returns false to skip the prim's children.
    void traverse(const std::function<bool(const PrimSpec&)>& visit) const;
    // The same, from `root` (visited first, when it is itself defined and active).
    static void traverse(const PrimSpec& root, const std::function<bool(const PrimSpec&)>& visit);

    // The attribute's value at `time`: at kDefaultTime the default value; otherwise time
    // samples (linear interpolation between numeric samples of equal size, held otherwise,
    // clamped at the ends), falling back to the default. std::nullopt when the attribute is not
    // authored or its resolved value is blocked (`None`).
    static std::optional<Value> resolve(const AttributeSpec& attribute, double time);

    // What composition stepped over, in the order found.
    const std::vector<CompositionWarning>& warnings() const { return log_.warnings(); }
    // Every layer file used, the root layer first.
    std::vector<std::string> layerFiles() const { return layerFiles_; }
    // Every asset-valued attribute of the composed stage, then the arc targets (sublayers,
    // references, payloads) that could not be used.
    std::vector<AssetReference> assetReferences() const;

    // Edits, as if authored in a session layer stronger than every layer of the stage. Composed
    // PrimSpecs outside the edited prim's subtree stay where they are.
    //
    // Sets the default value of a composed prim's attribute (authoring the attribute when the prim
    // has none of that name); its time samples no longer apply. False when there is no such prim.
    bool setAttribute(const std::string& primPath, const std::string& name, const Value& value);
    // Selects a variant as StageOptions::variantSelections does, and composes the prim's subtree
    // again (attribute edits made inside it are kept).
    void setVariantSelection(const std::string& primPath, const std::string& variantSet, const std::string& selection);

private:
    struct OpenFile {
        std::string path;
    };
    struct AttributeEdit {
        std::string primPath, name;
        Value value;
    };
    Stage(const OpenFile& file, const StageOptions& options);
    void compose(std::unique_ptr<Layer> inMemoryRoot, const std::string& path);
    void addPrims(PrimSpec& prim);
    void removePrims(const PrimSpec& prim);
    void addAssets(std::vector<AssetReference> assets);
    static void applyEdit(PrimSpec& prim, const AttributeEdit& edit);

    StageOptions options_;
    CompositionLog log_;
    std::unique_ptr<detail::LayerRegistry> registry_;  // every layer read, for recomposition
    const detail::LayerStack* rootStack_ = nullptr;
    std::unique_ptr<Layer> composed_;
    std::vector<std::string> layerFiles_;
    std::vector<AssetReference> assets_;
    std::unordered_map<std::string, PrimSpec*> primsByPath_;
    std::vector<AttributeEdit> edits_;
};

}  // namespace fluence::usd
