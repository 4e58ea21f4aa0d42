// HairBsdf: the hair and fur model of Chiang, Bitterli, Tappan and Burley 2016 ("A Practical and
// Controllable Hair and Fur Model for Production Path Tracing"), the near-field model Cycles'
// principled hair, Arnold's standard_hair and pbrt-v3 are built on.
//
// FRAME. Unlike a surface BSDF the model lives on the whole sphere around a fibre: the local frame
// is x along the fibre (the curve's tangent), z the normal of the ribbon facing the incoming ray
// and y = z x x across the fibre (render/render_scene.h's curve hits give that frame). theta is the
// longitudinal angle (sin theta = w.x), phi the azimuth about the fibre (phi = atan2(w.z, w.y)).
// The ray met the fibre at h in [-1, 1] along y (gamma_o = asin h), in radii from its axis.
//
//   f(wo, wi) = sum_p M_p(theta_i, theta_o) A_p(theta_o, h) N_p(phi_i - phi_o) / |cos theta_i wrt z|
//
// for p = 0 (R, reflection), 1 (TT), 2 (TRT) and a residual lobe p = 3 holding all longer paths:
//   M_p  the longitudinal lobe of d'Eon et al. 2011 with variance v_p, v_0 from the longitudinal
//        roughness beta_m by the paper's fit, v_1 = v_0 / 4, v_2 = v_3 = 4 v_0; the R, TT and TRT
//        lobes are shifted by the cuticle tilt alpha (-2 alpha, alpha, 4 alpha as the paper does);
//   A_p  the attenuation: Fresnel at the fibre's index eta and absorption sigma_a over each crossing
//        of the cylinder, T = exp(-sigma_a 2 cos gamma_t / cos theta_t) (per unit of diameter); the
//        residual lobe takes the sum of the geometric series A_2 T f / (1 - T f);
//   N_p  a logistic in phi of scale s (from the azimuthal roughness beta_n by the paper's fit),
//        trimmed to [-pi, pi] and centred on Phi(p) = 2 p gamma_t - 2 gamma_o + p pi; uniform for
//        the residual lobe.
// The division by |wi.z| cancels the cosine render/bsdf.h's integrators apply, so the scattered
// energy is the integral of sum_p M_p A_p N_p over the sphere: with sigma_a = 0 the A_p sum to
// one and every lobe is normalised, so a white fibre scatters all the light it receives
// (tests/render/bsdf_hair_test.cpp's white furnace).
//
// Sampling: a lobe p with probability A_p / sum A (by channel mean) from uLobe, which then also
// draws N_p; M_p exactly from u[0], u[1] (the paper's sec. 4.2). pdf() sums the same
// mixture, so sample() and pdf() agree (chi-square tested). The model is not reciprocal (A_p
// and the tilt depend on wo alone, as in the paper); M_p is symmetric in theta_i and theta_o.
// Flags: reflection, transmission (TT goes through the fibre), glossy.
#pragma once

#include <array>
#include <optional>

#include "render/bsdf.h"
#include "render/curves_description.h"

namespace fluence::render {

class HairBsdf final : public Bsdf {
public:
    static constexpr int kLobes = 3;  // R, TT, TRT; the residual lobe is index kLobes

    explicit HairBsdf(const HairParams& params);

    RGB f(const Vec3f& wo, const Vec3f& wi) const override;
    float pdf(const Vec3f& wo, const Vec3f& wi) const override;
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const override;
    unsigned flags() const override { return kBsdfReflection | kBsdfTransmission | kBsdfGlossy; }

    // The longitudinal lobe of variance v (d'Eon et al. 2011), normalised over theta_i with the
    // measure cos theta_i d theta_i.
    static float longitudinal(float cosThetaI, float cosThetaO, float sinThetaI, float sinThetaO, float v);

private:
    struct Incidence;  // what f, pdf and sample share for one wo
    Incidence incidence(const Vec3f& wo) const;
    // The sum over lobes of M_p N_p times `weights[p]` (A_p for f, the lobe probabilities for pdf).
    template <typename Weight>
    Weight lobeSum(const Incidence& in, const Vec3f& wi, const std::array<Weight, kLobes + 1>& weights) const;

    RGB sigmaA_;
    float eta_, h_, gammaO_, s_;
    std::array<float, kLobes + 1> v_;
    std::array<float, kLobes> sinTilt_, cosTilt_;  // per lobe: the tilt of theta_o
};

// Chiang et al.'s absorption coefficient that gives a fibre of azimuthal roughness beta_n the
// multiple-scattering colour `colour` (sec. 4.2's fit; Cycles' "absorption from colour").
RGB hairAbsorptionFromColour(const RGB& colour, float azimuthalRoughness);

}  // namespace fluence::render
