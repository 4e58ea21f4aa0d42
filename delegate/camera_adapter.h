// UsdGeomCamera -> render::CameraDesc (projection, focalLength, horizontal/verticalAperture and
// their offsets, clippingRange, with the schema's fallbacks; the world transform of the prim).
#pragma once

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

render::CameraDesc cameraFromPrim(const PrimReader& prim, const Matrix4& toWorld);

}  // namespace fluence::delegate
