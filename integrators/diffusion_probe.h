// Diffusion subsurface scattering (SubsurfaceMethod::Diffusion): where light that enters a
// subsurface material at one point comes back out, by the Christensen-Burley profile
// (media/normalized_diffusion.h), found with probe rays (King, Kulla, Conty & Fajardo 2013,
// "BSSRDF Importance Sampling"; as in pbrt-v3's SeparableBSSRDF).
//
// THE MODEL. A separable BSSRDF: light entering at pi (through the material's subsurface lobe,
// render/material_bsdf.h, which already carries the specular layer's transmission in) leaves at po
// with the profile's reflectance per unit area R(|po - pi|), per channel, then diffusely through
// subsurfaceExitBsdf() (the specular layer's transmission out). R is the response of a flat,
// semi-infinite medium: exact there (its integral over the plane is the subsurface colour A), an
// approximation on curved, thin or concave geometry, where a random walk is not.
//
// SAMPLING. One axis is chosen (the entry's shading normal with probability 1/2, either tangent
// with 1/4), one channel (1/3 each), a radius r from that channel's profile and an angle uniformly;
// the point at r in the plane through pi perpendicular to the axis is the centre of a probe segment
// along the axis, as long as the chord of the sphere of radius maxRadius(channel) about pi
// (a radius beyond it finds nothing: 0.1% of the energy is given up, media/normalized_diffusion.h).
// Every surface of the same material (the same interior) along the segment is a candidate, up to
// kMaxProbeHits; one is chosen uniformly. The density of po is the balance heuristic's sum over
// every axis and channel that could have found it:
//     pdf(po) = (1 / hits) sum_axis p_axis sum_c (1/3) pdfArea_c(r_axis) |n_po . axis|,
// r_axis the distance from pi to po projected on the plane perpendicular to that axis (0 beyond
// that channel's maxRadius), and the exit's weight is R(|po - pi|) / pdf(po). As in pbrt-v3, the
// 1 / hits of the probe that was taken stands in for the other axes' counts, which are not traced.
#pragma once

#include <optional>

#include "core/random.h"
#include "integrators/integrator.h"
#include "render/render_scene.h"

namespace fluence::integrators {

inline constexpr int kMaxProbeHits = 8;

// What a path does after its BSDF sample at `hit` (arrived along -wo, leaving along wi), for the
// integrators that follow subsurface light: it did not enter a diffusion material (NotEntered:
// go on as usual); it did, and `throughput` now carries the exit's weight and `exit` holds the
// exit point, the next vertex, reached without tracing a ray (Exited); or no exit was found and
// the path ends (Lost). It enters when it is transmitted inwards through a solid whose subsurface
// method is Diffusion; probe rays are counted as bounce rays.
enum class DiffusionStep { NotEntered, Exited, Lost };
DiffusionStep stepThroughDiffusion(const render::RenderScene& scene, const render::SurfaceHit& hit, const Vec3f& wo,
                                   const Vec3f& wi, RGB& throughput, std::optional<render::SurfaceHit>& exit,
                                   SampleStream& rng, RenderCounters& counters);

}  // namespace fluence::integrators
