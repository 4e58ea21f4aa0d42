// A moving camera's place at a time in the shutter (CameraDesc::motionTransforms).
//
// Interpolating a camera's matrices element by element, as instances are (motion_geometry.h),
// would shrink and shear a turning camera between its steps; instead each step's camera-to-world
// is decomposed into a translation, a rotation (a unit quaternion) and a scale along the
// camera's own axes (no shear), and between two steps the translation and the scale move
// linearly and the rotation turns at constant speed along the shorter arc (slerp), recomposed
// as translate * rotate * scale. Steps are evenly spaced over the shutter, as everywhere in
// motion blur: step 0 at its opening, the last at its close. A zoom or a focus pull
// (CameraDesc::motionLenses) moves each lens value linearly between its steps.
#pragma once

#include <vector>

#include "core/matrix.h"
#include "render/scene_description.h"

namespace fluence::render {

// The camera-to-world at `time` in [0, 1] (clamped) of the steps (at least 2) described above.
Matrix4 cameraTransformAt(const std::vector<Matrix4>& steps, float time);

// The lens at `time` in [0, 1] (clamped) of the steps (at least 2).
CameraLensStep cameraLensAt(const std::vector<CameraLensStep>& steps, float time);

// A moving camera's steps (either may be empty: that part stays the frame's).
struct CameraMotion {
    std::vector<Matrix4> transforms;
    std::vector<CameraLensStep> lenses;
};

}  // namespace fluence::render
