// The lights a LightDesc describes (the UsdLux types of LightType), made from one table
// (light_registry.cpp): for each LightType, the function that makes its light and whether the
// light it makes is a delta light (a point, a line, a distant light of angle 0: no ray can hit
// it). Adding a light type is a row there; nothing else in the render core or the integrators
// switches on a LightType.
#pragma once

#include <memory>

#include "render/light.h"
#include "render/scene_description.h"

namespace fluence::render {

// The light `desc` describes. Throws std::invalid_argument for a type without a row.
std::unique_ptr<Light> makeLight(const LightDesc& desc);

// Whether makeLight(desc) is a delta light, read from the description alone (without making the
// light: a dome's sampling distribution is not built to answer it).
bool isDeltaLight(const LightDesc& desc);

}  // namespace fluence::render
