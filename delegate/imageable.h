// UsdGeomImageable rules the delegate applies everywhere: what is rendered, and what is geometry.
#pragma once

#include <string>
#include <vector>

#include "scene/layer.h"

namespace fluence::delegate {

// The purposes a render includes (UsdRenderSettings includedPurposes). The default purpose always
// renders; USD's fallback includes the render purpose and leaves proxy and guide out.
struct IncludedPurposes {
    bool render = true, proxy = false, guide = false;

    // From purpose names ("default", "render", "proxy", "guide"; husk's "geometry" is "default").
    // Throws std::invalid_argument naming an unknown one.
    static IncludedPurposes fromNames(const std::vector<std::string>& names);
    bool includes(const std::string& purpose) const;
};

// Whether a prim's subtree is rendered at all: `visibility = "invisible"` prunes it, and so does
// a purpose the render does not include. Pruning the subtree is USD's purpose inheritance: a
// descendant of a guide prim is a guide whatever its own purpose.
bool isImaged(const usd::PrimSpec& prim, double time, const IncludedPurposes& purposes);

// A Mesh or an implicit surface (Sphere, Cube, Cylinder, Cone, Capsule).
bool isGeometryType(const std::string& typeName);

}  // namespace fluence::delegate
