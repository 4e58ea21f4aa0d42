// Participating media: the interface every medium implements, and its conventions.
//
// UNITS. Coefficients are per scene unit of length (whatever metersPerUnit says), per RGB channel
// of the rendering space: sigmaA (absorption), sigmaS (scattering), sigmaT = sigmaA + sigmaS
// (extinction). Emission is the radiance Le a medium emits along a ray per unit of absorption:
// dL/dt = -sigmaT L + sigmaA Le + sigmaS (in-scattered), so a purely absorbing, emitting slab
// of optical depth tau glows with Le (1 - e^-tau).
//
// MAJORANTS. A medium describes itself along a ray as consecutive segments [tMin, tMax), each
// with a constant sigmaMaj >= sigmaT at every point of the segment in every channel. Segments
// come in increasing t, do not overlap, and may leave gaps (empty space, where sigmaT = 0).
// Tracking (delta, ratio, and every method that needs transmittance or free-flight sampling) is
// written once against this contract (media/tracking.h) and never looks inside a medium.
// A majorant below the true sigmaT anywhere makes every tracking estimator biased: each
// medium's tests check its majorants bound it (media/majorant_check.h).
//
// MINORANTS. A segment may also carry sigmaMin, 0 <= sigmaMin <= sigmaT at every point of it in
// every channel (the "control" extinction of residual ratio tracking, Novak et al. 2014). It is
// optional: 0, the default, is always a valid minorant. Transmittance estimation draws tentative
// collisions only at the rate sigmaMaj - sigmaMin, so a medium that knows its density is constant
// over a segment (sigmaMin == sigmaT == sigmaMaj) gets its transmittance exactly, with no lookup.
//
// EXACT EXTINCTION. A medium may also describe sigmaT along a ray exactly: consecutive pieces
// [tMin, tMax), in increasing t, over each of which sigmaT is a cubic polynomial in s = t - tMin
// times a constant per channel, and 0 in the gaps between them (a grid's trilinear density in each cell between
// voxel centres, volumes/trilinear_cells.h; a constant). Optical depth is then a piecewise quartic
// in closed form, and media/exact_tracking.h samples distances and transmittances from it with no
// tentative collision. A medium that cannot describe itself so (the default) says so by
// hasExactExtinction() and is only tracked.
//
// DIRECTIONS. Ray directions are unit vectors in world space; t is distance along them.
#pragma once

#include "core/function_ref.h"
#include "core/rgb.h"
#include "core/vec.h"

namespace fluence::media {

// A medium's coefficients at a point.
struct MediumProperties {
    RGB sigmaA{0.0f}, sigmaS{0.0f};
    RGB emission{0.0f};  // Le (see UNITS)
    float g = 0.0f;      // Henyey-Greenstein anisotropy of the phase function, in (-1, 1)
};

// A stretch of a ray over which sigmaMin <= sigmaT <= sigmaMaj (see MAJORANTS, MINORANTS).
struct MajorantSegment {
    float tMin = 0.0f, tMax = 0.0f;
    RGB sigmaMaj{0.0f};
    RGB sigmaMin{0.0f};
};

// A stretch of a ray over which sigmaT_c(t) = scale_c * sum_k polynomial[k] (t - tMin)^k (see EXACT
// EXTINCTION): one cubic, scaled per channel (a grid's density times its extinction factor).
struct ExtinctionPiece {
    double tMin = 0.0, tMax = 0.0;
    double polynomial[4] = {0.0, 0.0, 0.0, 0.0};
    Vec3d scale{0.0};
};

// The optical depth tau_c over a ray's pieces, and how many pieces were summed.
struct OpticalDepth {
    Vec3d tau{0.0};
    int pieces = 0;
};

// Where the hero channel's optical depth along a ray first reaches a target: tStop (< 0 if it never
// does within the range), tau_c and sigmaT_c there (tau_c over the whole range if it never does),
// and how many pieces were visited.
struct DepthCrossing {
    Vec3d tau{0.0}, sigmaT{0.0};
    double tStop = -1.0;
    int pieces = 0;
};

class Medium {
public:
    virtual ~Medium() = default;

    // The coefficients at world-space point p.
    virtual MediumProperties at(const Vec3f& p) const = 0;

    // Calls `visit` with the majorant segments of the ray origin + t direction covering
    // [tMin, tMax), in increasing t, until it returns false or the range is covered.
    virtual void majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                           FunctionRef<bool(const MajorantSegment&)> visit) const = 0;

    // Whether extinctionPieces() describes this medium (see EXACT EXTINCTION).
    virtual bool hasExactExtinction() const { return false; }
    // Calls `visit` with the pieces of the ray origin + t direction within [tMin, tMax), in
    // increasing t, until it returns false or the range is covered; only where hasExactExtinction().
    virtual void extinctionPieces(const Vec3f& /*origin*/, const Vec3f& /*direction*/, float /*tMin*/, float /*tMax*/,
                                  FunctionRef<bool(const ExtinctionPiece&)> /*visit*/) const {}
    // The sums media/exact_tracking.h takes from the pieces within [tMin, tMax) (media/exact_depth.h):
    // by default through extinctionPieces(); a medium may override them with the same visitors
    // inlined into its own walk (same figures, no call per piece).
    virtual OpticalDepth exactOpticalDepth(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax) const;
    virtual DepthCrossing exactDepthCrossing(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                                             int hero, double target) const;
};

}  // namespace fluence::media
