// The multiple-importance weights of bidirectional path tracing (integrators/bdpt.h): Veach's
// power heuristic (beta = 2) over the strategies that build one path, computed from the densities
// of its vertices as in Veach's thesis, ch. 10.2, and pbrt's BDPT (Pharr, Jakob & Humphreys,
// "Physically Based Rendering", 3rd/4th ed., "Bidirectional Path Tracing", MISWeight).
//
// THE PATH. x_0 ... x_k: x_0 on a light, x_k the camera. Strategy s (0 <= s <= k - 1) draws
// x_0 ... x_{s-1} by the light subpath and x_s ... x_k by the camera subpath, and joins x_{s-1}
// to x_s (s = 0: the camera subpath hits the light itself). Strategy s = k (t = 1) is light
// tracing: the light subpath's x_{k-1} joined to the camera x_k, splatting into the pixel it lands
// on; it exists only when StrategyPath::lightTracing says the render uses it (a perspective camera and
// a film that is the whole image, integrators/bdpt.h), and for k >= 2 (a light seen directly is
// left to s = 0). t = 0 (a light subpath hitting the camera) never exists. The weights sum to one
// over the strategies that exist.
//
// THE DENSITIES, per vertex and in the measure of the path (area; solid angle for a light at
// infinity's x_0): fromLight is the density with which the light subpath would draw x_i from
// x_{i-1} (x_0: choosing the light for emission times its emission density; 0 if it offers none),
// fromCamera that of the camera subpath drawing x_i from x_{i+1}. A delta scattering at x_i makes
// the density of its neighbours drawn through it a Dirac delta, which is stored as 1 on both
// sides (the same delta, so it cancels between the strategies that hold it, and any strategy that
// would join a path at x_i is excluded). The camera x_k is a pinhole, a delta in position for every
// strategy alike, or a point of a thin lens's aperture, drawn uniformly over it by every strategy
// alike (camera rays and light tracing's joins), so it enters no ratio (its densities are stored
// as 1); x_{k-1}.fromCamera is the camera's density of its ray from x_k towards x_{k-1} over the
// whole image (render/camera.h, directionDensity), as an area density: one light path is traced per camera sample, so light
// tracing draws as many paths per pixel as the camera does, and the two densities compare. Strategy 1 is next-event estimation, which chooses the
// light with the light tree and samples it by its own sampler: x_0's density under it,
// `neeOrigin`, takes the place of x_0.fromLight for s = 1 alone.
//
// A strategy exists when its join is between two non-delta vertices (x_0 counts as non-delta for
// s = 1: next-event estimation reaches point lights) and, for s = 0, when x_0 can be hit (not a
// delta light). Its density p_s is the product of the light densities of x_0 ... x_{s-1} and the
// camera densities of x_s ... x_k, and its weight p_s^2 / sum over existing strategies of p^2.
// The ratios p_s' / p_s are accumulated outwards from s, so only densities that strategy s
// actually sampled with (never zero) appear in denominators. A vertex inside a material's interior
// (a random walk's scattering, integrators/bdpt.h) is not `joinable`: no strategy joins there, so
// it excludes strategies as a delta vertex does, but its densities are real ones.
//
// MEDIA (StrategyPath::hero >= 0). A medium vertex is measured per unit volume: its densities
// carry no cosine. Every path edge e (x_{i-1} to x_i, stored at x_i) is crossed either by a free
// flight (delta tracking, media/free_flight.h), whose density is DT(e) = Tmaj(e) prod sigmaN over
// its null points (times sigmaS at a medium vertex it ends at), or, as the join of a strategy, by
// ratio tracking, RT(e) (media/ratio_tracking.h). A medium vertex is always reached by a flight of
// its own subpath, so its sigmaS is in every strategy's density; the strategies differ only in
// which edge is joined: p_s = g_s A RT(e_s) / DT(e_s), with g_s the densities above (directions,
// emission, no transmittance), A the product over every edge of DT and over every medium vertex of
// sigmaS (the same for all strategies). The weights use a model of these densities, the same
// function of the path whichever strategy drew it (which is what keeps the estimator unbiased):
//     p~_{c,s} = g_s prod_{e != e_s} Tmaj_c(e) prod_{medium x_i} sigmaS_c(x_i) [p_{c,s} > 0],
// channel c's majorant transmittance standing in for RT / DT. Through a homogeneous medium (every
// material interior) the majorant is exact and no null point is drawn: p~ is the true density.
// Through a heterogeneous one it is a model, but a consistent one, and the indicator (whether
// channel c's tracking could draw the path's null points: EdgeMedia's masks, from the estimators'
// own density ratios) keeps every weight zero where its strategy cannot draw the path.
//
// SPECTRAL MIS. Distances are drawn at one hero channel h's rates (media/tracking.h). The hero and
// the strategy are one technique (h, s): the power heuristic over all of them, with the hero
// chosen uniformly (one-sample MIS over heroes, every strategy evaluated), gives for channel c the
// estimate (f_c / p_{h,s}) * 3 / sum_{c', s'} (p~_{c',s'} / p~_{h,s})^2: misWeight() returns the
// factor after f_c / p_{h,s}. With a gray medium or none it is the power heuristic over strategies.
// A hero that cannot draw a path (a channel a medium does not scatter) gets no weight for it.
#pragma once

#include <span>

#include "core/rgb.h"

namespace fluence::integrators {

// How the edge from x_{i-1} to x_i crosses media (MEDIA above); all zero optical depth and
// possible in empty space.
struct EdgeMedia {
    RGB majorantDepth{0.0f};   // the integral of sigmaMaj along the edge, per channel
    RGB flightPossible{1.0f};  // 1 where delta tracking in that channel draws its null points with density > 0
    RGB joinPossible{1.0f};    // 1 where ratio tracking in that channel does
};

struct VertexDensity {
    VertexDensity(float fromLight_ = 0.0f, float fromCamera_ = 0.0f, bool delta_ = false, bool joinable_ = true,
                  const RGB& sigmaS_ = RGB(1.0f), const EdgeMedia& edge_ = {})
        : fromLight(fromLight_),
          fromCamera(fromCamera_),
          delta(delta_),
          joinable(joinable_),
          sigmaS(sigmaS_),
          edge(edge_) {}

    float fromLight = 0.0f;
    float fromCamera = 0.0f;
    bool delta = false;    // x_i scatters by a delta lobe on this path
    bool joinable = true;  // a strategy may join at x_i (not a scattering inside a material's interior)
    RGB sigmaS{1.0f};      // at a medium vertex, its scattering coefficient; 1 on surfaces
    EdgeMedia edge;        // from x_{i-1} to x_i (unused at x_0)
};

struct StrategyPath {
    std::span<const VertexDensity> vertices;  // x_0 ... x_k
    float neeOrigin = 0.0f;                   // x_0's density under next-event estimation from x_1
    bool lightHittable = true;                // x_0 is not on a delta light
    int hero = -1;                            // the hero channel in a scene with media; -1: none
    bool lightTracing = false;                // strategy s = k (t = 1) is used
};

// Whether strategy s can produce the path.
bool strategyExists(const StrategyPath& path, int s);

// The weight of strategy s (which must exist) for the path: its power-heuristic weight, and, with
// media, the spectral factor above (to multiply f_c / p_{h,s} by; it may exceed 1).
float misWeight(const StrategyPath& path, int s);

}  // namespace fluence::integrators
