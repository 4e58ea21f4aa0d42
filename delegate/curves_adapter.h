// UsdGeomBasisCurves, UsdGeomNurbsCurves and UsdGeomHermiteCurves as the render core's CurvesDesc
// (render/curves_description.h), in the prim's object space.
//
// BasisCurves: `type` linear or cubic, `basis` bezier, bspline or catmullRom, `wrap` nonperiodic,
// periodic or pinned, checked per curve as UsdGeom's basisCurves.h tabulates them (linear: 2
// vertices or more, 3 when periodic; cubic nonperiodic: 4 + k vstep; periodic: a multiple of vstep,
// at least 3; pinned bspline and catmullRom: 2 or more) and unrolled for Embree: a periodic curve
// repeats its first 4 - vstep vertices (one for linear), a pinned one gains the phantom points
// P[-1] = 2 P[0] - P[1] and P[n] = 2 P[n-1] - P[n-2]. `widths` (fallback 1, interpolation vertex
// by default), `primvars:displayColor` and `normals` may be constant, uniform (per curve), varying
// (per segment end: segments + 1 per curve, segments when periodic) or vertex; each becomes one
// value per control point (varying values at the segment ends they belong to, linearly between
// them for Bezier's inner vertices). Authored normals make normal-oriented ribbons; the primvar
// `primvars:fluence:curveStyle` ("round", "flat" or "ribbon") chooses the style over that.
// Shading primvars (every float, float2, float3 or colour primvar but widths, for a bound
// material's UsdPrimvarReader and texture st; render::CurvePrimvar) keep their interpolation:
// vertex ones per control point (unrolled as the points are, so they follow the curve's basis),
// varying, uniform and constant ones as the values at each segment's two ends (varying ones linear
// between them, as UsdGeomBasisCurves defines them).
//
// NurbsCurves (`order`, `knots`, `pointWeights`, `ranges`): each curve is evaluated (de Boor, in
// homogeneous coordinates for the weights) at 8 points per knot span and drawn as the Catmull-Rom
// curve through them (pinned: it starts and ends where the NURBS curve does). Vertex widths and
// colours, and vertex shading primvars, are evaluated with the same basis; constant, uniform and
// varying ones as for BasisCurves, at the samples.
//
// HermiteCurves (`points`, `tangents`, one per point): each segment from P_i to P_i+1 with tangents
// T_i and T_i+1 is exactly the cubic Bezier segment P_i, P_i + T_i / 3, P_i+1 - T_i+1 / 3, P_i+1,
// and the batch is drawn as those Bezier segments (Embree's native Bezier curves, every style).
// Widths, normals, displayColor and shading primvars are per vertex (vertex and varying alike), per
// curve or constant, and vary linearly along each segment. A curve of fewer than 2 vertices is left
// out with a warning.
//
// A curve whose vertex count fits no row of the tables is left out alone, with a warning (as Hydra
// draws the batch's valid curves); counts that do not add up to the points, widths or normals with
// too few values, or malformed NURBS knots raise SceneError naming the prim (the render index leaves
// it out with a warning). A displayColor or shading primvar with too few values (or an
// interpolation curves do not take) is ignored with a warning: what reads it falls back to its
// constant value. A primvar of exactly one value is constant whatever its interpolation says.
#pragma once

#include <functional>
#include <string>

#include "delegate/material_adapter.h"
#include "delegate/prim_reader.h"
#include "render/curves_description.h"

namespace fluence::delegate {

bool isCurvesType(const std::string& typeName);

// `warn` hears of curves left out for their vertex counts and of primvars ignored for theirs.
render::CurvesDesc curvesFromPrim(const PrimReader& prim, const ColorConverter& convertColor,
                                  const std::function<void(const std::string&)>& warn);

// The curves moved by `toWorld`: points and normals, and radii scaled by the cube root of its
// volume scale (exact for uniform scales).
render::CurvesDesc transformCurves(render::CurvesDesc curves, const Matrix4& toWorld);

}  // namespace fluence::delegate
