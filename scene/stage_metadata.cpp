#include "scene/stage_metadata.h"

#include <cmath>

namespace fluence::usd::detail {

void checkStageMetadata(const Layer& rootLayer, CompositionLog& log) {
    if (const MetadataEntry* e = findMetadata(rootLayer.metadata, "upAxis")) {
        const std::optional<std::string> axis = e->value.asString();
        if (axis != "Y" && axis != "Z")
            log.warn("upAxis " + e->value.toString() + " is neither \"Y\" nor \"Z\"; the stage is taken as Y up",
                     e->location, "");
    }
    for (const char* key : {"framesPerSecond", "timeCodesPerSecond"})
        if (const MetadataEntry* e = findMetadata(rootLayer.metadata, key)) {
            const std::optional<double> rate = e->value.asDouble();
            if (!rate || !std::isfinite(*rate) || *rate <= 0.0)
                log.warn(std::string(key) + " " + e->value.toString() + " is not a positive number; ignored",
                         e->location, "");
        }
    const MetadataEntry* start = findMetadata(rootLayer.metadata, "startTimeCode");
    const MetadataEntry* end = findMetadata(rootLayer.metadata, "endTimeCode");
    if (start && end) {
        const std::optional<double> first = start->value.asDouble(), last = end->value.asDouble();
        if (first && last && *first > *last)
            log.warn("startTimeCode " + start->value.toString() + " is after endTimeCode " + end->value.toString(),
                     start->location, "");
    }
}

}  // namespace fluence::usd::detail
