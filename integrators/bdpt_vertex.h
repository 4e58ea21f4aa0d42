// The vertices of bidirectional path tracing (integrators/bdpt.h) and the densities its MIS
// weights need (integrators/bdpt_mis.h), in the measure of the path: per unit area at surface
// vertices, per unit volume at medium vertices (no cosine there; the free-flight density along the
// edge is kept apart, in EdgeMedia), per unit solid angle for x_0 on a light at infinity (whose x_1
// is then drawn per unit area of the emission disk, projected: EmissionDensity::position
// |cos theta_1|, or per unit volume, EmissionDensity::position, when x_1 is in a medium).
//
// A medium vertex scatters by the Henyey-Greenstein phase function (media/phase.h), which is its
// "BSDF": reciprocal, so its adjoint is itself, with no cosine factors.
//
// Shading follows `path`: a two-sided surface is shaded on the side its own subpath arrives from,
// a transmissive one keeps its orientation, and directions on which the shading frame and the
// surface disagree carry nothing (integrators/surface_frame.h). A light subpath transports importance:
// it evaluates and samples its BSDFs with render::Transport::Importance (the adjoint f(wi, wo),
// render/bsdf.h) and Veach's correction for shading normals (thesis, sec. 5.3),
// |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|).
#pragma once

#include <cmath>
#include <utility>

#include "integrators/bdpt_mis.h"
#include "integrators/surface_frame.h"
#include "integrators/integrator.h"
#include "integrators/medium_stack.h"
#include "media/phase.h"
#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"
#include "render/render_scene.h"

namespace fluence::integrators::bdpt {

// x_0 of a path: a point on a light (or, at infinity, the direction its light arrives along).
struct LightOrigin {
    int light = -1;
    Vec3f point, normal;
    Vec3f direction;  // unit, the way light leaves x_0 towards x_1
    bool atInfinity = false, delta = false;
    float cosine = 1.0f;      // at the light, between its normal and `direction`
    float time = 0.0f;        // the path's time in the shutter: the light is where it is then
    float fromLight = 0.0f;   // density as a light subpath's origin (bdpt_mis.h)
    float fromCamera = 0.0f;  // density as drawn by a camera subpath
};

// A vertex of either subpath: on a surface, or a scattering in a medium (`inMedium`: then only
// hit.point is set, and the phase function's g).
struct Vertex {
    Vertex(const render::SurfaceHit& hit_, const Vec3f& wo_, const RGB& beta_, const MediumStack& media_)
        : hit(hit_), wo(wo_), beta(beta_), media(media_) {}

    render::SurfaceHit hit;
    Vec3f wo;                   // unit, towards the previous vertex of its own subpath
    RGB beta;                   // the subpath's throughput up to here
    MediumStack media;          // the media its subpath was in on reaching it
    float fromOwn = 0.0f;       // area (volume) density its own subpath drew it with (1 through a delta lobe)
    float fromOther = 0.0f;     // the density the other subpath would, filled when the next vertex is drawn
    bool delta = false;         // left by a delta lobe
    bool transmissive = false;  // its BSDF transmits (shaded without flipping, light gathered from both sides)
    bool inMedium = false;
    bool walking = false;  // a scattering inside a material's interior: never joined (bdpt.h)
    float g = 0.0f;        // Henyey-Greenstein anisotropy, at a medium vertex
    RGB sigmaS{1.0f};      // scattering coefficient at a medium vertex (bdpt_mis.h); 1 on surfaces
    EdgeMedia edge;        // how the edge from its subpath's previous vertex crosses media
    int bounces = 0;       // its subpath's scattering vertices up to it, interior walks not counted

    const Vec3f& point() const { return hit.point; }
    // |cos| between direction d and the surface (1 in a medium: densities per unit volume).
    float cosine(const Vec3f& d) const { return inMedium ? 1.0f : std::abs(dot(hit.geometricNormal, d)); }
    // Where a ray towards direction d leaves it: just off the surface on d's side, or the point.
    Vec3f leaving(const Vec3f& d) const {
        return inMedium ? hit.point : spawnOrigin(hit.point, hit.geometricNormal, d);
    }
    // The medium a ray leaving it along d travels through, or nullptr.
    const media::Medium* mediumTowards(const Vec3f& d) const {
        return inMedium ? media.medium() : media.after(hit, wo, d).medium();
    }
};

// Solid-angle density `pdf` at `from` of the direction to `to`, as an area density at `to` (a
// volume density in a medium).
float toArea(float pdf, const Vec3f& from, const Vertex& to);

// What Shading::evaluate gives for world directions wo and wi: f for the transport mode (the
// adjoint f(wi, wo) for importance), the density of drawing wi from wo, and of wo from wi; zero
// where the shading frame and the surface disagree.
struct Scattered {
    RGB f;
    float pdf = 0.0f, pdfReverse = 0.0f;
};

// The BSDF (or phase function) of a vertex, shaded as seen from its own subpath's previous vertex.
class Shading {
public:
    Shading(const Vertex& v, render::BsdfArena& arena);

    bool transmissive() const { return bsdf_ && (bsdf_->flags() & render::kBsdfTransmission) != 0; }
    bool connectable() const { return !bsdf_ || (bsdf_->flags() & (render::kBsdfDiffuse | render::kBsdfGlossy)) != 0; }
    // The scattering from wo to wi of a subpath carrying `mode` (Scattered).
    Scattered evaluate(const Vec3f& wo, const Vec3f& wi, render::Transport mode = render::Transport::Radiance) const;
    // The cosine of a camera subpath's transport towards wi (1 in a medium).
    float cosine(const Vec3f& wi) const { return bsdf_ ? std::abs(dot(wi, surface_.frame.n)) : 1.0f; }
    // Cosine factors of a light subpath's transport from wo to wi (adjoint, with the shading-normal
    // correction, adjointShadingCosine in integrators/surface_frame.h), to multiply the importance
    // mode's f by; 1 in a medium.
    float importanceCosines(const Vec3f& wo, const Vec3f& wi) const;
    // What bdpt.cpp's scatter() samples: the BSDF and its frame, or (bsdf() null) the phase function.
    const render::Bsdf* bsdf() const { return bsdf_; }
    const SurfaceFrame& surface() const { return surface_; }
    const media::HenyeyGreenstein& phase() const { return phase_; }

private:
    const render::Bsdf* bsdf_;  // nullptr in a medium
    SurfaceFrame surface_;
    media::HenyeyGreenstein phase_;
};

// The point and normal next-event estimation chooses and samples lights from at x_1, gathering
// towards x_2 (as `path` does: a two-sided surface just off it on that side, a transmissive one
// or a medium vertex from the point itself with no normal).
std::pair<Vec3f, Vec3f> gatherPoint(const Vertex& x1, const Vec3f& toX2);

// x_0's density under next-event estimation from x_1 towards x_2 (bdpt_mis.h's neeOrigin).
float neeDensity(const render::RenderScene& scene, const LightOrigin& x0, const Vertex& x1, const Vec3f& toX2);

// x_0 completed by its emission densities: `light` at `point` (normal `normal`) sending light
// along `direction` at `time`; `choice`: the probability light subpaths start on it.
LightOrigin originAt(const render::RenderScene& scene, int light, const Vec3f& point, const Vec3f& normal,
                     const Vec3f& direction, bool delta, float choice, float time);

// Density of x_1 drawn from the origin by emission sampling.
float emittedTowards(const render::RenderScene& scene, const LightOrigin& x0, const Vertex& x1);

// Density of x_0 drawn by a camera subpath from x_1 with solid-angle density pdf.
float cameraReaches(const LightOrigin& x0, float pdf, const Vec3f& p1);

// The integral of `medium`'s majorant from `from` along unit `direction` over `length` (which may
// be infinite), per channel (EdgeMedia::majorantDepth): a deterministic walk of its segments.
RGB majorantDepth(const media::Medium* medium, const Vec3f& from, const Vec3f& direction, float length);

// The media (interiors, innermost last) that hold `point`, as a MediumStack: a ray from it along
// `direction` is followed through up to kMaxProbeSurfaces surfaces, and every interior whose
// surface it first crosses outwards holds it. For light subpaths, whose lights may sit inside
// closed surfaces (a camera is assumed outside all of them, as `path` assumes).
inline constexpr int kMaxProbeSurfaces = 16;
MediumStack mediaAt(const render::RenderScene& scene, const Vec3f& point, const Vec3f& direction,
                    RenderCounters& counters);

}  // namespace fluence::integrators::bdpt
