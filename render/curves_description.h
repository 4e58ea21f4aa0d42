// Curves as the render core takes them (hair, fur, grass, wires): Embree's native curve
// primitives, with the parameters of the hair BSDF that shades them. Plain structs, USD-free:
// delegate/curves_adapter.h turns UsdGeomBasisCurves and UsdGeomNurbsCurves into them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/rgb.h"
#include "core/vec.h"

namespace fluence::render {

// The cubic basis (or linear segments) of a curve set's control points, as Embree takes them:
// every segment reads the control points from its `segments` entry on (2 for Linear, 4 for the
// cubics), so periodic and pinned USD curves arrive already unrolled.
enum class CurveBasis { Linear, Bezier, BSpline, CatmullRom };

// How a curve is drawn: a round tube (the default), a flat ribbon that always faces the ray
// (primvars:fluence:curveStyle = "flat"), or a ribbon oriented by authored normals.
enum class CurveStyle { Round, Flat, Oriented };

// The parameters of the hair BSDF (render/bsdfs/hair.h) at a point of a fibre: Chiang et al.
// 2016's absorption coefficient (per unit of the fibre's diameter), longitudinal and azimuthal
// roughness in (0, 1], the fibre's index of refraction, the tilt of its cuticle scales, and where
// across the fibre the ray met it, h in [-1, 1].
struct HairParams {
    RGB absorption{0.0f};
    float longitudinalRoughness = 0.3f;
    float azimuthalRoughness = 0.3f;
    float ior = 1.55f;
    float tiltDegrees = 2.0f;
    float offset = 0.0f;  // h: signed distance of the hit from the fibre's axis, in radii
};

// A primvar a curve's material reads (UsdPrimvarReader, a texture's st; render/material_shader.h),
// `components` (1 to 4) floats per value, evaluated at a hit's curve parameter u: per control
// point, interpolated with the curve's basis as its points are (USD's vertex interpolation), or
// per segment, its values at the segment's two ends, linear between them (varying; uniform and
// constant ones have both ends equal).
struct CurvePrimvar {
    std::string name;
    int components = 1;
    bool perSegment = false;
    std::vector<float> values;  // control points * components, or segments * 2 * components
};

struct CurvesDesc {
    std::string name;  // prim path, for messages
    CurveBasis basis = CurveBasis::Linear;
    CurveStyle style = CurveStyle::Round;
    std::vector<Vec3f> points;            // world-space control points
    std::vector<float> radii;             // one per control point (half the USD width)
    std::vector<Vec3f> normals;           // Oriented: one per control point; else empty
    std::vector<RGB> colors;              // empty, or one per control point: displayColor
    std::vector<std::uint32_t> segments;  // each segment's first control point
    // Motion blur (render/motion_geometry.h): the control points at evenly spaced times over the
    // shutter, the first at its opening and the last at its close, each indexed like `points`
    // (empty: the curves do not move; `points` stays the frame's), and their radii at the same
    // steps (empty: `radii` at every step).
    std::vector<std::vector<Vec3f>> motionPoints{};
    std::vector<std::vector<float>> motionRadii{};
    int material = -1;  // index into SceneDescription::materials, -1 = default
    int linkGroup = 0;  // its light and shadow links (render/light_links.h)
    // The primvars its material may read.
    std::vector<CurvePrimvar> primvars{};
};

}  // namespace fluence::render
