// UsdGeomXformable: a prim's local transform from its xformOpOrder.
//
// Supported ops: translate, scale, rotateX/Y/Z, rotateXYZ/XZY/YXZ/YZX/ZXY/ZYX (degrees), orient
// (quaternion, real part first), transform (matrix4d), each optionally suffixed
// ("xformOp:translate:pivot") and optionally inverted ("!invert!xformOp:translate:pivot"), and
// "!resetXformStack!". Ops apply to points from last to first, as in USD: for
// ["xformOp:translate", "xformOp:rotateXYZ", "xformOp:scale"], points are scaled, then rotated,
// then translated. An op xformOpOrder names that has no value (no attribute, or one with neither a
// default nor time samples) is skipped with a warning, as UsdGeomXformable skips it.
#pragma once

#include <functional>
#include <string>

#include "core/matrix.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

struct LocalTransform {
    Matrix4 matrix = Matrix4::identity();
    bool resetsXformStack = false;  // the parent's transform does not apply
};

LocalTransform localTransform(const PrimReader& prim, const std::function<void(const std::string& message)>& warn);

}  // namespace fluence::delegate
