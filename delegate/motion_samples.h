// Motion blur read from the stage: what moves while the camera's shutter is open.
//
// The shutter is the camera's `shutter:open` and `shutter:close`, time codes relative to the
// frame (UsdGeomCamera; both 0 by default: an instant, no blur). Motion is sampled at evenly
// spaced steps over it, the first at its opening and the last at its close (Embree interpolates
// linearly between steps, render/motion_geometry.h): as few steps as put one on every time sample
// authored strictly inside the shutter, so several segments follow a motion keyed inside it, and
// at most kMaxMotionSteps. The frame's delegate is moved to each step (SceneDelegate::setMotionStep:
// only the animated prims are read again) and describes the scene there, and what moved between
// steps is handed to the render core:
//   - a world mesh whose positions differ between steps (a time-sampled xform of it or of an
//     ancestor, time-sampled `points`, skinned points) gets MeshDesc::motionPositions, provided
//     its triangles stay the same at every step (else it renders still, with a warning);
//   - curves (BasisCurves, NurbsCurves) and points whose control points, positions or widths
//     differ between steps get CurvesDesc::motionPoints / PointsDesc::motionPositions (and
//     motionRadii where the widths change), provided their segments or point count stay the same
//     (gathered by delegate/motion_steps.h);
//   - an instance (native, or of a PointInstancer) whose transform differs gets
//     InstanceDesc::motionTransforms;
//   - a Mesh's, Points' or curves' points that are not time-sampled move by their `velocities` (units per second) and
//     `accelerations`, as UsdGeomPointBased::ComputePointsAtTime moves them, and PointInstancer
//     instances by `velocities` and `angularVelocities` (degrees per second) (applied at sync
//     when DelegateOptions::velocityFrame is set: moveByVelocities, instanceVelocityMotion).
//   - the camera, when its transform differs between steps, gets CameraDesc::motionTransforms,
//     and when its focalLength, fStop or focusDistance does (a zoom, a focus pull),
//     CameraDesc::motionLenses (render/camera_motion.h).
//   - a UsdLux light whose transform differs gets LightDesc::motionTransforms (its time-sampled
//     xform or an ancestor's; the render core moves it rigidly, render/light_motion.h); an
//     emissive mesh moves as any world mesh does, and its triangles are sampled where they are at
//     a ray's time.
//   - the meshes, curves and points of a shared prototype that deform (skinned, time-sampled or
//     velocity-moved points, moved inside the prototype) get the same time steps, in prototype
//     space (PrototypeMotionSteps): every instance of the prototype deforms alike.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "core/vec.h"
#include "delegate/prim_reader.h"
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

struct DelegateOptions;
class SceneDelegate;

inline constexpr int kMaxMotionSteps = 33;

// The time codes of the motion steps over [frame + open, frame + close] (see above).
std::vector<double> motionStepTimes(const usd::Stage& stage, double frame, double open, double close);

// Moves a point-based prim's `positions` (one per point, already through `toWorld`) from the
// `velocityFrame` to `time` by its `velocities` and `accelerations` read at the frame, when its
// `points` are not time-sampled and the velocities have one entry per point (else nothing moves).
void moveByVelocities(const usd::Stage& stage, const usd::PrimSpec& prim, double time, double velocityFrame,
                      const Matrix4& toWorld, std::vector<Vec3f>& positions);

// `prim` with its `points` moved from the `velocityFrame` to `time` as moveByVelocities moves
// them (a copy, for the adapters that read points they process further: curves); nullptr when
// they do not move.
std::unique_ptr<usd::PrimSpec> withPointsMovedByVelocities(const usd::Stage& stage, const usd::PrimSpec& prim,
                                                           double time, double velocityFrame);

// A PointInstancer's instances moved from `velocityFrame` to `time`: for instance i, the offset
// of its position and the rotation applied before its orientation. Nullopt when `positions` are
// time-sampled or no velocities are authored.
struct InstanceVelocityMotion {
    std::vector<Vec3d> offsets;      // empty: no `velocities`
    std::vector<Matrix4> rotations;  // empty: no `angularVelocities`
};
std::optional<InstanceVelocityMotion> instanceVelocityMotion(const usd::Stage& stage, const usd::PrimSpec& instancer,
                                                             double time, double velocityFrame, std::size_t count);

// Whether `prim` moves by `velocities` or `angularVelocities` during the shutter (authored, with
// `points` or `positions` not time-sampled).
bool movesByVelocities(const usd::PrimSpec& prim);
// Whether `root` or a prim below it moves so (a prototype's contents).
bool movesByVelocitiesAtOrBelow(const usd::PrimSpec& root);

// Adds the motion over `camera`'s shutter to `scene`, which `delegate` described from `stage` by
// `options` at the frame (see above); leaves `delegate` at the shutter's close. Warns through
// options.warn what cannot move.
void addMotion(SceneDelegate& delegate, usd::Stage& stage, const DelegateOptions& options,
               const render::CameraDesc& camera, render::SceneDescription& scene);

}  // namespace fluence::delegate
