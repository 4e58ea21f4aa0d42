// UsdGeomImageable rules the delegate applies everywhere: what is rendered, and what is geometry.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "delegate/prim_reader.h"
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
// descendant of a guide prim is a guide whatever its own purpose. A visibility or purpose that
// is not a token (`int visibility = 3`, `string purpose = "guide"`) counts as not authored, as
// OpenUSD reads it (UsdGeomImageable::ComputeVisibility); `ignored` is given the SceneError
// naming the prim and the value.
bool isImaged(const usd::PrimSpec& prim, double time, const IncludedPurposes& purposes,
              const std::function<void(const SceneError&)>& ignored);
// What is done with such a value (the consequence a warning about it names).
inline constexpr const char* kReadAsNotAuthored = "read as not authored, as USD reads it";

// A Mesh, a TetMesh (its boundary surface, delegate/tet_mesh.h) or an implicit surface (Sphere,
// Cube, Cylinder, Cone, Capsule, ...).
bool isGeometryType(const std::string& typeName);

}  // namespace fluence::delegate
