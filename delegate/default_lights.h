// The lights a scene with none is rendered under, as usdview and usdrecord light such a scene
// with their camera light: a distant "key" light travelling along the camera's view direction and
// a dim, uniform dome, so geometry shows its shape and colour instead of a black image.
//
// They are added (by SceneDelegate::sceneDescription, with one warning) only when nothing in the
// scene emits: no UsdLux light, no surface whose material emits (a constant emission or one a
// texture or primvar drives), no volume with emission or blackbody emission. The key light's
// irradiance on a surface facing the camera is pi, so a Lambertian surface facing the camera
// shows its albedo; like usdview's camera light it casts no shadows (LightDesc::castsShadows), so
// a camera inside a closed shape (usdchecker's test files) still sees it lit; the dome adds kDefaultDomeRadiance times the albedo where the sky is unoccluded.
// As in usdview, the dome does not paint the background: a camera ray that leaves the scene sees
// black with alpha 0 (the dome still lights the scene and shows in reflections).
#pragma once

#include <vector>

#include "core/sampling.h"
#include "render/scene_description.h"

namespace fluence::delegate {

inline constexpr float kDefaultKeyIrradiance = kPi;
inline constexpr float kDefaultDomeRadiance = 0.1f;

// Whether anything in `scene` emits light: a light, an emissive surface material that a mesh uses,
// or a volume with (blackbody) emission.
bool emitsLight(const render::SceneDescription& scene);

// The default key light (along `camera`'s view direction) and dome.
std::vector<render::LightDesc> defaultLights(const render::CameraDesc& camera);

}  // namespace fluence::delegate
