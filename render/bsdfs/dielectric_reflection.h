// DielectricReflectionBsdf: what the surface of a dielectric reflects, alone: the top lobe of a
// clear coat or of a plastic's specular layer (what the surface lets through is the layer's base,
// render/bsdfs/layered.h).
//
//   rough:  f = tint F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),   h = normalize(wo + wi)
//   smooth: a delta mirror of reflectance tint F(cos theta_o)
//   F = exact dielectric Fresnel (render/bsdfs/fresnel.h), per channel of eta
//   reflectance(w)         = tint E(cos theta_w, alpha, F0 of eta)   (the share a layer keeps from
//                            its base: the lobe's directional albedo, render/bsdfs/ggx_albedo.h;
//                            exactly tint F(cos theta) when smooth)
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

#include <cmath>

#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/ggx_reflection.h"

namespace fluence::render {

// The tinted Fresnel reflectance of a dielectric of relative index eta (per channel), and the
// albedo of the GGX lobe it weights. The table is indexed by F0, which an index below 1 shares
// with its reciprocal: the albedo is that of the interface seen from its denser side's outside.
struct DielectricFresnel {
    DielectricFresnel(const RGB& eta, const RGB& tint = RGB(1.0f))
        : eta(eta), tint(tint), f0(normalIncidence(eta.x), normalIncidence(eta.y), normalIncidence(eta.z)) {}
    RGB operator()(float cosTheta) const { return tint * fresnelDielectric(cosTheta, eta); }
    // A smooth interface reflects exactly F(cos); a rough one its tabulated albedo, at the
    // geometric-mean width when anisotropic (render/bsdfs/ggx_albedo.h).
    RGB albedo(const Vec3f& w, const GgxDistribution& ggx) const {
        if (ggx.isSmooth()) return (*this)(w.z);
        return tint * perChannel([&](float f) { return ggxReflectionAlbedo(w.z, tableWidth(ggx), f); });
    }
    RGB averageAlbedo(const GgxDistribution& ggx) const {
        return tint * perChannel([&](float f) { return ggxReflectionAverageAlbedo(tableWidth(ggx), f); });
    }
    RGB eta, tint, f0;

private:
    static float tableWidth(const GgxDistribution& ggx) {
        return ggx.isSmooth() ? 0.0f : std::sqrt(ggx.alphaX() * ggx.alphaY());
    }
    static float normalIncidence(float eta) { return ((eta - 1.0f) / (eta + 1.0f)) * ((eta - 1.0f) / (eta + 1.0f)); }
    // g(F0) per channel, evaluated once when the three are equal.
    template <typename G>
    RGB perChannel(G g) const {
        if (f0.x == f0.y && f0.y == f0.z) return RGB(g(f0.x));
        return {g(f0.x), g(f0.y), g(f0.z)};
    }
};

using DielectricReflectionBsdf = GgxReflectionBsdf<DielectricFresnel>;

}  // namespace fluence::render
