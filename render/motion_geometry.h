// Motion blur in Embree: geometry with time steps, and where it is at a ray's time.
//
// Motion is given at N >= 2 evenly spaced steps over the shutter, step 0 at its opening and step
// N-1 at its close (MeshDesc::motionPositions, InstanceDesc::motionTransforms); between steps it
// is linear, as Embree interpolates it: vertex positions, and the 3x4 matrices of instances
// element by element. A ray at time t in [0, 1] (render::Ray::time) meets the geometry where this
// interpolation puts it, and a hit is shaded there too (the functions below compute the same
// interpolation in single precision).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "core/vec.h"

struct RTCGeometryTy;  // Embree's geometry handle (embree3/rtcore_geometry.h)
struct RTCDeviceTy;    // Embree's device handle (embree3/rtcore_device.h)

namespace fluence::render {

// Where `time` falls among `steps` evenly spaced time steps: the segment's first step and the
// fraction of the way to the next (steps >= 2; time clamped to [0, 1]).
struct MotionSegment {
    std::size_t step = 0;
    float fraction = 0.0f;
};
MotionSegment motionSegment(std::size_t steps, float time);

// The position of vertex `index` at `time` (steps: at least 2 position sets of equal size).
Vec3f positionAt(const std::vector<std::vector<Vec3f>>& steps, std::uint32_t index, float time);
// The transform at `time` (steps: at least 2), interpolated element by element.
Matrix4 transformAt(const std::vector<Matrix4>& steps, float time);

// A triangle geometry (uncommitted) with one vertex buffer per time step: `positions` alone when
// `motion` is empty, else each of `motion` (its time steps).
RTCGeometryTy* newTriangleGeometry(RTCDeviceTy* device, const std::vector<Vec3f>& positions,
                                   const std::vector<std::vector<Vec3f>>& motion,
                                   const std::vector<std::uint32_t>& indices);
// Fills the vertex buffers of a curve or point geometry with (x, y, z, radius) per vertex (radii
// below 0 read as 0): `points` and `radii` alone when `motionPoints` is empty, else one buffer per
// time step, its radii from `motionRadii` (or `radii` when that is empty); and, when `normals` is
// not empty, the same normals at every time step (oriented ribbons and discs keep the frame's).
void setPointRadiusBuffers(RTCGeometryTy* geom, const std::vector<Vec3f>& points, const std::vector<float>& radii,
                           const std::vector<std::vector<Vec3f>>& motionPoints,
                           const std::vector<std::vector<float>>& motionRadii, const std::vector<Vec3f>& normals);
// Sets an instance's transform: `transform` alone when `motion` is empty, else each of `motion`.
void setInstanceTransforms(RTCGeometryTy* instance, const Matrix4& transform, const std::vector<Matrix4>& motion);

// Throws std::invalid_argument, naming `name`, unless `motion` is empty or holds at least two
// position sets of `vertices` positions each.
void checkMotionPositions(const std::string& name, const std::vector<std::vector<Vec3f>>& motion, std::size_t vertices);
// Throws std::invalid_argument, naming `name`, unless `radii` is empty or holds one set of
// `vertices` radii per time step of `motion`.
void checkMotionRadii(const std::string& name, const std::vector<std::vector<float>>& radii,
                      const std::vector<std::vector<Vec3f>>& motion, std::size_t vertices);

}  // namespace fluence::render
