// UsdLux lights -> render::LightDesc.
//
// Units follow UsdLux: the emitted radiance is intensity * 2^exposure * color (so a directly
// seen light of intensity 1, exposure 0, colour white reads 1.0), divided by the light's
// world-space area when inputs:normalize is on (done by the render core, which knows the area).
// Attribute names are read with the "inputs:" prefix and, for files written before USD 21.05,
// without it.
//
// | type         | attributes read (fallback)                                                 |
// |--------------|-----------------------------------------------------------------------------|
// | all          | intensity (1; DistantLight 50000), exposure (0), color (1,1,1), normalize (false) |
// | RectLight    | width (1), height (1)                                                        |
// | SphereLight  | radius (0.5)                                                                  |
// | DistantLight | angle (0.53 degrees)                                                          |
// | DomeLight    | constant colour only (texture:file warns and is ignored in this slice)        |
// enableColorTemperature, light textures and shaping are not supported yet: they warn once.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

bool isLightType(const std::string& typeName);

std::optional<render::LightDesc> lightFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                                               const std::function<void(const std::string&)>& warn);

}  // namespace fluence::delegate
