// UsdGeomCamera -> render::CameraDesc (projection, focalLength, horizontal/verticalAperture and
// their offsets, clippingRange, fStop and focusDistance (depth of field) and the fluence:camera:
// apertureBlades (0, round; or 3 to 64) and apertureRotation (degrees) attributes, with the schema's
// fallbacks; the world transform of the prim), and
// the default camera of a stage that has none.
#pragma once

#include "core/matrix.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

render::CameraDesc cameraFromPrim(const PrimReader& prim, const Matrix4& toWorld);

// A camera with UsdGeomCamera's fallback lens that frames everything `scene` holds (meshes,
// points' centres, instances; light shapes excluded) as usdview's and usdrecord's free camera does: looking along
// -Z with +Y up on a Y-up stage, along +Y with +Z up on a Z-up stage, far enough back that the
// bounding sphere fits the narrower field of view. An empty scene is framed as a unit sphere at
// the origin.
render::CameraDesc framingCamera(const render::SceneDescription& scene, char upAxis);

}  // namespace fluence::delegate
