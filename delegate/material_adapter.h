// UsdShade materials -> render::MaterialDesc (which material a prim binds:
// delegate/material_binding.h).
//
// Material: the Material's `outputs:mtlx:surface` (then `outputs:surface`) is followed, through
// NodeGraph outputs, to a Shader whose info:id is UsdPreviewSurface or
// ND_standard_surface_surfaceshader; delegate/surface_shaders.h maps its inputs onto
// render::MaterialParams, and delegate/shading_network.h reads the texture and primvar-reader
// nodes that drive inputs per point. An input connected to a Material interface input takes that
// input's value. Any other surface shader warns and the default material is used.
#pragma once

#include <functional>
#include <string>
#include <utility>

#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

using ColorConverter = std::function<RGB(const RGB&, const std::string&)>;
using Warn = std::function<void(const std::string& primPath, const std::string& message)>;

render::MaterialDesc materialFromPath(const usd::Stage& stage, const std::string& materialPath, double time,
                                      const ColorConverter& convertColor, const Warn& warn);

// The parent of a prim path ("/" for a root prim).
std::string parentPath(const std::string& path);

// Resolves a relationship or connection target (absolute, or relative to `anchor`).
std::string resolveTargetPath(const std::string& anchor, const std::string& target);

// Splits "/Prim/Path.property:name" into the prim path and the property name.
std::pair<std::string, std::string> splitPropertyPath(const std::string& path);

}  // namespace fluence::delegate
