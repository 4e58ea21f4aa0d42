// The asset values within a USD value: an asset or asset array itself, or those inside a value's
// list items and dictionary entries (metadata such as clips or customData), depth first. What
// composition anchors in place (scene/prim_composer) and what `fluence render` checks are read
// (apps/scene_loading) both look for them.
#pragma once

#include "core/function_ref.h"
#include "scene/value.h"

namespace fluence::usd {

// Whether `test` holds for an asset value within `value`; stops at the first for which it does.
bool anyAssetValue(const Value& value, FunctionRef<bool(const Value&)> test);

}  // namespace fluence::usd
