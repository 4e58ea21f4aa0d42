// Template value clips (internal to the scene library; USD's "Template Clip Metadata"): the clip
// files a `templateAssetPath` such as "sim.###.usda" (integer times) or "sim.###.##.usda"
// (times with a fraction) names for the times templateStartTime, + templateStride, ... up to
// templateEndTime, and the `active` and `times` metadata they imply: each existing file is a clip
// active from its time ((t, t) in `times`), or from t + templateActiveOffset, in which case
// `times` also gets points |offset| before the first and after the last time. Files that do not
// exist are passed over.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fluence::usd::detail {

struct ClipAsset {
    std::string authored;  // as written (or derived from the template)
    std::string resolved;  // anchored at the authoring layer
};

struct ClipTemplate {
    std::vector<ClipAsset> assets;
    std::vector<std::pair<double, double>> active;  // (stage time, clip index)
    std::vector<std::pair<double, double>> times;   // (stage time, clip time)
};

// The clips of a template authored in the layer `layerIdentifier`, or nullopt with `problem` set
// when the template metadata is invalid (USD's rules: a positive stride, an offset no larger than
// the stride, one or two adjacent groups of '#', start no later than end).
std::optional<ClipTemplate> deriveClipTemplate(const std::string& pattern, const std::string& layerIdentifier,
                                               double start, double end, double stride,
                                               std::optional<double> activeOffset, std::string& problem);

}  // namespace fluence::usd::detail
