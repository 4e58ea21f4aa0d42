// PhongBsdf: the original Phong model as a BRDF, as the seeds define it. NOT energy conserving.
//
//   f = kd + ks max(0, cos alpha)^n,    cos alpha = r . wi,  r = mirror direction of wo
//
// | parameter | meaning                                                               |
// |-----------|-----------------------------------------------------------------------|
// | kd        | diffuse coefficient: a BRDF value, so the diffuse term reflects pi kd |
// | ks        | specular coefficient: the lobe's peak BRDF value                      |
// | n         | Phong exponent (>= 0); larger is shinier                               |
//
// The seeds' "Phong model rho = kd + ks cos^n theta_r" (003, "glossy BRDFs"; the shading
// formula I = kd (N.L) + ks (E.L)^n of 000 read as a BRDF), which lists its issues: "non
// reciprocal, non energy conserving". As a BRDF in r . wi it is in fact reciprocal
// (r(wo) . wi = r(wi) . wo); the non-reciprocal variant divides by cos theta_i to make the
// shading formula's (R.L)^n the reflected radiance. It is not energy conserving: neither term is
// normalised, so the lobe alone reflects ks 2 pi / (n + 2) at normal incidence, more than ks
// itself for n < 2 pi - 2; tests/render/bsdf_phong_test.cpp measures the excess in a white
// furnace. Use modifiedPhong() (render/bsdfs/modified_phong.h) for rendering.
//
// Sampling: the diffuse term cosine-weighted, the lobe by a power-cosine about r (density
// (n + 1) / (2 pi) cos^n alpha; Lafortune & Willems 1994), directions below the surface rejected.
// Two-sided. Flags: reflection, diffuse (kd != 0), glossy (ks != 0). Path-class label: D.
#pragma once

#include "render/bsdfs/diffuse_glossy.h"

namespace fluence::render {

struct PhongLobe {
    static float cosine(const Vec3f& wo, const Vec3f& wi) { return dot(mirrorZ(-wo), wi); }
    static float albedoAtNormalIncidence(float n) { return 2.0f * kPi / (n + 2.0f); }
    static Vec3f sample(const Vec3f& wo, Vec2f u, float n);
    static float pdf(const Vec3f& wo, const Vec3f& wi, float n);
};

using PhongBsdf = DiffuseGlossyBsdf<PhongLobe>;

}  // namespace fluence::render
