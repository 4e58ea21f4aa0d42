// The multiple-importance weights of bidirectional path tracing (integrators/bdpt.h): Veach's
// power heuristic (beta = 2) over the strategies that build one path, computed from the densities
// of its vertices as in Veach's thesis, ch. 10.2, and pbrt's BDPT (Pharr, Jakob & Humphreys,
// "Physically Based Rendering", 3rd/4th ed., "Bidirectional Path Tracing", MISWeight).
//
// THE PATH. x_0 ... x_k: x_0 on a light, x_k the camera. Strategy s (0 <= s <= k - 1) draws
// x_0 ... x_{s-1} by the light subpath and x_s ... x_k by the camera subpath, and joins x_{s-1}
// to x_s (s = 0: the camera subpath hits the light itself). Strategies with t = k + 1 - s < 2
// (light tracing to the camera, splatting into other pixels) are not part of Fluence's BDPT, so
// the weights sum to one over s = 0 ... k - 1 alone.
//
// THE DENSITIES, per vertex and in the measure of the path (area; solid angle for a light at
// infinity's x_0): fromLight is the density with which the light subpath would draw x_i from
// x_{i-1} (x_0: choosing the light for emission times its emission density; 0 if it offers none),
// fromCamera that of the camera subpath drawing x_i from x_{i+1}. A delta scattering at x_i makes
// the density of its neighbours drawn through it a Dirac delta, which is stored as 1 on both
// sides (the same delta, so it cancels between the strategies that hold it, and any strategy that
// would join a path at x_i is excluded). Strategy 1 is next-event estimation, which chooses the
// light with the light tree and samples it by its own sampler: x_0's density under it,
// `neeOrigin`, takes the place of x_0.fromLight for s = 1 alone.
//
// A strategy exists when its join is between two non-delta vertices (x_0 counts as non-delta for
// s = 1: next-event estimation reaches point lights) and, for s = 0, when x_0 can be hit (not a
// delta light). Its density p_s is the product of the light densities of x_0 ... x_{s-1} and the
// camera densities of x_s ... x_k, and its weight p_s^2 / sum over existing strategies of p^2.
// The ratios p_s' / p_s are accumulated outwards from s, so only densities that strategy s
// actually sampled with (never zero) appear in denominators.
#pragma once

#include <span>

namespace fluence::integrators {

struct VertexDensity {
    float fromLight = 0.0f;
    float fromCamera = 0.0f;
    bool delta = false;  // x_i scatters by a delta lobe on this path
};

struct StrategyPath {
    std::span<const VertexDensity> vertices;  // x_0 ... x_k
    float neeOrigin = 0.0f;                   // x_0's density under next-event estimation from x_1
    bool lightHittable = true;                // x_0 is not on a delta light
};

// Whether strategy s can produce the path.
bool strategyExists(const StrategyPath& path, int s);

// The power-heuristic weight of strategy s (which must exist) for the path.
float misWeight(const StrategyPath& path, int s);

}  // namespace fluence::integrators
