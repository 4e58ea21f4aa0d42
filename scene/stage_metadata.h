// Checks of the stage metadata USD itself would flag (UsdGeomGetStageUpAxis, UsdStage's time
// metadata): an upAxis other than "Y" or "Z" (the stage is then Y up), a framesPerSecond or
// timeCodesPerSecond that is not a positive number (ignored: the rate falls back as
// scene/layer_stack.h says), and a startTimeCode after the endTimeCode. Each is a composition
// warning at the metadata's file:line:column; nothing is changed.
#pragma once

#include "scene/composition_types.h"
#include "scene/layer.h"

namespace fluence::usd::detail {

void checkStageMetadata(const Layer& rootLayer, CompositionLog& log);

}  // namespace fluence::usd::detail
