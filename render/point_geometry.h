// UsdGeomPoints in the render core: Embree's point primitives for a PointsDesc, and the hit on one.
//
// A point set is stored in RenderScene twice: as Embree geometry (spheres, ray-facing discs or
// discs along their normals; RTC_GEOMETRY_TYPE_*_POINT) and, for shading, as a mesh of one
// degenerate triangle (i, i, i) per point whose corners carry the point's colour and primvars, so
// materials, their primvar bindings and RenderScene::primvarAt read a point exactly as they read
// a triangle. A hit shades through that mesh and is then placed on the primitive itself
// (placeOnPoint): its position on the sphere or disc and its normal. Normal maps and texture
// filtering by footprint see no surface tangents on points. Moving points (PointsDesc::motionPositions)
// are Embree geometry with a buffer per time step, and their shading mesh moves with them, so a
// hit and its motion vector (RenderScene::pointAt: the centre's motion) follow the ray's time.
#pragma once

#include "render/points_description.h"
#include "render/ray.h"
#include "render/scene_description.h"

struct RTCDeviceTy;
struct RTCGeometryTy;

namespace fluence::render {

struct SurfaceHit;

// Validates `points` (one radius per point, one normal per point for oriented discs, colours and
// primvars per point, motion steps of one position and radius per point) and throws std::invalid_argument naming it otherwise.
void validatePoints(const PointsDesc& points);
// The committed Embree geometry of `points`.
RTCGeometryTy* pointGeometry(RTCDeviceTy* device, const PointsDesc& points);
// The shading mesh described above: degenerate triangles (i, i, i), corner colours and primvars
// repeated three times.
MeshDesc pointShadingMesh(const PointsDesc& points);
// Moves a hit shaded on the shading mesh onto the primitive the ray met at `t`, whose geometric
// normal Embree gave as `ng` (any length).
void placeOnPoint(SurfaceHit& hit, const Ray& ray, float t, const Vec3f& ng);

}  // namespace fluence::render
