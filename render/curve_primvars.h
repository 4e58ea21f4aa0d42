// The primvars a curve set's material reads (render/curves_description.h, CurvePrimvar), evaluated
// at a hit's curve parameter u, and the material evaluated there (render/material_shader.h).
//
// Per-control-point primvars are Embree vertex attributes of the curve geometry, so that
// rtcInterpolate evaluates them with the curve's own basis (linear, Bezier, B-spline, Catmull-Rom),
// exactly as the positions; per-segment ones are the values at the segment's two ends, mixed
// linearly by u. Each of the shader's primvar slots (MaterialShader::primvarSlots) takes the curve
// primvar of its name; a slot with none (or one past the first kMaxCurvePrimvarSlots) reads its
// fallback. Curves have no st parameterisation across their width: textures are point-sampled at
// their finest level, and normal maps do not apply.
#pragma once

#include <cstddef>
#include <vector>

#include "render/curves_description.h"
#include "render/material_shader.h"

struct RTCGeometryTy;

namespace fluence::render {

inline constexpr std::size_t kMaxCurvePrimvarSlots = 16;

// Throws std::invalid_argument naming the curves when a primvar has no 1 to 4 components or not the
// values its kind needs for `controlPoints` control points and `segments` segments.
void validateCurvePrimvars(const CurvesDesc& curves, std::size_t controlPoints, std::size_t segments);

class CurveShading {
public:
    // The primvars of `curves` that `shader` reads; the per-control-point ones will be vertex
    // attributes of the curve geometry from slot `firstAttribute` on (attributeCount() of them).
    CurveShading(const CurvesDesc& curves, const MaterialShader& shader, unsigned firstAttribute);
    unsigned attributeCount() const { return static_cast<unsigned>(attributes_.size()); }
    // Fills those vertex attribute buffers of `geometry` (whose vertex attribute count the caller
    // has set to at least firstAttribute + attributeCount()), before it is committed.
    void setAttributes(RTCGeometryTy* geometry) const;

    // The material's parameters at curve parameter u of segment `segment` of `geometry`.
    void evaluate(RTCGeometryTy* geometry, unsigned segment, float u, MaterialParams& out) const;

private:
    // A slot's curve primvar: values per segment end, or a vertex attribute slot.
    struct Slot {
        const CurvePrimvar* primvar = nullptr;
        unsigned attribute = 0;
    };
    const MaterialShader* shader_;
    std::vector<CurvePrimvar> primvars_;                // the ones read, in order of first use
    std::vector<unsigned> attributes_;                  // the vertex attribute slot of each per-control-point one
    std::vector<const CurvePrimvar*> perControlPoint_;  // those primvars, parallel to attributes_
    std::vector<Slot> slots_;                           // per shader slot
    std::vector<CornerPrimvar> heads_;                  // per shader slot: the name and components read
    std::vector<const CornerPrimvar*> slotPointers_;    // per shader slot: into heads_, or nullptr
};

}  // namespace fluence::render
