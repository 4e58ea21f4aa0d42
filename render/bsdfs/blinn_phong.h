// Blinn-Phong with a normalised lobe: energy-conserving reflection around the half vector.
//
//   f = rhoD / pi + rhoS c(n) max(0, cos theta_h)^n,    cos theta_h = n . normalize(wo + wi)
//   c(n) = (n + 2)(n + 4) / (8 pi (n + 2^(-n/2)))
//
// | parameter | meaning                                                                |
// |-----------|------------------------------------------------------------------------|
// | rhoD      | diffuse albedo, per channel                                            |
// | rhoS      | specular albedo at normal incidence, per channel; rhoD + rhoS <= 1     |
// | n         | Blinn exponent (>= 0)                                                  |
//
// The seeds' Blinn-Phong (003, "Blinn-Phong model rho = kd + ks (N.H)^n" and "modified
// Blinn-Phong model") with its energy-conserving constant. The seeds' constant (n + 2) / (2 pi)
// normalises cos^n theta_h as a distribution of half vectors, not the BRDF: as a BRDF it
// reflects up to 4 rhoS at normal incidence for large n (the half-vector Jacobian). c(n) is
// instead 1 / (the lobe's albedo at normal incidence), the integral of cos^n theta_h cos theta_i
// over the hemisphere, 8 pi (n + 2^(-n/2)) / ((n + 2)(n + 4)) in closed form; the lobe reflects
// the most at normal incidence, so with rhoD + rhoS <= 1 the model conserves energy at every
// angle (tests/render/bsdf_phong_test.cpp). Reciprocal (the half vector is symmetric); two-sided.
//
// Sampling: the diffuse term cosine-weighted, the lobe by drawing h from the power-cosine
// (n + 1) / (2 pi) cos^n theta_h and reflecting wo about it (pdf / (4 wo.h)).
// Flags: reflection, diffuse, glossy. Path-class label: D.
#pragma once

#include "render/bsdfs/diffuse_glossy.h"

namespace fluence::render {

struct BlinnPhongLobe {
    static float cosine(const Vec3f& wo, const Vec3f& wi) { return normalize(wo + wi).z; }
    static float albedoAtNormalIncidence(float n);
    static Vec3f sample(const Vec3f& wo, Vec2f u, float n);
    static float pdf(const Vec3f& wo, const Vec3f& wi, float n);
};

using BlinnPhongBsdf = DiffuseGlossyBsdf<BlinnPhongLobe>;

inline BlinnPhongBsdf modifiedBlinnPhong(const RGB& rhoD, const RGB& rhoS, float n) {
    return BlinnPhongBsdf::normalised(rhoD, rhoS, n);
}

}  // namespace fluence::render
