// The metadata fields USD registers (Sdf's schema plus the Usd, UsdGeom, UsdShade and
// UsdRender plugins), so the reader can flag an unregistered field as USD does, and the values
// of the fields Sdf restricts to a fixed set. Internal to the scene library.
#pragma once

#include <string>
#include <string_view>

namespace fluence::usd::detail {

bool isRegisteredMetadataField(std::string_view name);

// The unit names of Sdf's unit registry that `displayUnit` accepts: lengths (mm, cm, dm, m, km,
// in, ft, yd, mi), angles (deg, rad) and "default" (dimensionless). Sdf's percent unit, "%", is
// not an identifier and cannot be written in a text layer.
bool isDisplayUnit(std::string_view name);
std::string displayUnitNames();  // "mm, cm, ..." for messages

}  // namespace fluence::usd::detail
