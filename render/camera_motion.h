// A moving camera's place at a time in the shutter (CameraDesc::motionTransforms).
//
// Interpolating a camera's matrices element by element, as instances are (motion_geometry.h),
// would shrink and shear a turning camera between its steps; instead each step's camera-to-world
// is decomposed into a translation, a rotation (a unit quaternion) and a scale along the
// camera's own axes (no shear), and between two steps the translation and the scale move
// linearly and the rotation turns at constant speed along the shorter arc (slerp), recomposed
// as translate * rotate * scale. Steps are evenly spaced over the shutter, as everywhere in
// motion blur: step 0 at its opening, the last at its close.
#pragma once

#include <vector>

#include "core/matrix.h"

namespace fluence::render {

// The camera-to-world at `time` in [0, 1] (clamped) of the steps (at least 2) described above.
Matrix4 cameraTransformAt(const std::vector<Matrix4>& steps, float time);

}  // namespace fluence::render
