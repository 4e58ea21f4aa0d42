// A UsdLux light that moves while the shutter is open (LightDesc::motionTransforms).
//
// The delegate gives a moving light its light-to-world transform at the same evenly spaced motion
// steps as a moving instance (delegate/motion_samples.h), and the transform at a ray's time is
// interpolated between steps as an instance's is (render/motion_geometry.h: transformAt, element
// by element). A light is not deformed by its motion: the light at time t is the frame's light
// carried by the rigid motion that takes the light's origin to where the transform at t puts it
// (so it travels exactly as an instance's origin does) and turns it by the rotation of the
// transform at t relative to the frame's (the rotation nearest to it, its polar factor: between
// two steps that turn, the element-by-element interpolation itself is not a rotation). A light
// that only translates is moved exactly as geometry would be. Sampling a light at a time
// (render/light_at_time.h) maps the query into the frame's light by the inverse motion and the
// answer back; distances, solid angles and radiance are unchanged by a rigid motion.
#pragma once

#include <vector>

#include "core/matrix.h"
#include "render/light.h"

namespace fluence::render {

// A rigid motion and its inverse (rotation and translation only).
struct RigidMotion {
    Matrix4 forward;  // the frame's light to where it is at the time
    Matrix4 inverse;

    Vec3f point(const Vec3f& p) const { return Vec3f(forward.transformPoint(Vec3d(p))); }
    Vec3f vector(const Vec3f& v) const { return Vec3f(forward.transformVector(Vec3d(v))); }
    Vec3f pointBack(const Vec3f& p) const { return Vec3f(inverse.transformPoint(Vec3d(p))); }
    Vec3f vectorBack(const Vec3f& v) const { return Vec3f(inverse.transformVector(Vec3d(v))); }
};

class LightMotion {
public:
    // `frame`: the light-to-world the light was made with; `steps`: at least two.
    LightMotion(const Matrix4& frame, std::vector<Matrix4> steps);

    // The motion from the frame's light to the light at `time` in [0, 1] (clamped).
    RigidMotion at(float time) const;
    // Whether the light turns during the shutter (else it only translates).
    bool turns() const { return turns_; }
    // A bound holding the frame's light's bound `frame` at every time of the shutter: the box
    // carried along by each step's translation (exact between steps, where translation is linear)
    // for a light that only translates; for one that turns, the box around each step's origin of
    // the ball (about the light's origin) that holds the frame's box whatever the rotation, with
    // normals in every direction.
    LightBounds sweptBounds(const LightBounds& frame) const;

private:
    Matrix4 frame_;
    std::vector<Matrix4> steps_;
    bool turns_ = false;
};

// The union of bounds over a light's places in the shutter: the boxes' union, the largest
// power, and the normal cone kept only where every place has the same (else every direction).
LightBounds unionOfLightBounds(const std::vector<LightBounds>& places);

}  // namespace fluence::render
