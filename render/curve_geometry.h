// Curves in the render scene: each CurvesDesc one Embree native curve geometry (round tubes,
// flat ribbons facing the ray, or normal-oriented ribbons; linear, Bezier, B-spline or
// Catmull-Rom segments; render/curves_description.h), and the SurfaceHit of a ray that meets one.
// Moving curves (CurvesDesc::motionPoints) have a vertex buffer per time step; a hit is shaded
// where the curve is at the ray's time.
//
// A hit's frame follows the fibre: the tangent is the curve's derivative at the hit, and the
// shading and geometric normals are the normal of the ribbon that faces the ray (an oriented
// ribbon's own normal), perpendicular to the tangent, on the ray's side. Across the curve, the
// hit's offset from the axis in radii (HairParams::offset) is measured along normal x tangent.
// The hit's material is the hair BSDF (render/hair_material.h) of its material evaluated at the hit
// (its primvar readers and textures reading the curve's primvars at u, render/curve_primvars.h),
// its colour the material's diffuse there, or the curve's displayColor interpolated with the
// curve's own basis where no material is bound. Materials' emission is not evaluated on curves.
//
// A round tube is seen from outside only: a ray that meets one from inside (one that went through
// the fibre, the hair BSDF's transmission) passes out through it (an Embree filter drops the hit
// where the ray leaves the tube), so light crosses a fibre as the BSDF says and not twice.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "render/material_shader.h"
#include "render/ray.h"
#include "render/scene_description.h"

struct RTCDeviceTy;
struct RTCGeometryTy;
struct RTCSceneTy;

namespace fluence::render {

struct SurfaceHit;

class CurveGeometry {
public:
    CurveGeometry();
    ~CurveGeometry();
    CurveGeometry(const CurveGeometry&) = delete;
    CurveGeometry& operator=(const CurveGeometry&) = delete;

    // Validates `desc` (std::invalid_argument naming it when its arrays disagree), makes its Embree
    // geometry and attaches it to `scene` as `geomID`.
    void add(RTCDeviceTy* device, RTCSceneTy* scene, unsigned geomID, const CurvesDesc& desc,
             const std::vector<MaterialDesc>& materials, const std::vector<MaterialShader>& shaders,
             std::uint32_t objectName, std::uint32_t materialName);
    // Whether the surface geometry `geomID` is one of these curves.
    bool contains(unsigned geomID) const;
    // The hit of `ray` on segment primID of curve geometry geomID at curve parameter u, distance t,
    // with Embree's geometric normal ng.
    std::optional<SurfaceHit> shade(unsigned geomID, unsigned primID, float u, const Ray& ray, float t,
                                    const Vec3f& ng) const;
    // The point on the axis of segment primID of curve geometry geomID at curve parameter u, at
    // `time` in the shutter (render/motion_geometry.h).
    Vec3f centreAt(unsigned geomID, unsigned primID, float u, float time) const;
    // Grows [lo, hi] by every control point's sphere, at every time step.
    void growBounds(Vec3f& lo, Vec3f& hi) const;
    std::size_t segmentCount() const { return segments_; }

private:
    struct Curves;
    // The axis point (and radius) and its derivative along the curve at `time`: Embree's vertex
    // buffers interpolated at u, then between the two time steps around `time`.
    static void interpolate(const Curves& curves, unsigned primID, float u, float time, float centre[4],
                            float derivative[4]);
    std::vector<Curves> curves_;
    std::vector<int> byGeomID_;  // Embree geometry id -> into curves_, or -1
    std::size_t segments_ = 0;
};

}  // namespace fluence::render
