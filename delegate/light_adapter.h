// UsdLux lights -> render::LightDesc (the sync phase of a LightSprim).
//
// Units follow UsdLux: the emitted radiance is intensity * 2^exposure * color (so a directly
// seen light of intensity 1, exposure 0, colour white reads 1.0), times the colour temperature's
// tint when enabled, divided by the light's world-space area when inputs:normalize is on (done
// by the render core, which knows the area). Attribute names are read with the "inputs:" prefix
// and, for files written before USD 21.05, without it (treatAsPoint, treatAsLine and poleAxis
// have no prefix in either).
//
// | type          | attributes read (fallback)                                                  |
// |---------------|-----------------------------------------------------------------------------|
// | all           | intensity (1; DistantLight 50000), exposure (0), color (1,1,1),              |
// |               | normalize (false), enableColorTemperature (false), colorTemperature (6500)   |
// | RectLight     | width (1), height (1), texture:file (none)                                   |
// | DiskLight     | radius (0.5)                                                                 |
// | SphereLight   | radius (0.5), treatAsPoint (false)                                           |
// | CylinderLight | length (1), radius (0.5), treatAsLine (false)                                |
// | DistantLight  | angle (0.53 degrees)                                                         |
// | DomeLight     | texture:file (none), texture:format (automatic)                              |
// | DomeLight_1   | as DomeLight, and poleAxis (scene)                                           |
// | ShapingAPI    | shaping:cone:angle (90), shaping:cone:softness (0), shaping:focus (0),        |
// |               | shaping:focusTint (0,0,0): read on rect, disk, sphere and cylinder lights     |
// |               | that apply ShapingAPI or author any of them (render/light_shaping.h);         |
// |               | shaping:ies:file (none), shaping:ies:angleScale (0), shaping:ies:normalize    |
// |               | (false): the profile read by texture/ies_file.h (render/ies_profile.h)        |
//
// - Colour temperature: color is multiplied by core/blackbody.h's blackbodyRgb divided by that of
//   6500 K and scaled to luminance 1, so 6500 K is exactly white as the clarified UsdLux
//   documentation (OpenUSD PR 3182) requires; clamped with a warning to UsdLux's valid 1000-10000 K.
// - inputs:diffuse and inputs:specular other than 1 warn and are not applied.
// - Textures are read by texture::loadImage (linear; sRGB files decoded; the alpha channel and any
//   channel past the third are dropped, one channel is grey). A file that cannot be read warns,
//   naming it, and the light keeps its constant colour.
// - DomeLight texture:format: "latlong", and "automatic" (which warns when the image is not 2:1),
//   read the image as a lat-long map; "mirroredBall", "angular" and "cubeMapVerticalCross" warn
//   and fall back to the constant colour.
// - DomeLight_1 poleAxis: "Y" keeps the OpenEXR lat-long orientation (top +Y, longitude 0 along
//   +Z); "Z" turns the dome +90 degrees about X so its top is +Z and longitude 0 looks along -Y,
//   as UsdLux says; "scene" follows the stage's upAxis. DomeLight always has its pole on +Y.
// - treatAsPoint / treatAsLine render the point and line lights of render/lights/point_light.h and
//   render/lights/line_light.h. A normalized sphere of radius 0 is a point light, a normalized
//   cylinder of radius 0 a line light; unnormalized, they emit nothing and are skipped with a
//   warning.
// - An IES file that is missing or cannot be read warns, naming it (file:line for a malformed
//   one), and the light is rendered without the profile (a missing file is an error before the
//   render starts unless --allow-missing, as every missing input asset is).
// - Not supported, with one warning each: shaping on dome and distant lights.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

bool isLightType(const std::string& typeName);
// Whether the prim's composed apiSchemas apply `schema` ("ShapingAPI", "MeshLightAPI").
bool appliesSchema(const usd::PrimSpec& prim, const std::string& schema);

// Whether the prim authors any shaping input (inputs:shaping:*, or shaping:* before USD 21.05).
bool authorsShaping(const usd::PrimSpec& prim);

// The prim's ShapingAPI inputs (cone, focus, IES profile: a profile that cannot be read warns and
// is left out), as every shaped light reads them.
render::LightShapingDesc shapingOf(const PrimReader& prim, const std::function<void(const std::string&)>& warn);

// UsdLuxLightAPI's radiance, as every light reads it: intensity (fallback `fallbackIntensity`) *
// 2^exposure * color, times the colour temperature's tint when enabled. Warns about connected
// inputs and diffuse or specular multipliers other than 1 (neither is applied).
RGB lightApiRadiance(const PrimReader& prim, double fallbackIntensity,
                     const std::function<void(const std::string&)>& warn);

// `stageUpAxis` ('Y' or 'Z') orients a DomeLight_1 whose poleAxis is "scene".
std::optional<render::LightDesc> lightFromPrim(const PrimReader& prim, const Matrix4& toWorld, char stageUpAxis,
                                               const std::function<void(const std::string&)>& warn);

}  // namespace fluence::delegate
