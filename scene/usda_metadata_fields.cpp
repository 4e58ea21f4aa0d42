#include "scene/usda_metadata_fields.h"

#include <algorithm>
#include <array>

namespace fluence::usd::detail {

bool isRegisteredMetadataField(std::string_view name) {
    // Sorted, for binary search.
    static constexpr std::array<std::string_view, 73> kFields = {
        "active",
        "allowedTokens",
        "apiSchemas",
        "assetInfo",
        "bindMaterialAs",
        "clipSets",
        "clips",
        "colorConfiguration",
        "colorManagementSystem",
        "colorSpace",
        "comment",
        "connectability",
        "customData",
        "customLayerData",
        "default",
        "defaultPrim",
        "displayGroup",
        "displayGroupOrder",
        "displayName",
        "displayUnit",
        "doc",
        "documentation",
        "elementSize",
        "endFrame",
        "endTimeCode",
        "expressionVariables",
        "fallbackPrimTypes",
        "framePrecision",
        "framesPerSecond",
        "hasOwnedSubLayers",
        "hidden",
        "inherits",
        "instanceable",
        "interpolation",
        "kind",
        "metersPerUnit",
        "nameChildren",
        "noLoadHint",
        "outputName",
        "owner",
        "payload",
        "payloads",
        "permission",
        "prefix",
        "prefixSubstitutions",
        "properties",
        "references",
        "relocates",
        "renderSettingsPrimPath",
        "renderType",
        "sdrMetadata",
        "sessionOwner",
        "specializes",
        "startFrame",
        "startTimeCode",
        "subLayerOffsets",
        "subLayers",
        "suffix",
        "suffixSubstitutions",
        "symmetricPeer",
        "symmetryArguments",
        "symmetryFunction",
        "targetPaths",
        "timeCodesPerSecond",
        "timeSamples",
        "typeName",
        "unauthoredValuesIndex",
        "upAxis",
        "variantSelection",
        "variantSetNames",
        "variantSets",
        "variants",
        "weight",  // UsdSkel's in-between weight
    };
    static_assert(std::is_sorted(kFields.begin(), kFields.end()));
    // Fluence's own fields (written by flattening, scene/flatten.h, read by the delegate).
    if (name.starts_with("fluence:")) return true;
    return std::binary_search(kFields.begin(), kFields.end(), name);
}

namespace {

constexpr std::array<std::string_view, 12> kDisplayUnits = {
    "mm", "cm", "dm", "m", "km", "in", "ft", "yd", "mi", "deg", "rad", "default",
};

}  // namespace

bool isDisplayUnit(std::string_view name) {
    return std::find(kDisplayUnits.begin(), kDisplayUnits.end(), name) != kDisplayUnits.end();
}

std::string displayUnitNames() {
    std::string names;
    for (std::string_view unit : kDisplayUnits) {
        names.append(names.empty() ? "" : ", ").append(unit);
    }
    return names;
}

}  // namespace fluence::usd::detail
