// DielectricReflectionBsdf: what the surface of a dielectric reflects, alone: the top lobe of a
// clear coat or of a plastic's specular layer (what the surface lets through is the layer's base,
// render/bsdfs/layered.h).
//
//   rough:  f = tint F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),   h = normalize(wo + wi)
//   smooth: a delta mirror of reflectance tint F(cos theta_o)
//   F = exact dielectric Fresnel (render/bsdfs/fresnel.h), per channel of eta
//   reflectance(cos theta) = tint F(cos theta)   (the share a layer keeps from its base)
//
// | parameter | meaning                                                                      |
// |-----------|------------------------------------------------------------------------------|
// | eta       | relative index per channel (equal channels for glass or a coat; a coloured    |
// |           | normal-incidence reflectance F0 maps to one index per channel, etaFromF0)     |
// | tint      | per-channel scale of the reflection in [0, 1] (Standard Surface's specular    |
// |           | weight x specular_color); 1 for a physical interface                          |
// | ggx       | GGX widths (x along the tangent); smooth below kGgxSmoothAlpha                |
//
// The specular term of the seeds' Torrance-Sparrow / Cook-Torrance (000) with the GGX
// distribution and Fresnel's exact reflectance: the reflection half of GgxDielectricBsdf, which
// is the whole interface. f, sample and pdf are those of GgxReflectionBsdf
// (render/bsdfs/ggx_reflection.h): visible-normal sampling, weight tint F(wo.h) G2 / G1(wo) <= 1.
// Reciprocal; two-sided. Flags: reflection and glossy (rough) or specular (smooth). Path-class
// label: D (glossy) when rough, S when smooth.
#pragma once

#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_reflection.h"

namespace fluence::render {

// The tinted Fresnel reflectance of a dielectric of relative index eta (per channel).
struct DielectricFresnel {
    DielectricFresnel(const RGB& eta, const RGB& tint = RGB(1.0f)) : eta(eta), tint(tint) {}
    RGB operator()(float cosTheta) const { return tint * fresnelDielectric(cosTheta, eta); }
    RGB eta, tint;
};

using DielectricReflectionBsdf = GgxReflectionBsdf<DielectricFresnel>;

}  // namespace fluence::render
