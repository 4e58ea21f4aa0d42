// A clear coat over a glossy base that keeps the light its underside sends back down: Kulla &
// Conty's energy compensation (2017) applied to the whole coated stack.
//
// A coat laid over a base by albedo scaling (render/bsdfs/layered.h) drops the light the base
// reflects towards directions where the coat reflects it back down: from wo,
//
//   loss(wo) = (1 - A(wo)) B(wo),   B(w) = integral A(wi) f_base(w, wi) cos theta_i dwi
//   A: the coat's directional albedo (render/bsdfs/dielectric_reflection.h)
//
// Over a diffuse base B is a constant and the layer's normalisation returns the loss exactly
// (layered.h, ENERGY-PRESERVING LAYERING). Over a plastic or a metal the base sends its glossy
// reflection towards grazing directions when lit at grazing angles, where A is largest: a coat
// over a white plastic read 0.956 at 80 degrees and 1.008 at normal incidence with that
// normalisation, a coat over a white metal 0.84 at 80 degrees without it. Here the lost light
// comes back as a lobe symmetric in wo and wi,
//
//   f = f_coated(wo, wi) + filter loss(wo) loss(wi) / (pi Lavg),   Lavg = 1/pi integral loss cos
//
// whose albedo is loss(wo) exactly: a white stack reflects 1 at every angle, and the result stays
// reciprocal. It is built as a LayeredBsdf whose top is the coated stack with reflectance
// 1 - loss and whose base is a Lambertian of albedo filter (the coat's colour filters what
// crosses it), so the layer's sampling picks the returned lobe with probability loss(wo).
//
// B is computed for a base made of parts, each a GGX lobe of albedo E(mu) and width alpha plus
// a diffuse-shaped lobe K g(wo) g(wi) / pi (a plastic: the specular layer over its diffuse base,
// g = 1 - E, K = the diffuse albedo / (1 - Eavg); a metal: its single scattering and its
// multiple-scattering lobe, g = 1 - E, K = Fms / (1 - Eavg)), mixed by weights:
//
//   B(mu) = sum over parts  weight (E(mu) sum_k A(mu_k) spread_k(mu, alpha) + K g(mu) G)
//   G     = 2 integral A(nu) g(nu) nu dnu
//
// spread (render/bsdfs/ggx_redistribution.h) says where the GGX lobe sends the light; the
// loss is tabulated at the 32 mu nodes of render/bsdfs/albedo_table.h and interpolated
// linearly, and Lavg integrated exactly from the same interpolant. Approximations: the base is
// isotropic (an anisotropic lobe spreads as its geometric-mean width), a coloured specular
// layer spreads as the one of its first channel's index, a coloured metal as its bare lobe; the returned lobe has the shape the symmetric form gives it, not
// that of a simulation of the layers; light returned to a coloured base is not coloured again.
#pragma once

#include <array>

#include "core/rgb.h"
#include "render/bsdf.h"
#include "render/bsdf_arena.h"
#include "render/bsdfs/albedo_table.h"

namespace fluence::render {

class CoatReturn {
public:
    using NodeValues = std::array<RGB, albedo_table::kCosines>;

    // coatAlbedo: the coat's directional albedo A at each mu node (cosineAt(i)).
    explicit CoatReturn(const std::array<float, albedo_table::kCosines>& coatAlbedo);

    // A part of the base of mix weight `weight`: a GGX lobe of width alpha, Fresnel reflectance
    // f0 (1 for a metal's bare lobe) and albedo lobe[i] at the mu nodes, and the diffuse-shaped
    // lobe scale g(wo) g(wi) / pi.
    void addPart(float weight, float alpha, float f0, const NodeValues& lobe, const NodeValues& g, const RGB& scale);

    // `coated` (the coat over the base, reflection only) with the light it loses returned,
    // through the coat's filter.
    const Bsdf& compensate(const Bsdf& coated, const RGB& filter, BsdfArena& arena) const;

private:
    std::array<float, albedo_table::kCosines> coatAlbedo_;
    NodeValues returned_{};  // B at the mu nodes
};

}  // namespace fluence::render
