// The vertices of bidirectional path tracing (integrators/bdpt.h) and the densities its MIS
// weights need (integrators/bdpt_mis.h), in the measure of the path: per unit area at surface
// vertices, per unit solid angle for x_0 on a light at infinity (whose x_1 is then drawn per unit
// area of the emission disk, projected: EmissionDensity::position |cos theta_1|).
//
// Shading follows `path`: a two-sided surface is shaded on the side its own subpath arrives from,
// a transmissive one keeps its orientation, and directions on which the shading frame and the
// surface disagree carry nothing (integrators/first_hit.h). A light subpath transports importance:
// render/bsdf.h's f is for radiance, so it uses the adjoint f*(wo, wi) = f(wi, wo) with Veach's
// correction for shading normals (thesis, sec. 5.3), |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|).
#pragma once

#include <cmath>
#include <utility>

#include "integrators/first_hit.h"
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
    float fromLight = 0.0f;   // density as a light subpath's origin (bdpt_mis.h)
    float fromCamera = 0.0f;  // density as drawn by a camera subpath
};

// A surface vertex of either subpath.
struct Vertex {
    render::SurfaceHit hit;
    Vec3f wo;         // unit, towards the previous vertex of its own subpath
    RGB beta;         // the subpath's throughput up to here
    float fromOwn = 0.0f;    // area density its own subpath drew it with (1 through a delta lobe)
    float fromOther = 0.0f;  // area density the other subpath would, filled when the next vertex is drawn
    bool delta = false;          // left by a delta lobe
    bool transmissive = false;   // its BSDF transmits (shaded without flipping, light gathered from both sides)
};

// Solid-angle density `pdf` at `from` of the direction to `to`, as an area density at `to`
// (whose surface has unit normal `normal`).
float toArea(float pdf, const Vec3f& from, const Vec3f& to, const Vec3f& normal);

// The BSDF of a vertex, shaded as seen from its own subpath's previous vertex.
struct Shading {
    const render::Bsdf& bsdf;
    SurfaceFrame surface;

    Shading(const Vertex& v, render::BsdfArena& arena)
        : bsdf(render::materialBsdf(v.hit.material, arena)), surface(shadingFrame(v.hit, v.wo, transmissive())) {}

    bool transmissive() const { return (bsdf.flags() & render::kBsdfTransmission) != 0; }
    bool connectable() const { return (bsdf.flags() & (render::kBsdfDiffuse | render::kBsdfGlossy)) != 0; }
    // f(a, b) and the density of drawing b from a, for world directions a (as wo) and b (as wi);
    // zero where the shading frame and the surface disagree.
    std::pair<RGB, float> evaluate(const Vec3f& a, const Vec3f& b) const {
        Vec3f al = surface.frame.toLocal(a), bl = surface.frame.toLocal(b);
        if (!sidesAgree(a, b, surface.geometricNormal, al.z, bl.z)) return {RGB(0.0f), 0.0f};
        return {bsdf.f(al, bl), bsdf.pdf(al, bl)};
    }
    // Cosine factors of a light subpath's transport from wo to wi (adjoint, with the shading-normal
    // correction), to multiply f(wi, wo) by.
    float importanceCosines(const Vec3f& wo, const Vec3f& wi) const {
        float woNg = std::abs(dot(wo, surface.geometricNormal));
        return woNg > 0.0f ? std::abs(dot(wo, surface.frame.n)) * std::abs(dot(wi, surface.geometricNormal)) / woNg : 0.0f;
    }
};

// The point and normal next-event estimation chooses and samples lights from at x_1, gathering
// towards x_2 (as `path` does: a two-sided surface just off it on that side, a transmissive one
// from the point itself with no normal).
std::pair<Vec3f, Vec3f> gatherPoint(const Vertex& x1, const Vec3f& toX2);

// x_0's density under next-event estimation from x_1 towards x_2 (bdpt_mis.h's neeOrigin).
float neeDensity(const render::RenderScene& scene, const LightOrigin& x0, const Vertex& x1, const Vec3f& toX2);

// x_0 completed by its emission densities: `light` at `point` (normal `normal`) sending light
// along `direction`; `choice`: the probability light subpaths start on it.
LightOrigin originAt(const render::RenderScene& scene, int light, const Vec3f& point, const Vec3f& normal, const Vec3f& direction,
                     bool delta, float choice);

// Density of x_1 (on a surface with normal n1) drawn from the origin by emission sampling.
float emittedTowards(const render::RenderScene& scene, const LightOrigin& x0, const Vec3f& p1, const Vec3f& n1);

// Density of x_0 drawn by a camera subpath from x_1 with solid-angle density pdf.
float cameraReaches(const LightOrigin& x0, float pdf, const Vec3f& p1);

}  // namespace fluence::integrators::bdpt
