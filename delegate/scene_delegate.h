// The scene delegate: reads a USD stage and produces the render core's SceneDescription.
//
// This is the only place that knows USD schema names. It walks the stage's defined, active
// prims depth-first, composing world transforms (UsdGeomXformable), skipping invisible
// subtrees and guide/proxy purposes, and hands each prim to the adapter for its type: Mesh,
// Camera, the UsdLux lights, and (through material:binding) UsdShade materials. Authored
// colours are converted into the rendering space through `convertColor`. Prim types it cannot
// render yet are skipped with one warning per type. Semantic errors raise SceneError naming the
// prim path.
//
// Change tracking (dirty bits, re-sync of edited prims) arrives with the composition issue; for
// now the delegate translates the whole stage once.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "delegate/material_adapter.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

struct DelegateOptions {
    std::string cameraPath;  // "" = the render settings' camera, else the first Camera prim
    double time = usd::kDefaultTime;
    ColorConverter convertColor;  // authored colour + colour space -> rendering space
    Warn warn;                    // (prim path, message)
};

struct RenderSettingsInfo {
    std::string path;
    std::optional<std::pair<int, int>> resolution;
    std::string cameraPath;
};

struct DelegateResult {
    render::SceneDescription scene;
    std::string cameraPath;
    std::optional<RenderSettingsInfo> renderSettings;
    std::size_t primsVisited = 0;
};

DelegateResult populateScene(const usd::Stage& stage, const DelegateOptions& options);

}  // namespace fluence::delegate
