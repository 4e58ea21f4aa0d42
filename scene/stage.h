// The stage: the scene graph the delegate reads.
//
// This first cut has no composition (sublayers, references, variants land with issue 4): the
// stage is its root layer. What the stage adds to the layer is USD's value resolution —
// layer-metadata fallbacks (upAxis "Y", metersPerUnit 0.01), attribute values at a time code
// (the default value, or time samples held or linearly interpolated), and the traversal rules
// (only defined, active prims; `over`-only and `class` subtrees are not rendered).
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "scene/layer.h"

namespace fluence::usd {

// USD's UsdTimeCode::Default(): the attribute's default value, ignoring time samples.
inline constexpr double kDefaultTime = std::numeric_limits<double>::quiet_NaN();

class Stage {
public:
    explicit Stage(std::unique_ptr<Layer> rootLayer);

    // Reads a .usda file (or a .usd / .sdf file holding USD text). Throws usd::FileError or
    // usd::ParseError.
    static std::unique_ptr<Stage> open(const std::string& path);

    const Layer& rootLayer() const { return *layer_; }

    std::string defaultPrim() const;
    char upAxis() const;             // 'Y' or 'Z'; USD's fallback is 'Y'
    double metersPerUnit() const;    // USD's fallback is 0.01 (centimetres)
    std::optional<double> startTimeCode() const;
    std::optional<double> endTimeCode() const;

    const PrimSpec* prim(const std::string& path) const { return layer_->primAtPath(path); }

    // Visits defined (`def`), active prims depth-first in authored order. The visitor returns
    // false to skip the prim's children.
    void traverse(const std::function<bool(const PrimSpec&)>& visit) const;

    // The attribute's value at `time`: at kDefaultTime the default value; otherwise time
    // samples (linear interpolation between numeric samples of equal size, held otherwise,
    // clamped at the ends), falling back to the default. std::nullopt when the attribute is not
    // authored or its resolved value is blocked (`None`).
    static std::optional<Value> resolve(const AttributeSpec& attribute, double time);

private:
    std::unique_ptr<Layer> layer_;
};

}  // namespace fluence::usd
