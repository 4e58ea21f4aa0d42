// UsdGeomImageable rules the delegate applies everywhere: what is rendered, and what is geometry.
#pragma once

#include <string>

#include "scene/layer.h"

namespace fluence::delegate {

// Whether a prim's subtree is rendered at all: `visibility = "invisible"` and the guide and proxy
// purposes prune it (the render purpose and the default purpose render).
bool isImaged(const usd::PrimSpec& prim, double time);

// A Mesh or an implicit surface (Sphere, Cube, Cylinder, Cone, Capsule).
bool isGeometryType(const std::string& typeName);

}  // namespace fluence::delegate
