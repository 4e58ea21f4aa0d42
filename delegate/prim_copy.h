// Copies of prim specs that hold values computed by the delegate (a skinned pose, points moved by
// their velocities), so the adapters read them as they read authored data.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/layer.h"

namespace fluence::delegate {

// A copy of `prim`, its children included.
std::unique_ptr<usd::PrimSpec> copyPrim(const usd::PrimSpec& prim);

// Sets the attribute `name` of `prim` (added when it has none) to the array `values`, of type
// `typeName` (e.g. "point3f[]") with `components` numbers per element, at every time: its time
// samples are dropped, its metadata kept.
void setArray(usd::PrimSpec& prim, const std::string& name, const std::string& typeName, std::vector<double> values,
              int components);

}  // namespace fluence::delegate
