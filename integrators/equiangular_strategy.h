// Equiangular sampling towards local lights in the path tracer's media: the strategy, and the
// densities the multiple-importance weights of every light-reaching medium vertex need.
//
// THE STRATEGY. For each stretch of a ray through the scene's volumes (not inside a material's
// interior), before its free flight: the stretch's medium segment (mediumSegment: from where the
// medium's first non-zero majorant begins along the ray to the surface the ray hits, unbounded if
// none; finding where the medium ends would walk the whole majorant grid, which cost more than the
// points drawn beyond it, rejected by one lookup); a light chosen by the light tree from the ray's origin (no normal), and kept if it has a position
// (bounds: point, sphere, spot, rect, disk, cylinder lights and emissive triangles; a light at
// infinity gives the stretch no sample); a distance t on the segment drawn equiangularly about
// the centre of the light's bounds (media/equiangular.h); the transmittance to x(t) by ratio
// tracking; then next-event estimation of that light from x(t), as at a free flight's scattering.
//
// THE WEIGHTS (the balance heuristic in the spectral-MIS form of media/tracking.h). A path whose
// last medium vertex x(t) connects to a point y on a light is produced by three strategies:
//   free flight + light sampling   (delta-tracked null points and t; the light tree at x(t), y)
//   free flight + phase sampling   (delta-tracked null points and t; wi; the flight that reaches y)
//   equiangular + light sampling   (the light tree at the origin, t; ratio-tracked null points; y)
// Their densities per channel c, over the hero's density of the strategy that drew the path:
//   pA_c = T_null,c sigmaS_c(t)                 delta tracking's density of the null points and t
//   pB_c = pEq(t) Q_c                           Q: ratio tracking's density of the same null points
// times the light's (lightTree(x) lightPdf(y) or phase pdf, and the shadow ray's own densities).
// The path tracer carries rE = the path's density ratio had its last medium vertex been drawn by
// this strategy, without pEq and the light's density (MisState::rE), beside rU and rL; every
// light-reaching weight then has the form f / average(rU + rL lightPdf + rE pEq lightPdf). A
// free flight supplies Q for its own null points (FreeFlight::ratioTrackedPdfRatio). The weights
// sum to 1 over the three strategies and the three heroes for every path, so the estimate is
// unbiased; paths to lights at infinity and through surfaces are weighted as before (rE = 0).
#pragma once

#include <optional>
#include <vector>

#include "core/vec.h"
#include "media/equiangular.h"
#include "media/medium.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// The stretch origin + t direction, t in [tMin, tMax], over which the strategy draws t.
struct MediumSegment {
    Vec3f origin, direction;
    float tMin = 0.0f, tMax = 0.0f;
};

// The stretch of the ray origin + t direction, t in [0, tBoundary), from the start of the first
// majorant segment of `medium` that is non-zero to tBoundary (may be infinite); nullopt if none.
std::optional<MediumSegment> mediumSegment(const media::Medium& medium, const Vec3f& origin, const Vec3f& direction,
                                           float tBoundary);

// A light the strategy chose for a segment, with its probability and the distance sampler about
// its centre.
struct EquiangularChoice {
    int light = -1;
    float probability = 0.0f;
    media::EquiangularDistance distance;
};

// The scene's lights as the strategy sees them: the centre of each one's bounds (none for lights
// at infinity). Made once per render (PathTracer::prepare).
class EquiangularLights {
public:
    EquiangularLights() = default;
    explicit EquiangularLights(const render::RenderScene& scene);

    // Whether some light has a position: without one the strategy never samples.
    bool any() const { return any_; }
    // The light chosen for `segment` by the light tree from its origin with u, and its distance
    // sampler; nullopt when the tree chooses none or a light at infinity.
    std::optional<EquiangularChoice> choose(const render::RenderScene& scene, const MediumSegment& segment,
                                            float u) const;
    // The density with which choose() and its sampler give `light` and distance t on `segment`
    // (per unit length).
    float pdf(const render::RenderScene& scene, const MediumSegment& segment, int light, float t) const;

private:
    std::vector<std::optional<Vec3f>> centres_;
    bool any_ = false;
};

}  // namespace fluence::integrators
