// The metadata fields USD registers (Sdf's schema plus the Usd, UsdGeom, UsdShade and
// UsdRender plugins), so the reader can flag an unregistered field as USD does. Internal to
// the scene library.
#pragma once

#include <string_view>

namespace fluence::usd::detail {

bool isRegisteredMetadataField(std::string_view name);

}  // namespace fluence::usd::detail
